/* The GTAO talk's depth MIP chain with MINIMUM filtering
 * (gtao_depth_mip.h): each level is the minimum of its level-0
 * footprint (against a direct minimum), and on a height field (the depth
 * buffer of the boxes, from above and at a slant) the horizons found with
 * MIN-filtered MIP depths never lie below the full-resolution ones at the
 * same sample points, so AO never rises; on most pixels some horizon is
 * strictly higher (the check can fail). Half resolution keeps each block's
 * closest pixel. */
#include <math.h>
#include <stdlib.h>

#include "gtao/gtao_depth_mip.h"
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

/* Level l texel (x, y) against the minimum over its 2^l x 2^l footprint. */
static void test_chain_is_footprint_minimum(const ss_gbuffer *g, const ss_depth_mip *m)
{
    int wrong = 0;
    for (int l = 0; l < m->levels; ++l)
        for (int y = 0; y < m->height[l]; ++y)
            for (int x = 0; x < m->width[l]; ++x) {
                float lowest = INFINITY;
                for (int fy = y << l; fy < (y + 1) << l; ++fy)
                    for (int fx = x << l; fx < (x + 1) << l; ++fx)
                        if (ss_covered(g, fx, fy) && g->depth[fy * g->width + fx] < lowest)
                            lowest = g->depth[fy * g->width + fx];
                wrong += m->depth[l][y * m->width[l] + x] != lowest;
            }
    printf("MIP chain: %d texels differ from their footprint's minimum\n", wrong);
    CHECK(wrong == 0);
}

static gtao_params search_params(void)
{
    gtao_params p;
    gtao_preset("reference", &p);
    p.slices = 8;
    p.steps = 8;
    p.radius = 1e4f;
    p.falloff = 0.0f;
    p.max_radius_px = 40.0f;
    return p;
}

/* For every covered pixel and 8 slices: h1, h2 of `fetch` against POINT. */
static void test_horizons_never_lower(const ss_gbuffer *g, const ss_depth_mip *m, gtao_depth_fetch fetch,
                                      const char *what)
{
    gtao_params p = search_params();
    int lower = 0, raised_pixels = 0, pixels = 0;
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            if (!ss_covered(g, x, y))
                continue;
            int raised = 0;
            for (int k = 0; k < p.slices; ++k) {
                float phi = gtao_slice_angle(x, y, 0, k, p.slices, 0);
                gtao_slice a, b;
                gtao_mip_search_slice(g, m, GTAO_FETCH_POINT, x, y, &p, phi, 0.5f, &a);
                gtao_mip_search_slice(g, m, fetch, x, y, &p, phi, 0.5f, &b);
                /* Angles run from the view vector: a higher horizon is a smaller |h|.
                 * 1e-5 rad: float rounding of the cosines, a few ulps, through acos. */
                lower += b.h2 > a.h2 + 1e-5f || b.h1 < a.h1 - 1e-5f;
                raised |= b.h2 < a.h2 - 1e-4f || b.h1 > a.h1 + 1e-4f;
            }
            raised_pixels += raised;
            ++pixels;
        }
    printf("%s: %d slice horizons below the full-resolution ones; %d of %d pixels with a raised horizon\n", what,
           lower, raised_pixels, pixels);
    CHECK(lower == 0);
    CHECK(raised_pixels > pixels / 10);
}

static void test_ao_never_higher(const ss_gbuffer *g, const ss_depth_mip *m)
{
    gtao_params p = search_params();
    size_t n = (size_t)g->width * g->height;
    float *point = malloc(sizeof(float) * n), *min = malloc(sizeof(float) * n);
    gtao_mip_frame(g, m, GTAO_FETCH_POINT, &p, point);
    gtao_mip_frame(g, m, GTAO_FETCH_MIP_MIN, &p, min);
    double worst = -INFINITY;
    for (size_t i = 0; i < n; ++i)
        if (g->mask[i] != 0.0f)
            worst = fmax(worst, min[i] - point[i]);
    printf("max AO(MIN MIP) - AO(full resolution) = %.3g\n", worst);
    CHECK(worst <= 1e-5);
    free(point);
    free(min);
}

static void test_half_resolution(const ss_gbuffer *g)
{
    ss_half_gbuffer h;
    CHECK(ss_half_resolution(g, &h) == 0);
    int wrong = 0;
    for (int y = 0; y < h.g.height; ++y)
        for (int x = 0; x < h.g.width; ++x) {
            float lowest = INFINITY;
            for (int k = 0; k < 4; ++k)
                if (ss_covered(g, 2 * x + (k & 1), 2 * y + (k >> 1)))
                    lowest = fminf(lowest, g->depth[(2 * y + (k >> 1)) * g->width + 2 * x + (k & 1)]);
            long i = (long)y * h.g.width + x;
            wrong += isfinite(lowest) ? h.g.mask[i] != 1.0f || h.g.depth[i] != lowest : h.g.mask[i] != 0.0f;
        }
    printf("half resolution: %d pixels not their block's closest\n", wrong);
    CHECK(wrong == 0);
    ss_half_free(&h);
}

static void run(const char *camera_json, const char *what)
{
    image img;
    ss_gbuffer g;
    ss_depth_mip m;
    if (render_gbuffer("builtin:boxes", camera_json, &img, &g) != 0 || ss_depth_mip_build(&g, 4, &m) != 0) {
        CHECK(0);
        return;
    }
    printf("-- %s\n", what);
    test_chain_is_footprint_minimum(&g, &m);
    test_horizons_never_lower(&g, &m, GTAO_FETCH_MIP, "MIP, point-sampled");
    test_horizons_never_lower(&g, &m, GTAO_FETCH_MIP_MIN, "MIP, MIN-filtered");
    test_ao_never_higher(&g, &m);
    test_half_resolution(&g);
    ss_depth_mip_free(&m);
    image_free(&img);
}

int main(void)
{
    run("{\"position\":[0,26,0],\"target\":[0,0,0],\"up\":[0,0,-1],\"yfov_deg\":40,\"width\":64,\"height\":64}",
        "boxes from above");
    run("{\"position\":[27,22,35],\"target\":[0,0,0],\"up\":[0,1,0],\"yfov_deg\":45,\"width\":64,\"height\":48}",
        "boxes at a slant");
    return check_report("test_gtao_depth_mip");
}
