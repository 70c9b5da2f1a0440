/* The talk's fast arc cosine with free coefficients, and GTAO's slice
 * integrals replayed from cached horizon cosines (gtao_fast_acos.h):
 * the talk's coefficients give gtao_fast_acos bit for bit, and the replay
 * equals gtao_frame (exact and fast maths) on the boxes scene to float
 * rounding, so the fast-math study measures what GTAO computes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gtao/gtao.h"
#include "gtao/gtao_fast_acos.h"
#include "raytracer/reference_render.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

static void test_poly_is_the_talks(void)
{
    gtao_acos_poly talk = gtao_acos_poly_talk();
    int same = 1;
    for (int i = 0; i <= 20000; ++i) {
        float x = -1.0f + (float)i / 10000.0f;
        float a = gtao_fast_acos_poly(x, &talk), b = gtao_fast_acos(x);
        same &= memcmp(&a, &b, sizeof a) == 0;
    }
    CHECK(same);
    /* A different slope moves acos(0.5) by (slope change) * 0.5 * sqrt~(0.5). */
    gtao_acos_poly other = talk;
    other.slope += 0.01f;
    double moved = gtao_fast_acos_poly(0.5f, &other) - gtao_fast_acos_poly(0.5f, &talk);
    CHECK_NEAR(moved, 0.01 * 0.5 * gtao_fast_sqrt(0.5f), 1e-6);
}

static const char *const boxes_camera =
    "{\"position\":[7,6,9],\"target\":[0,0.5,0],\"up\":[0,1,0],\"yfov_deg\":40,\"width\":48,\"height\":40}";

static int render_boxes(image *img, ss_gbuffer *g)
{
    gt_error e;
    scene s;
    camera cam;
    if (scene_load("builtin:boxes", &s, &e) != 0 || camera_parse_json(boxes_camera, "test", &cam, &e) != 0)
        return fprintf(stderr, "%s\n", e.message), -1;
    reference_request req = {.quantity = QUANTITY_GBUFFER, .sampling = {.spp = 0, .seed = 1, .threads = 2},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    int rc = reference_render(&s, "builtin:boxes", &cam, &req, img, &stats, &e);
    scene_free(&s);
    if (rc == 0) {
        camera_view v = camera_view_from(&cam);
        ss_camera c = {v.forward, v.right, v.up, v.tan_half_yfov, v.aspect};
        rc = ss_gbuffer_from_image(img, "boxes", c, g, &e);
    }
    if (rc != 0)
        fprintf(stderr, "%s\n", e.message);
    return rc;
}

/* The largest |replay - gtao_frame| over the covered pixels. */
static double replay_difference(const ss_gbuffer *g, const gtao_params *p, const gtao_acos_poly *poly)
{
    size_t n = (size_t)g->width * g->height;
    float *ao = calloc(n, sizeof *ao);
    gtao_frame(g, p, 0, ao, NULL);
    double worst = 0.0;
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            size_t i = (size_t)y * g->width + x;
            if (g->mask[i] == 0.0f)
                continue;
            float sum = 0.0f;
            for (int k = 0; k < p->slices; ++k) {
                gtao_slice_cosines c;
                gtao_slice_cosines_at(g, x, y, p, gtao_slice_angle(x, y, 0, k, p->slices, 0), 0.5f, &c);
                sum += gtao_replay_slice(&c, poly);
            }
            worst = fmax(worst, fabs(sum / (float)p->slices - ao[i]));
        }
    free(ao);
    return worst;
}

static void test_replay_equals_gtao(void)
{
    image img;
    ss_gbuffer g;
    if (render_boxes(&img, &g) != 0) {
        CHECK(0);
        return;
    }
    gtao_params p;
    gtao_preset("reference", &p);
    p.slices = 6;
    p.steps = 8;
    p.radius = 1e4f;
    p.falloff = 0.0f;
    p.max_radius_px = 48.0f;
    gtao_acos_poly talk = gtao_acos_poly_talk();
    p.fast_math = 0;
    CHECK(replay_difference(&g, &p, NULL) < 2e-6);
    p.fast_math = 1;
    CHECK(replay_difference(&g, &p, &talk) < 2e-6);
    /* and the two differ: the test can tell the fast maths from the exact */
    CHECK(replay_difference(&g, &p, NULL) > 1e-3);
    image_free(&img);
}

int main(void)
{
    test_poly_is_the_talks();
    test_replay_equals_gtao();
    return check_report("test_gtao_fast_acos");
}
