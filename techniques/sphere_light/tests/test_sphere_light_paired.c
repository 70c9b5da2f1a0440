/* The sphere-light refit's paired comparison (fit_sphere_light.h) by its
 * identities on synthetic configurations (references made up: the identities
 * hold for any):
 *   - the mean of |r_a| - |r_b| is the difference of the two models' mean
 *     |residual| (sphere_light_measure) to rounding;
 *   - swapping the models negates the mean and keeps the standard error;
 *   - a model against itself is 0 with standard error 0;
 *   - the standard error is the textbook one of the per-configuration
 *     differences, recomputed here by hand. */
#include <math.h>

#include "core/vec3.h"
#include "sphere_light/sphere_light_fit.h"
#include "tests/check.h"

enum { N = 40 };

static void make_samples(sphere_light_sample *s)
{
    for (int i = 0; i < N; ++i) {
        float t = (float)i / N, phi = 2.4f * (float)i;
        vec3 v = v3_normalize(v3(0.6f * t, 0.1f, 1.0f)), lc = v3_normalize(v3(0.5f * cosf(phi), 0.4f * sinf(phi), 1.0f));
        s[i] = (sphere_light_sample){.v = v, .lc = lc, .sin_sigma = 0.02f + 0.3f * t, .alpha = 0.05f + 0.6f * t,
                                     .reference = 0.5 + 3.0 * t, .reference_stderr = 0.01};
    }
}

int main(void)
{
    static sphere_light_sample s[N];
    make_samples(s);
    decima_sphere_constants k = decima_sphere_published();
    sphere_light_errors karis, decima;
    sphere_light_measure(SPHERE_MODEL_KARIS, NULL, s, N, &karis);
    sphere_light_measure(SPHERE_MODEL_DECIMA, &k, s, N, &decima);
    double m, se, m2, se2, m0, se0;
    sphere_light_paired_abs(SPHERE_MODEL_KARIS, NULL, SPHERE_MODEL_DECIMA, &k, s, N, &m, &se);
    sphere_light_paired_abs(SPHERE_MODEL_DECIMA, &k, SPHERE_MODEL_KARIS, NULL, s, N, &m2, &se2);
    sphere_light_paired_abs(SPHERE_MODEL_DECIMA, &k, SPHERE_MODEL_DECIMA, &k, s, N, &m0, &se0);
    CHECK_MSG(fabs(m - (karis.mean_abs - decima.mean_abs)) < 1e-12, "%g vs %g", m, karis.mean_abs - decima.mean_abs);
    CHECK(m2 == -m && se2 == se && m0 == 0.0 && se0 == 0.0);
    double d[N], mean = 0.0, sq = 0.0;
    for (int i = 0; i < N; ++i)
        d[i] = fabs(sphere_light_residual(SPHERE_MODEL_KARIS, NULL, &s[i])) -
               fabs(sphere_light_residual(SPHERE_MODEL_DECIMA, &k, &s[i]));
    for (int i = 0; i < N; ++i)
        mean += d[i] / N;
    for (int i = 0; i < N; ++i)
        sq += (d[i] - mean) * (d[i] - mean);
    CHECK(se > 0.0 && fabs(se - sqrt(sq / (N - 1) / N)) < 1e-12);
    return check_report("sphere_light_paired");
}
