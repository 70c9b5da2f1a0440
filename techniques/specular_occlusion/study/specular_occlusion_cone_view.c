/* The visibility cone's own error and the dimension the 3-D table drops
 * (issue 26, items 1 and 5; specular_occlusion/specular_occlusion_study.h, so_cone_view_result). */
#include <math.h>
#include <stdlib.h>

#include "core/frame.h"
#include "specular_occlusion/cone_visibility_view.h"
#include "metrics/image_error.h"
#include "metrics/noise_corrected.h"
#include "specular_occlusion/specular_occlusion_rankings.h"

static vec3 load3(const float *const c[3], size_t p) { return v3(c[0][p], c[1][p], c[2][p]); }

/* V_s^cone of surface pixel p: the view lifted onto the horizon as the
 * reference does, the bent normal (or n where it is zero) as the cone's axis. */
static double cone_view_pixel(const so_screen_buffers *b, vec3 eye, const so_pixel_inputs *in, size_t p, int strata,
                              uint32_t seed)
{
    vec3 n = load3(b->normal, p), bent = load3(b->bent, p);
    frame f = frame_from_normal(n);
    vec3 v = frame_to_local(&f, v3_normalize(v3_sub(eye, load3(b->position, p))));
    if (v.z < 1e-4f)
        v = v3_normalize(v3(v.x, v.y, 1e-4f));
    vec3 axis = v3_length(bent) > 0.0f ? frame_to_local(&f, v3_normalize(bent)) : v3(0.0f, 0.0f, 1.0f);
    double alpha = (double)in->roughness[p] * in->roughness[p];
    double cos_av = so_visibility_cos_aperture(in->ao_cosine[p], SO_AO_COSINE);
    return so_cone_visibility_view(v, axis, cos_av, fmax(alpha, 1e-3), strata, seed);
}

static void cone_view_image(const so_screen_buffers *b, vec3 eye, const so_pixel_inputs *in, int strata, int case_index,
                            float *out)
{
    long n = (long)b->width * b->height;
#pragma omp parallel for schedule(dynamic, 64)
    for (long p = 0; p < n; ++p)
        out[p] = in->mask[p] >= 0.5f
                     ? (float)cone_view_pixel(b, eye, in, (size_t)p, strata, (uint32_t)(case_index * n + p) + 1u)
                     : 0.0f;
}

static int band_of(float n_dot_v) { return n_dot_v < 0.3f ? 0 : n_dot_v < 0.6f ? 1 : 2; }

/* RMSE of a against b over the mask, less `variance` (noise_corrected_rmse). */
static int rmse(const float *a, const float *b, const so_pixel_inputs *in, double variance, const char *what,
                double *out, gt_error *e)
{
    image_error_stats st;
    if (image_error_compute(a, b, in->mask, in->width, in->height, what, &st, e) != 0)
        return -1;
    *out = noise_corrected_rmse(st.rmse, variance);
    return 0;
}

int so_cone_view_add(so_cone_view_scores *s, const so_screen_buffers *b, vec3 eye, const so_pixel_inputs *in,
                     const float *reference, const float *reference_stderr, int roughness_index, const char *what,
                     gt_error *e)
{
    size_t n = (size_t)in->width * in->height;
    if (s->cases >= SO_RANK_CASES)
        return gt_error_set(e, what, "more than %d specular-occlusion cases", SO_RANK_CASES);
    float *cone = malloc(sizeof(float) * n), *lut = malloc(sizeof(float) * n);
    int rc = cone && lut ? 0 : gt_error_set(e, what, "out of memory");
    if (rc == 0) {
        so_variant v;
        so_variant_parse("lut", &v);
        v.lut = s->lut;
        so_approx_evaluate(in, &v, lut);
        cone_view_image(b, eye, in, s->strata, s->cases, cone);
        double variance = noise_mean_variance(reference_stderr, in->mask, n);
        int c = s->cases;
        rc = rmse(cone, reference, in, variance, what, &s->visibility[c], e);
        if (rc == 0)
            rc = rmse(lut, cone, in, 0.0, what, &s->dropped[c], e);
        if (rc == 0)
            rc = rmse(lut, reference, in, variance, what, &s->total[c], e);
        for (size_t p = 0; p < n && rc == 0; ++p)
            if (in->mask[p] >= 0.5f) {
                int k = band_of(in->n_dot_v[p]);
                double d = (double)lut[p] - cone[p];
                s->band_sq[roughness_index][k] += d * d, s->band_count[roughness_index][k]++;
            }
    }
    free(cone);
    free(lut);
    s->cases += rc == 0;
    return rc;
}

/* The mean over the scenes of per-case values at one roughness. */
static double mean_at(const double *values, int scenes, int k)
{
    double sum = 0.0;
    for (int s = 0; s < scenes; ++s)
        sum += values[s * SO_STUDY_ROUGHNESSES + k];
    return scenes ? sum / scenes : NAN;
}

void so_cone_view_compute(const so_cone_view_scores *s, int scenes, so_cone_view_result *out)
{
    static const double zero[SO_RANK_CASES];
    out->strata = s->strata;
    for (int k = 0; k < SO_STUDY_ROUGHNESSES; ++k) {
        out->visibility_rmse[k] = mean_at(s->visibility, scenes, k);
        out->dropped_rmse[k] = mean_at(s->dropped, scenes, k);
        out->total_rmse[k] = mean_at(s->total, scenes, k);
        for (int j = 0; j < SO_NV_BANDS; ++j) {
            long count = s->band_count[k][j];
            out->dropped_rmse_band[k][j] = count ? sqrt(s->band_sq[k][j] / count) : NAN;
        }
    }
    for (int j = 0; j < SO_NV_BANDS; ++j) {
        out->band_pixels[j] = 0;
        for (int k = 0; k < SO_STUDY_ROUGHNESSES; ++k)
            out->band_pixels[j] += s->band_count[k][j];
    }
    out->visibility = so_paired_over_scenes(s->visibility, zero, 1, scenes, -1);
    out->dropped = so_paired_over_scenes(s->dropped, zero, 1, scenes, -1);
    out->dropped_minus_visibility = so_paired_over_scenes(s->dropped, s->visibility, 1, scenes, -1);
}
