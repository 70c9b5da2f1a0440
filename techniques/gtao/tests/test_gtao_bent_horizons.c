/* The talk's horizon-vector bent normal (gtao_bent_horizons.h):
 * 0.5 (h1_vec + h2_vec) = cos((h2 - h1) / 2) dir((h1 + h2) / 2) (the
 * sum-to-product identities), and with a single slice per pixel its
 * direction is the halfway direction gtao_render computes with
 * bent_halfway = 1 (an independent implementation), on the boxes scene. */
#include <math.h>
#include <stdlib.h>

#include "gtao/gtao_bent_horizons.h"
#include "raytracer/reference_render.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

static void test_identity(void)
{
    double worst = 0.0;
    for (int i = 0; i < 400; ++i) {
        float h1 = -1.5f * (float)(i % 20) / 19.0f, h2 = 1.5f * (float)(i / 20) / 19.0f, bv, bs;
        gtao_bent_horizon_average(h1, h2, &bv, &bs);
        double c = cos(0.5 * (h2 - h1)), m = 0.5 * (h1 + h2);
        worst = fmax(worst, fmax(fabs(bv - c * cos(m)), fabs(bs - c * sin(m))));
    }
    CHECK(worst < 1e-6);
}

static const char *const boxes_camera =
    "{\"position\":[7,6,9],\"target\":[0,0.5,0],\"up\":[0,1,0],\"yfov_deg\":40,\"width\":48,\"height\":40}";

static void test_one_slice_is_halfway(void)
{
    gt_error e;
    scene s;
    camera cam;
    image img;
    ss_gbuffer g;
    if (scene_load("builtin:boxes", &s, &e) != 0 || camera_parse_json(boxes_camera, "test", &cam, &e) != 0) {
        CHECK(0);
        return;
    }
    reference_request req = {.quantity = QUANTITY_GBUFFER, .sampling = {.spp = 0, .seed = 1, .threads = 2},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    int rc = reference_render(&s, "builtin:boxes", &cam, &req, &img, &stats, &e);
    scene_free(&s);
    camera_view v = camera_view_from(&cam);
    ss_camera c = {v.forward, v.right, v.up, v.tan_half_yfov, v.aspect};
    if (rc != 0 || ss_gbuffer_from_image(&img, "boxes", c, &g, &e) != 0) {
        CHECK(0);
        return;
    }
    size_t n = (size_t)g.width * g.height;
    float *a[3], *b[3], ao[48 * 40];
    for (int k = 0; k < 3; ++k) {
        a[k] = calloc(n, sizeof(float));
        b[k] = calloc(n, sizeof(float));
    }
    gtao_params p;
    gtao_preset("reference", &p);
    p.slices = 1;
    p.steps = 8;
    p.radius = 1e4f;
    p.falloff = 0.0f;
    p.max_radius_px = 48.0f;
    p.bent_halfway = 1;
    gtao_bent_horizons_frame(&g, &p, 0, a);
    CHECK(gtao_render(&g, &p, ao, b) == 0);
    double worst = 0.0;
    int compared = 0;
    /* An open slice contributes a zero vector and the estimator falls back
     * to the pixel's normal: compare where it did not. */
    for (size_t i = 0; i < n; ++i)
        if (g.mask[i] != 0.0f && a[0][i] * g.normal[0][i] + a[1][i] * g.normal[1][i] + a[2][i] * g.normal[2][i] <
                                     1.0f - 1e-6f) {
            double dot = a[0][i] * b[0][i] + a[1][i] * b[1][i] + a[2][i] * b[2][i];
            worst = fmax(worst, 1.0 - dot);
            ++compared;
        }
    CHECK_MSG(compared > 300 && worst < 1e-5, "compared %d, worst 1 - cos %g", compared, worst);
    for (int k = 0; k < 3; ++k) {
        free(a[k]);
        free(b[k]);
    }
    image_free(&img);
}

int main(void)
{
    test_identity();
    test_one_slice_is_halfway();
    return check_report("test_gtao_bent_horizons");
}
