/* The bilateral filter's options (gtao_spatial_filter.h): the
 * default is gtao_denoiser.c's filter (bitwise, two implementations); on a
 * plane seen at a grazing angle, the second derivatives model linear depth
 * better than the first alone (weights closer to 1); a clamp window too
 * wide to bind is the plain accumulation. */
#include <math.h>
#include <stdlib.h>

#include "gtao/gtao_denoiser.h"
#include "gtao/gtao_spatial_filter.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

static int render_gbuffer(const char *spec, const char *camera_json, image *img, ss_gbuffer *g)
{
    gt_error e;
    scene s;
    camera cam;
    if (scene_load(spec, &s, &e) != 0 || camera_parse_json(camera_json, "test camera", &cam, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return -1;
    }
    reference_request req = {.quantity = QUANTITY_GBUFFER, .sampling = {.spp = 1, .seed = 7, .threads = 2},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    int rc = reference_render(&s, spec, &cam, &req, img, &stats, &e);
    scene_free(&s);
    camera_view v = camera_view_from(&cam);
    ss_camera c = {v.forward, v.right, v.up, v.tan_half_yfov, v.aspect};
    if (rc != 0 || ss_gbuffer_from_image(img, spec, c, g, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return -1;
    }
    return 0;
}

/* A deterministic noisy image in [0, 1]. */
static void noise_image(size_t n, float *out)
{
    uint32_t state = 12345u;
    for (size_t i = 0; i < n; ++i) {
        state = state * 1664525u + 1013904223u;
        out[i] = (float)(state >> 8) / 16777216.0f;
    }
}

static void test_default_is_denoiser(const ss_gbuffer *g)
{
    size_t n = (size_t)g->width * g->height;
    float *in = malloc(sizeof(float) * n), *a = malloc(sizeof(float) * n), *b = malloc(sizeof(float) * n);
    noise_image(n, in);
    int differ = 0;
    for (int frame = 0; frame < 2; ++frame) {
        gtao_spatial_denoise(g, frame, in, a);
        gtao_spatial_filter(g, frame, &gtao_spatial_default, in, b);
        for (size_t i = 0; i < n; ++i)
            differ += a[i] != b[i];
    }
    printf("default options vs gtao_spatial_denoise: %d pixels differ\n", differ);
    CHECK(differ == 0);
    /* a clamp window too wide to bind is the plain running mean */
    for (int frame = 0; frame < 3; ++frame) {
        gtao_temporal_accumulate(in, frame, n, a);
        gtao_temporal_clamped(g, in, frame, 1e30f, b);
        noise_image(n / 2 + (size_t)frame, in);
    }
    differ = 0;
    for (size_t i = 0; i < n; ++i)
        differ += a[i] != b[i];
    CHECK(differ == 0);
    free(in);
    free(a);
    free(b);
}

/* Mean 1 - w over every pixel's 4x4 window on a plane (all neighbours
 * belong to it, so an exact depth model gives 0). */
static double mean_rejection(const ss_gbuffer *g, gtao_depth_test test)
{
    gtao_spatial_options o = gtao_spatial_default;
    o.depth_test = test;
    double sum = 0.0;
    long count = 0;
    for (int y = 3; y < g->height - 3; ++y)
        for (int x = 3; x < g->width - 3; ++x)
            for (int oy = -1; oy <= 2; ++oy)
                for (int ox = -1; ox <= 2; ++ox)
                    if (ss_covered(g, x, y) && ss_covered(g, x + ox, y + oy)) {
                        sum += 1.0 - gtao_depth_test_weight(g, &o, x, y, ox, oy);
                        ++count;
                    }
    return count > 0 ? sum / count : 1.0;
}

static void test_second_derivatives_on_a_plane(void)
{
    image img;
    ss_gbuffer g;
    if (render_gbuffer("builtin:plane",
                       "{\"position\":[0,0.4,6],\"target\":[0,0,0],\"up\":[0,1,0],\"yfov_deg\":40,\"width\":48,"
                       "\"height\":48}",
                       &img, &g) != 0) {
        CHECK(0);
        return;
    }
    double d1 = mean_rejection(&g, GTAO_DEPTH_LINEAR_D1), d2 = mean_rejection(&g, GTAO_DEPTH_LINEAR_D2);
    double log1 = mean_rejection(&g, GTAO_DEPTH_LOG_D1);
    printf("grazing plane, mean 1 - w: linear + 1st %.3g, linear + 1st + 2nd %.3g, log + 1st %.3g\n", d1, d2, log1);
    CHECK(d2 < 0.75 * d1); /* the slope's curvature modelled: well below linear + 1st */
    CHECK(d2 < log1);      /* and below log + 1st, the talk's alternative */
    image_free(&img);
}

int main(void)
{
    image img;
    ss_gbuffer g;
    if (render_gbuffer("builtin:boxes",
                       "{\"position\":[27,22,35],\"target\":[0,0,0],\"up\":[0,1,0],\"yfov_deg\":45,\"width\":48,"
                       "\"height\":40}",
                       &img, &g) != 0)
        return 1;
    test_default_is_denoiser(&g);
    image_free(&img);
    test_second_derivatives_on_a_plane();
    return check_report("test_gtao_spatial_filter");
}
