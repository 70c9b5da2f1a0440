/* The LTC sphere light scored on the refit's held-out configurations
 * (sphere_light/sphere_light_study.h, "LTC sphere lights"): its residual, the paired
 * differences against Karis and Decima, and the N-gon's own error. */
#include <math.h>
#include <stdlib.h>

#include "core/progress.h"
#include "core/statistics/sample_mean.h"
#include "ltc/ltc_sphere.h"
#include "sphere_light/sphere_light_fit.h"
#include "sphere_light/sphere_light_study.h"

double sphere_ltc_residual(const ltc_table *t, const sphere_light_sample *s)
{
    double value = ltc_sphere_ggx(t, s->v, s->lc, s->sin_sigma, sqrtf(s->alpha));
    return log((value + SPHERE_FIT_FLOOR) / (s->reference + SPHERE_FIT_FLOOR));
}

/* |residual| of sample s under held-out model m of the outcome. */
static double other_abs_residual(const sphere_fit_outcome *fit, int m, const sphere_light_sample *s)
{
    const decima_sphere_constants published = decima_sphere_published();
    if (m == SPHERE_FIT_KARIS)
        return fabs(sphere_light_residual(SPHERE_MODEL_KARIS, NULL, s));
    const decima_sphere_constants *k = m == SPHERE_FIT_PUBLISHED ? &published : &fit->fit.constants;
    return fabs(sphere_light_residual(SPHERE_MODEL_DECIMA, k, s));
}

/* The N-gon's own error at sample s in the residual's terms:
 * |ln((ngon + 0.01)/(exact + 0.01))|, both as radiance per unit normal
 * illuminance (E times the LTC integral over pi sin^2 sigma), the exact
 * disk being the 1024-gon. */
double sphere_ltc_ngon_error(const ltc_table *t, const sphere_light_sample *s, int sides)
{
    float texel[LTC_CHANNELS];
    ltc_table_sample(t, s->v.z, sqrtf(s->alpha), texel);
    double scale = texel[LTC_MAGNITUDE] / (M_PI * s->sin_sigma * s->sin_sigma);
    double exact = scale * ltc_sphere_integral(texel, s->v, s->lc, s->sin_sigma, LTC_MAX_SIDES);
    double ngon = scale * ltc_sphere_integral(texel, s->v, s->lc, s->sin_sigma, sides);
    return fabs(log((ngon + SPHERE_FIT_FLOOR) / (exact + SPHERE_FIT_FLOOR)));
}

static void score_ngon(const ltc_table *t, const sphere_light_sample *test, int count, sphere_ltc_result *out)
{
    double sum = 0.0, worst = 0.0;
    for (int i = 0; i < count; ++i) {
        double err = sphere_ltc_ngon_error(t, &test[i], LTC_SPHERE_SIDES);
        sum += err, worst = fmax(worst, err);
    }
    out->ngon_mean = sum / count, out->ngon_max = worst;
}

/* Per model of the outcome, the paired mean of |other| - |LTC| and its
 * standard error (d: count doubles of scratch). */
static void score_pairs(const ltc_table *t, const sphere_light_sample *test, int count, const sphere_fit_outcome *fit,
                        double *d, sphere_ltc_result *out)
{
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m) {
        for (int i = 0; i < count; ++i)
            d[i] = other_abs_residual(fit, m, &test[i]) - fabs(sphere_ltc_residual(t, &test[i]));
        sample_mean_se(d, count, &out->paired[m], &out->paired_se[m]);
    }
}

void sphere_ltc_score(const ltc_table *t, const sphere_light_sample *test, int count, const sphere_fit_outcome *fit,
                      sphere_ltc_result *out)
{
    sphere_light_error_sums sums = {0};
    for (int i = 0; i < count; ++i)
        sphere_light_error_add(&sums, sphere_ltc_residual(t, &test[i]));
    sphere_light_error_finish(&sums, &out->held_out);
    double *d = malloc(sizeof *d * (size_t)(count > 0 ? count : 1));
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m)
        out->paired[m] = out->paired_se[m] = NAN;
    if (d)
        score_pairs(t, test, count, fit, d, out);
    free(d);
    score_ngon(t, test, count, out);
}
