/* The 13 -> 9 bloom tap refit: fits, scores and shader constants; see bloom_study.h. */
#include "bloom/bloom_study.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bloom/bloom_kernels.h"
#include "bloom/bloom_pyramid.h"
#include "bloom/bloom_quality.h"
#include "core/files/atomic_file.h"

enum { RESPONSE_STEPS = 33, PHASE_STEPS = 16 };

bloom_request bloom_default_request(study_quality quality)
{
    const bloom_quality *q = bloom_quality_of(quality);
    bloom_request rq = {q->render_width, q->render_height, q->render_spp, q->pyramid_levels, 1};
    return rq;
}

static double jimenez_variance(void)
{
    double w[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT], v = 0.0;
    bloom_tap taps[BLOOM_JIMENEZ_TAPS];
    bloom_jimenez13(taps);
    bloom_footprint_weights(taps, BLOOM_JIMENEZ_TAPS, w);
    for (int j = 0; j < BLOOM_FOOTPRINT; ++j)
        for (int i = 0; i < BLOOM_FOOTPRINT; ++i)
            v += w[j][i] * (i - 2.5) * (i - 2.5);
    return v;
}

void bloom_target_weights(int target, double weights[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT], double *sigma)
{
    double grid[BLOOM_GRID][BLOOM_GRID];
    *sigma = bloom_gaussian_sigma(jimenez_variance());
    bloom_target_grid(target, *sigma, 0.0, 0.0, grid);
    for (int j = 0; j < BLOOM_FOOTPRINT; ++j)
        for (int i = 0; i < BLOOM_FOOTPRINT; ++i)
            weights[j][i] = grid[j + 1][i + 1];
}

/* The talk's measure: each tap's four weights over their sum against the target block's. */
static void normalised_error(const double t[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT], bloom_target_result *r)
{
    double f[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT];
    bloom_footprint_weights(r->fit.taps, BLOOM_FIT_TAPS, f);
    for (int k = 0; k < BLOOM_FIT_TAPS; ++k) {
        int bx = 2 * (k % 3), by = 2 * (k / 3);
        double sf = f[by][bx] + f[by][bx + 1] + f[by + 1][bx] + f[by + 1][bx + 1];
        double st = t[by][bx] + t[by][bx + 1] + t[by + 1][bx] + t[by + 1][bx + 1];
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                double d = fabs(f[by + j][bx + i] / sf - t[by + j][bx + i] / st);
                if (d > r->worst_normalised_error)
                    r->worst_normalised_error = d, r->worst_normalised_tap = k;
            }
    }
}

static void frequency_response(int reference, double sigma, bloom_target_result *r)
{
    double gf[BLOOM_GRID][BLOOM_GRID], gt[BLOOM_GRID][BLOOM_GRID];
    bloom_texel_weights(r->fit.taps, BLOOM_FIT_TAPS, 0.0, 0.0, gf);
    bloom_target_grid(reference, sigma, 0.0, 0.0, gt);
    for (int j = 0; j < RESPONSE_STEPS; ++j)
        for (int i = 0; i < RESPONSE_STEPS; ++i) {
            double wx = M_PI * i / (RESPONSE_STEPS - 1), wy = M_PI * j / (RESPONSE_STEPS - 1);
            r->response_max_error = fmax(r->response_max_error, fabs(bloom_frequency_response(gf, wx, wy) -
                                                                     bloom_frequency_response(gt, wx, wy)));
        }
    r->response_target_nyquist = bloom_frequency_response(gt, M_PI / 2, 0.0);
    r->response_fit_nyquist = bloom_frequency_response(gf, M_PI / 2, 0.0);
}

/* The largest texel weight difference between the 9 taps and the target at a phase; adds squares to *sum_sq. */
static double phase_error(int target, double sigma, const bloom_tap *taps, double px, double py, double *sum_sq)
{
    double gf[BLOOM_GRID][BLOOM_GRID], gt[BLOOM_GRID][BLOOM_GRID], worst = 0.0;
    bloom_texel_weights(taps, BLOOM_FIT_TAPS, px, py, gf);
    bloom_target_grid(target, sigma, px, py, gt);
    for (int j = 0; j < BLOOM_GRID; ++j)
        for (int i = 0; i < BLOOM_GRID; ++i) {
            double d = gf[j][i] - gt[j][i];
            worst = fmax(worst, fabs(d));
            *sum_sq += d * d;
        }
    return worst;
}

/* Every phase on a grid, and the rows of 240x135 -> 120x67. */
static void off_half(int target, double sigma, bloom_target_result *r)
{
    double unused = 0.0, sum_sq = 0.0;
    for (int j = 0; j < PHASE_STEPS; ++j)
        for (int i = 0; i < PHASE_STEPS; ++i)
            r->worst_any_phase = fmax(r->worst_any_phase, phase_error(target, sigma, r->fit.taps, (double)i / PHASE_STEPS,
                                                                      (double)j / PHASE_STEPS, &unused));
    for (int j = 0; j < 67; ++j) {
        double cy = (j + 0.5) * 135.0 / 67.0;
        r->worst_odd_mip = fmax(r->worst_odd_mip, phase_error(target, sigma, r->fit.taps, 0.0, cy - floor(cy), &sum_sq));
    }
    r->rms_odd_mip = sqrt(sum_sq / (67.0 * BLOOM_GRID * BLOOM_GRID));
}

static int fit_target(int f, bloom_result *out, gt_error *e)
{
    static const char *const names[BLOOM_FITS] = {"13 taps, least squares", "13 taps, weights held",
                                                  "Gaussian, least squares"};
    static const int fitted[BLOOM_FITS] = {BLOOM_TARGET_JIMENEZ, BLOOM_TARGET_JIMENEZ, BLOOM_TARGET_GAUSSIAN_6};
    static const int references[BLOOM_FITS] = {BLOOM_TARGET_JIMENEZ, BLOOM_TARGET_JIMENEZ, BLOOM_TARGET_GAUSSIAN};
    bloom_target_result *r = &out->targets[f];
    double t[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT], sigma;
    bloom_target_weights(fitted[f], t, &sigma);
    r->target = names[f], r->fit_target = fitted[f], r->reference = references[f], r->hold_weights = f == 1;
    if (bloom_fit_9tap(t, r->hold_weights, &r->fit, e) != 0)
        return -1;
    for (int j = 0; j < BLOOM_FOOTPRINT; ++j)
        for (int i = 0; i < BLOOM_FOOTPRINT; ++i)
            r->max_target_weight = fmax(r->max_target_weight, t[j][i]);
    normalised_error(t, r);
    frequency_response(r->reference, sigma, r);
    off_half(r->reference, sigma, r);
    return 0;
}

/* Exact halvings from w x h before the first odd size. */
static int exact_halvings(int w, int h)
{
    int n = 0;
    for (; w % 2 == 0 && h % 2 == 0 && w > 1 && h > 1; w /= 2, h /= 2)
        ++n;
    return n;
}

/* The taps as HLSL and GLSL constants: (x, y) offsets in source texels, weight. */
static int write_shaders(const char *dir, const bloom_result *r, gt_error *e)
{
    static const char *const langs[2][3] = {{"hlsl", "static const float3 ", "float3("}, {"glsl", "const vec3 ", "vec3("}};
    for (int l = 0; l < 2; ++l) {
        char text[4096], path[4200];
        size_t len = (size_t)snprintf(text, sizeof text,
                                      "// gtlab: 9 bilinear taps refitted to a bloom downsample (INSIDE, GDC 2016).\n"
                                      "// Sum over k of w_k * tex(uv + xy_k * sourceTexelSize); exact 1/2 resolution only.\n");
        static const char *const names[BLOOM_FITS] = {"JIMENEZ13", "JIMENEZ13_WEIGHTS_HELD", "GAUSSIAN"};
        for (int t = 0; t < BLOOM_FITS; ++t) {
            len += (size_t)snprintf(text + len, sizeof text - len, "%sBLOOM_9TAP_%s[9]%s", langs[l][1], names[t],
                                    l ? " = vec3[9](\n" : " = {\n");
            for (int k = 0; k < BLOOM_FIT_TAPS; ++k) {
                const bloom_tap *p = &r->targets[t].fit.taps[k];
                len += (size_t)snprintf(text + len, sizeof text - len, "    %s%.9f, %.9f, %.9f)%s\n", langs[l][2], p->x,
                                        p->y, p->w, k + 1 < BLOOM_FIT_TAPS ? "," : "");
            }
            len += (size_t)snprintf(text + len, sizeof text - len, "%s;\n", l ? ")" : "}");
        }
        snprintf(path, sizeof path, "%s/bloom_9tap.%s", dir, langs[l][0]);
        if (atomic_write_text(path, text, e) != 0)
            return -1;
    }
    return 0;
}

int bloom_study(const study_context *ctx, const bloom_request *rq, bloom_result *out, gt_error *e)
{
    char dir[4096];
    memset(out, 0, sizeof *out);
    out->request = *rq;
    out->jimenez_variance = jimenez_variance();
    out->gaussian_sigma = bloom_gaussian_sigma(out->jimenez_variance);
    double inside = erf(3.0 / (out->gaussian_sigma * sqrt(2.0)));
    out->gaussian_outside_mass = 1.0 - inside * inside;
    out->exact_levels_1080 = exact_halvings(1920, 1080);
    out->exact_levels_1088 = exact_halvings(1920, 1088);
    if (study_make_dir(ctx, BLOOM_DIR, dir, sizeof dir, e) != 0)
        return -1;
    for (int f = 0; f < BLOOM_FITS; ++f)
        if (fit_target(f, out, e) != 0)
            return -1;
    if (write_shaders(dir, out, e) != 0)
        return -1;
    return bloom_pyramids(ctx, rq, out, e);
}
