/* Visibility-bitmask AO (vbao.h):
 *  - sector rounding (the paper's and centre rule) on hand-worked intervals;
 *  - a slice's free runs integrate GTAO's arc integrals exactly;
 *  - a plane gives 1;
 *  - with infinite thickness, VBAO equals brute-force GTAO within the sector
 *    quantisation bound (each of the two visible-arc ends moves by at most
 *    half a sector of pi/N, where the cosine integrand is at most 1: per
 *    slice |dV| <= pi/N times the slice weight), and the error falls with N;
 *  - brute-force VBAO (back face at depth + T, centre rounding, 32 sectors,
 *    64 slices, every pixel cell) converges to the thickness-T height-field
 *    Monte Carlo reference, while infinite thickness does not. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/reference_schema.h"
#include "gtao/vbao.h"
#include "ao/heightfield_ao_integrator.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

#define PI 3.14159265358979
enum { SPP = 256 };
static const float test_thickness = 0.5f;

static void test_sector_bits(void)
{
    CHECK(vbao_sector_bits(0.0f, 1.0f, 32, VBAO_ROUND_CENTRE) == 0xFFFFFFFFu);
    CHECK(vbao_sector_bits(0.0f, 1.0f, 32, VBAO_ROUND_PAPER) == 0xFFFFFFFFu);
    CHECK(vbao_sector_bits(0.5f, 1.0f, 4, VBAO_ROUND_CENTRE) == 0xCu);
    CHECK(vbao_sector_bits(0.49f, 0.51f, 32, VBAO_ROUND_CENTRE) == 0u);   /* no centre inside */
    CHECK(vbao_sector_bits(0.49f, 0.51f, 32, VBAO_ROUND_PAPER) == 1u << 15); /* floor start, one sector */
    CHECK(vbao_sector_bits(0.3f, 0.42f, 10, VBAO_ROUND_CENTRE) == 0x8u);   /* only the centre 0.35 */
    CHECK(vbao_sector_bits(-0.5f, 0.1f, 8, VBAO_ROUND_CENTRE) == 0x1u);
    CHECK(vbao_sector_bits(1.2f, 1.5f, 8, VBAO_ROUND_PAPER) == 0u);
}

/* The visibility of the free sectors above a boundary equals the arc
 * integral from the boundary's angle to the hemisphere's end. */
static void test_slice_integrals(void)
{
    vbao_params p = vbao_preset(GTAO_PRESET_REFERENCE, INFINITY, VBAO_EXACT);
    double worst = 0.0;
    for (int i = 0; i < 200; ++i) {
        gtao_slice s = {.n = (float)((i % 21) - 10) * 0.14f, .n_len = 0.5f + 0.0025f * (float)i, .weight = 1.0f};
        int k = i % 33;
        uint32_t occupied = k == 0 ? 0u : (k >= 32 ? 0xFFFFFFFFu : (1u << k) - 1u); /* sectors below k */
        float a = s.n + (float)PI * ((float)k / 32.0f - 0.5f), b = s.n + (float)PI * 0.5f;
        /* integral_a^b n_len cos(t - n) |sin t| dt by Simpson */
        double sum = 0.0;
        for (int j = 0; j <= 20000; ++j) {
            double t = a + (b - a) * j / 20000.0, w = j == 0 || j == 20000 ? 1 : (j % 2 ? 4 : 2);
            sum += w * s.n_len * cos(t - s.n) * fabs(sin(t));
        }
        double exact = sum * (b - a) / 60000.0;
        worst = fmax(worst, fabs(vbao_slice_visibility(occupied, &s, &p, NULL) - exact));
        p.counting = VBAO_COUNT_EQUAL;
        CHECK_NEAR(vbao_slice_visibility(occupied, &s, &p, NULL), (32 - k) / 32.0, 1e-6);
        p.counting = VBAO_COUNT_COSINE;
    }
    printf("slice integrals: max |free runs - Simpson| = %.3g\n", worst);
    CHECK(worst < 2e-6);
}

typedef struct {
    image img;
    ss_gbuffer g;
} rendered;

/* The G-buffer of scene_spec at the camera, with the thickness-T height
 * field when spp > 0. */
static int render(const char *scene_spec, const char *camera_json, int spp, float thickness, rendered *r)
{
    gt_error e;
    scene s;
    camera cam;
    if (scene_load(scene_spec, &s, &e) != 0 || camera_parse_json(camera_json, "camera", &cam, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return -1;
    }
    heightfield_ao_options o = heightfield_ao_thickness(thickness);
    reference_request req = {.quantity = spp > 0 ? QUANTITY_HEIGHTFIELD_AO : QUANTITY_GBUFFER,
                             .sampling = {.spp = spp, .seed = 11, .threads = 2}, .normals = NORMAL_SHADING,
                             .settings = &o.header};
    render_stats stats;
    int rc = reference_render(&s, scene_spec, &cam, &req, &r->img, &stats, &e);
    scene_free(&s);
    camera_view v = camera_view_from(&cam);
    ss_camera c = {v.forward, v.right, v.up, v.tan_half_yfov, v.aspect};
    if (rc == 0 && (rc = ss_gbuffer_from_image(&r->img, scene_spec, c, &r->g, &e)) != 0)
        image_free(&r->img);
    if (rc != 0)
        fprintf(stderr, "%s\n", e.message);
    return rc;
}

static const char *const boxes_from_above =
    "{\"position\":[0,26,0],\"target\":[0,0,0],\"up\":[0,0,-1],\"yfov_deg\":40,\"width\":48,\"height\":48}";

static vbao_params brute(vbao_params p, int slices)
{
    p.gtao.slices = slices;
    p.gtao.steps = 0;
    p.gtao.radius = 1e4f;
    p.gtao.falloff = 0.0f;
    p.gtao.max_radius_px = 128.0f;
    return p;
}

static void test_plane(void)
{
    rendered r;
    CHECK(render("builtin:plane", "{\"position\":[3,4,4],\"target\":[0,0,0],\"up\":[0,1,0],\"yfov_deg\":40,"
                 "\"width\":48,\"height\":48}", 0, 0, &r) == 0);
    size_t n = image_pixel_count(&r.img);
    float *ao = calloc(n, sizeof *ao);
    for (int counting = 0; counting < 3; ++counting) {
        vbao_params p = brute(vbao_preset(GTAO_PRESET_REFERENCE, 0.1f, VBAO_EXACT), 32);
        p.counting = (vbao_counting)counting;
        vbao_render(&r.g, &p, ao, NULL);
        double worst = 0.0;
        for (size_t i = 0; i < n; ++i)
            if (r.g.mask[i] != 0.0f)
                worst = fmax(worst, fabs(ao[i] - 1.0));
        printf("plane: VBAO (counting %d) max |V - 1| = %.3g\n", counting, worst);
        CHECK(worst < 1e-5);
    }
    free(ao);
    image_free(&r.img);
}

/* Infinite thickness against brute-force GTAO on the same samples. */
static void test_infinite_is_gtao(const rendered *r)
{
    size_t n = image_pixel_count(&r->img);
    float *gtao = calloc(n, sizeof *gtao), *ao = calloc(n, sizeof *ao);
    vbao_params p = brute(vbao_preset(GTAO_PRESET_REFERENCE, INFINITY, VBAO_EXACT), 16);
    p.backface = VBAO_BACK_VIEW;
    gtao_params g = p.gtao;
    gtao_render(&r->g, &g, gtao, NULL);
    double mean_err[2] = {0, 0};
    for (int pass = 0; pass < 2; ++pass) {
        p.sectors = pass == 0 ? 8 : 32;
        vbao_render(&r->g, &p, ao, NULL);
        int covered = 0, beyond = 0;
        for (int y = 0; y < r->g.height; ++y)
            for (int x = 0; x < r->g.width; ++x) {
                size_t i = (size_t)y * r->g.width + x;
                if (r->g.mask[i] == 0.0f)
                    continue;
                vec3 v = v3_normalize(v3_neg(ss_view_position(&r->g, x, y)));
                double bound = 0.0;
                for (int k = 0; k < p.gtao.slices; ++k)
                    bound += PI / p.sectors * gtao_slice_weight(v, gtao_slice_angle(x, y, 0, k, p.gtao.slices, 0));
                bound /= p.gtao.slices;
                beyond += fabs(ao[i] - gtao[i]) > bound + 1e-5;
                mean_err[pass] += fabs(ao[i] - gtao[i]);
                ++covered;
            }
        mean_err[pass] /= covered;
        printf("T = inf, %d sectors: %d of %d pixels beyond the quantisation bound, mean |VBAO - GTAO| %.4f\n",
               p.sectors, beyond, covered, mean_err[pass]);
        CHECK(beyond == 0);
    }
    CHECK(mean_err[1] < 0.5 * mean_err[0]);
    free(gtao);
    free(ao);
}

/* Pixels of brute-force VBAO within 4 sqrt(stderr^2 + q^2) of the
 * reference: q the quantisation's standard deviation over the slices (two
 * ends per slice, each uniform over half a sector either way, integrand at
 * most 1: (pi/N) / sqrt(12) sqrt(2 / slices)). Returns the share, and the
 * mean difference in *bias. */
static double within_share(const rendered *r, const vbao_params *p, double *bias, double *bias_se)
{
    size_t n = image_pixel_count(&r->img);
    float *ao = calloc(n, sizeof *ao);
    vbao_render(&r->g, p, ao, NULL);
    const float *ref = image_channel_data(&r->img, CH_AO), *se = image_channel_data(&r->img, CH_AO_STDERR);
    double q = PI / p->sectors / sqrt(12.0) * sqrt(2.0 / p->gtao.slices), sum = 0, var = 0;
    int covered = 0, within = 0;
    for (size_t i = 0; i < n; ++i)
        if (r->g.mask[i] != 0.0f) {
            double s = fmax(se[i], 1.0 / SPP), d = ao[i] - ref[i];
            within += fabs(d) <= 4.0 * sqrt(s * s + q * q);
            sum += d;
            var += s * s + q * q;
            ++covered;
        }
    free(ao);
    *bias = sum / covered;
    *bias_se = sqrt(var) / covered;
    return (double)within / covered;
}

static void test_converges_to_thickness_reference(const rendered *r)
{
    vbao_params p = brute(vbao_preset(GTAO_PRESET_REFERENCE, test_thickness, VBAO_EXACT), 64);
    double bias, bias_se;
    double share = within_share(r, &p, &bias, &bias_se);
    printf("brute-force VBAO (T = %.2f) vs thickness-T height field: %.4f of pixels within 4 s.e., mean "
           "difference %+.4f (s.e. %.4f)\n", test_thickness, share, bias, bias_se);
    CHECK(share >= 0.99);
    CHECK(fabs(bias) <= 4.0 * bias_se);
    p.thickness = INFINITY;
    double share_inf = within_share(r, &p, &bias, &bias_se);
    printf("the same with T = inf: %.4f within, mean difference %+.4f\n", share_inf, bias);
    CHECK(share_inf < 0.9);
}

int main(void)
{
    test_sector_bits();
    test_slice_integrals();
    test_plane();
    rendered boxes;
    int rendered_ok = render("builtin:boxes", boxes_from_above, SPP, test_thickness, &boxes) == 0;
    CHECK(rendered_ok);
    if (rendered_ok) {
        test_infinite_is_gtao(&boxes);
        test_converges_to_thickness_reference(&boxes);
        image_free(&boxes.img);
    }
    return check_report("test_vbao");
}
