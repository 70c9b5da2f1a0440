/* The baselines the GTAO talk cites, Alchemy AO (McGuire et al. 2011) and
 * CryENGINE 2's SSAO (Mittring 2007), and the talk's "Possible Pitfall"
 * integrand, against closed forms: on a lone plane Alchemy's v . n is 0 and
 * it reads 1; Crytek's opposite point pairs put exactly half the points
 * behind the plane, which reads 1 after V = min(1, 2 (1 - o)); the pitfall's
 * slice integral is |sin n| (sin(h2 - n) - sin(h1 - n)) (numerically
 * integrated), and on the open plane it gives the average of 2 |sin n| over
 * slices, not 1. Alchemy on the boxes scene equals its estimator written out
 * in double for one pixel. */
#include <math.h>
#include <stdlib.h>

#include "gtao/alchemy_ao.h"
#include "gtao/crytek_ssao.h"
#include "gtao/gtao_sin_n_pitfall.h"
#include "raytracer/reference_render.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

#define PI 3.14159265358979323846

static int render_gbuffer(const char *spec, const char *camera_json, image *img, ss_gbuffer *g)
{
    gt_error e;
    scene s;
    camera cam;
    if (scene_load(spec, &s, &e) != 0 || camera_parse_json(camera_json, "test", &cam, &e) != 0)
        return fprintf(stderr, "%s\n", e.message), -1;
    reference_request req = {.quantity = QUANTITY_GBUFFER, .sampling = {.spp = 0, .seed = 1, .threads = 2},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    int rc = reference_render(&s, spec, &cam, &req, img, &stats, &e);
    scene_free(&s);
    if (rc == 0) {
        camera_view v = camera_view_from(&cam);
        ss_camera c = {v.forward, v.right, v.up, v.tan_half_yfov, v.aspect};
        rc = ss_gbuffer_from_image(img, spec, c, g, &e);
    }
    if (rc != 0)
        fprintf(stderr, "%s\n", e.message);
    return rc;
}

static const char *const tilted_plane =
    "{\"position\":[3,4,4],\"target\":[0,0,0],\"up\":[0,1,0],\"yfov_deg\":40,\"width\":48,\"height\":48}";
static const char *const boxes_view =
    "{\"position\":[7,6,9],\"target\":[0,0.5,0],\"up\":[0,1,0],\"yfov_deg\":40,\"width\":48,\"height\":40}";

static void test_pitfall_integral(void)
{
    double worst = 0.0;
    for (int t = 0; t < 50; ++t) {
        double n = -1.4 + 2.8 * t / 49.0, h1 = n - 1.5 + 0.02 * t, h2 = n + 0.3 + 0.02 * t, sum = 0.0;
        for (int i = 0; i < 20000; ++i) { /* midpoint rule */
            double th = h1 + (h2 - h1) * (i + 0.5) / 20000.0;
            sum += cos(th - n) * fabs(sin(n)) * (h2 - h1) / 20000.0;
        }
        worst = fmax(worst, fabs(sum - gtao_integrate_arc_pitfall((float)h1, (float)h2, (float)n)));
    }
    CHECK(worst < 1e-5);
    CHECK_NEAR(gtao_integrate_arc_pitfall((float)(-PI / 2), (float)(PI / 2), 0.0f), 0.0, 1e-7);
}

/* On the plane: Alchemy 1 everywhere; Crytek 1 (a point pair lying in the
 * plane may round either way: allowed on 1% of pixels); the pitfall the
 * slice average of weight n_len 2 |sin n|. */
static void test_plane(void)
{
    image img;
    ss_gbuffer g;
    if (render_gbuffer("builtin:plane", tilted_plane, &img, &g) != 0) {
        CHECK(0);
        return;
    }
    size_t n = (size_t)g.width * g.height;
    float *ao = calloc(n, sizeof *ao);
    alchemy_params a = alchemy_default_params(2.0f);
    alchemy_frame(&g, &a, 0, ao);
    int covered = 0, alchemy_ones = 0, crytek_ones = 0;
    for (size_t i = 0; i < n; ++i)
        if (g.mask[i] != 0.0f) {
            ++covered;
            alchemy_ones += ao[i] == 1.0f;
        }
    crytek_params c = {16, 2.0f, 1, 0, 1};
    crytek_frame(&g, &c, 0, ao);
    for (size_t i = 0; i < n; ++i)
        crytek_ones += g.mask[i] != 0.0f && ao[i] == 1.0f;
    CHECK(covered > 1000 && alchemy_ones == covered);
    CHECK(crytek_ones >= covered - covered / 100);

    gtao_params p;
    gtao_preset("reference", &p);
    p.slices = 8;
    p.steps = 8;
    p.radius = 1e4f;
    p.falloff = 0.0f;
    gtao_pitfall_frame(&g, &p, 0, ao);
    double worst = 0.0, mean = 0.0;
    for (int y = 0; y < g.height; y += 5)
        for (int x = 0; x < g.width; x += 5) {
            if (g.mask[(size_t)y * g.width + x] == 0.0f)
                continue;
            double expected = 0.0;
            for (int k = 0; k < p.slices; ++k) {
                gtao_slice s;
                gtao_search_slice(&g, x, y, &p, gtao_slice_angle(x, y, 0, k, p.slices, 0), 0.5f, &s);
                expected += s.weight * s.n_len * 2.0 * fabs(sin(s.n)) / p.slices;
            }
            worst = fmax(worst, fabs(expected - ao[(size_t)y * g.width + x]));
            mean += ao[(size_t)y * g.width + x];
        }
    CHECK(worst < 1e-4);
    CHECK(mean > 0.0);
    free(ao);
    image_free(&img);
}

/* Alchemy's estimator written out in double for one pixel of the boxes. */
static void test_alchemy_estimator(void)
{
    image img;
    ss_gbuffer g;
    if (render_gbuffer("builtin:boxes", boxes_view, &img, &g) != 0) {
        CHECK(0);
        return;
    }
    float *ao = calloc((size_t)g.width * g.height, sizeof *ao);
    alchemy_params a = alchemy_default_params(1.5f);
    a.pattern = 0;
    alchemy_frame(&g, &a, 0, ao);
    int checked = 0, darkened = 0;
    for (int y = 2; y < g.height; y += 7)
        for (int x = 3; x < g.width; x += 7) {
            if (g.mask[(size_t)y * g.width + x] == 0.0f)
                continue;
            vec3 c = ss_view_position(&g, x, y), nn = ss_view_normal(&g, x, y);
            double r_px = ss_radius_px(&g, x, y, a.radius, a.max_radius_px), sum = 0.0;
            for (int i = 0; i < a.samples; ++i) {
                double al = (i + 0.5) / a.samples, th = 2.0 * PI * 7.0 * al + PI; /* pattern off: phi = pi */
                double fx = x + 0.5 + al * r_px * cos(th), fy = y + 0.5 + al * r_px * sin(th);
                if (!ss_covered(&g, (int)floor(fx), (int)floor(fy)))
                    continue;
                vec3 pi = ss_sample_position(&g, (float)fx, (float)fy);
                double vx = pi.x - c.x, vy = pi.y - c.y, vz = pi.z - c.z;
                double vn = vx * nn.x + vy * nn.y + vz * nn.z + c.z * 1e-4;
                sum += fmax(0.0, vn) / (vx * vx + vy * vy + vz * vz + 1e-4);
            }
            double expected = fmax(0.0, 1.0 - 2.0 / a.samples * sum);
            CHECK_NEAR(ao[(size_t)y * g.width + x], expected, 2e-4);
            ++checked;
            darkened += expected < 0.95;
        }
    CHECK(checked > 10 && darkened > 0);
    free(ao);
    image_free(&img);
}

int main(void)
{
    test_pitfall_integral();
    test_plane();
    test_alchemy_estimator();
    return check_report("test_ao_baselines");
}
