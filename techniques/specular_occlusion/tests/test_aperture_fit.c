/* The gloss-to-aperture search (specular_occlusion/aperture_fit.c) recovers the u its
 * cases were synthesised with, for either cone (the talk's a_s = theta_m and
 * the reflected directions' 2 theta_m): two 64x64 cases of varied inputs
 * (n.v, beta, AO, roughness; a masked-out border) whose "reference" is the
 * cone/cone image at u0 = 10^-1.3, so the mean DSSIM is 0 at u0 and the
 * search must land there (to well within its scan step); and, as issue 26
 * asks, the talk's u = 0.01 with noise added (uniform, +-0.02 per pixel,
 * fixed seed) is recovered to within 0.1 decade, inside the range. Also:
 * the curve is the scan, sorted by u; every figure is a DSSIM (>= 0); the
 * talk's u = 0.01 scores no better than the fit; the evaluation count is
 * scan + golden section + 1. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "specular_occlusion/aperture_fit.h"
#include "tests/check.h"

enum { SIZE = 64 };
static const double LOG10_U0 = -1.3;

/* Smoothly varying inputs (a different pattern per `seed`), 0 on the border. */
static void synthesise_inputs(so_pixel_inputs *in, int seed)
{
    size_t n = (size_t)SIZE * SIZE;
    in->width = in->height = SIZE;
    in->mask = calloc(6 * n, sizeof(float));
    in->n_dot_v = in->mask + n, in->beta = in->mask + 2 * n, in->ao_cosine = in->mask + 3 * n;
    in->ao_uniform = in->mask + 4 * n, in->roughness = in->mask + 5 * n;
    for (int y = 2; y < SIZE - 2; ++y)
        for (int x = 2; x < SIZE - 2; ++x) {
            size_t p = (size_t)y * SIZE + x;
            double s = (double)x / SIZE, t = (double)y / SIZE, w = 0.5 + 0.5 * sin(7.0 * s * t + seed);
            in->mask[p] = 1.0f;
            in->n_dot_v[p] = (float)(0.2 + 0.8 * t);
            in->beta[p] = (float)(1.4 * w * s);
            in->ao_cosine[p] = in->ao_uniform[p] = (float)(0.3 + 0.65 * (1.0 - s * w));
            in->roughness[p] = (float)(0.15 + 0.8 * t * (0.5 + 0.5 * w));
        }
}

/* A case whose reference is the cone/cone image of `mapping` at 10^log10_u,
 * plus uniform noise of amplitude `noise` (a fixed linear congruential
 * sequence), clamped to [0, 1]. */
static void synthesise_case(aperture_case *c, float *reference, int seed, so_aperture_mapping mapping,
                            double log10_u, double noise)
{
    synthesise_inputs(&c->inputs, seed);
    so_variant v = {SO_VARIANT_CONE_EXACT, mapping, pow(10.0, log10_u), SO_AO_COSINE, NULL};
    so_approx_evaluate(&c->inputs, &v, reference);
    uint32_t state = 12345u + (uint32_t)seed;
    for (int p = 0; p < SIZE * SIZE; ++p) {
        state = state * 1664525u + 1013904223u;
        double offset = noise * (2.0 * (state >> 8) / 16777216.0 - 1.0);
        reference[p] = (float)fmin(1.0, fmax(0.0, reference[p] + offset));
    }
    c->reference = reference;
    snprintf(c->name, sizeof c->name, "synthetic %d", seed);
}

static void check_curve(const aperture_fit *fit)
{
    CHECK(fit->curve_count == 96); /* log10 u from -12 to -0.125 by 1/8 */
    for (int i = 0; i < fit->curve_count; ++i) {
        CHECK(fit->curve_dssim[i] >= 0.0);
        CHECK(fit->curve_dssim[i] >= fit->dssim);
        if (i > 0)
            CHECK(fit->curve_u[i] > fit->curve_u[i - 1]);
    }
    CHECK(fit->evaluations > fit->curve_count + 1);
}

/* The regions partition the cases' surface pixels; without noise each
 * region's RMSE is lowest at a scan point next to the synthesised u. */
static void check_regions(const aperture_fit *fit, const aperture_case *cases, double log10_u)
{
    long surface = 0, counted = 0;
    for (int i = 0; i < 2; ++i)
        for (int p = 0; p < SIZE * SIZE; ++p)
            surface += cases[i].inputs.mask[p] != 0.0f;
    for (int k = 0; k < APERTURE_REGIONS; ++k) {
        counted += fit->region_pixels[k];
        CHECK(fit->region_pixels[k] > 0);
        if (!isnan(log10_u))
            CHECK_MSG(fabs(log10(fit->region_best_u[k]) - log10_u) <= 0.125, "%s: lowest RMSE at log10 u %.3f",
                      aperture_region_name((aperture_region)k), log10(fit->region_best_u[k]));
    }
    CHECK(counted == surface);
}

static void recover(so_aperture_mapping mapping, double log10_u, double noise, double tolerance)
{
    static float references[2][SIZE * SIZE];
    aperture_case cases[2];
    for (int i = 0; i < 2; ++i)
        synthesise_case(&cases[i], references[i], i, mapping, log10_u, noise);
    aperture_fit fit;
    gt_error e;
    CHECK(aperture_fit_run(cases, 2, mapping, 1, &fit, &e) == 0);
    CHECK_MSG(fabs(fit.log10_u - log10_u) <= tolerance, "%s: log10 u %.4f, synthesised %.4f",
              so_aperture_name(mapping), fit.log10_u, log10_u);
    CHECK(fit.mapping == mapping && !fit.at_range_edge);
    CHECK_NEAR(fit.u, pow(10.0, fit.log10_u), 1e-12);
    CHECK(fit.dssim >= 0.0 && (noise > 0.0 || fit.dssim < 1e-4));
    CHECK(fit.dssim_at_published >= fit.dssim);
    check_curve(&fit);
    check_regions(&fit, cases, noise == 0.0 ? log10_u : NAN);
    for (int i = 0; i < 2; ++i)
        aperture_case_free(&cases[i]);
}

int main(void)
{
    static const so_aperture_mapping cones[2] = {SO_APERTURE_PHONG_U, SO_APERTURE_PHONG_U_REFLECTED};
    for (int k = 0; k < 2; ++k) {
        recover(cones[k], LOG10_U0, 0.0, 0.01);
        recover(cones[k], -2.0, 0.02, 0.1);
    }
    aperture_fit fit;
    gt_error e;
    CHECK(aperture_fit_run(NULL, 0, SO_APERTURE_DROBOT, 1, &fit, &e) == -1 && strstr(e.message, "drobot"));
    return check_report("test_aperture_fit");
}
