/* The average-albedo table of Kulla & Conty 2017; see kulla_conty_lut.h. */
#include "kulla_conty/kulla_conty_lut.h"

#include <math.h>
#include <stdlib.h>

#include "core/sampling/quadrature.h"
#include "core/vec3.h" /* M_PI */
#include "luts/dfg_lut.h"

/* The E quadrature's own tolerance is 1e-7; E_avg's is looser by the
 * length of the interval it sums them over. */
#define AVERAGE_TOLERANCE 1e-6

static double cosine_weighted_albedo(double mu, void *ctx)
{
    double e[DFG_CHANNELS];
    dfg_integrate(mu, *(const double *)ctx, e);
    return 2.0 * mu * e[DFG_ALBEDO];
}

double kulla_conty_average_albedo(double roughness, double *error)
{
    /* E falls fastest at grazing mu: split there so bisection need not find it. */
    static const double points[4] = {0.0, 0.05, 0.25, 1.0};
    return quadrature_gk15_split(cosine_weighted_albedo, &roughness, points, 4, AVERAGE_TOLERANCE, error);
}

double kulla_conty_lobe(double e_out, double e_in, double e_avg)
{
    double lost = 1.0 - e_avg;
    return lost > 0.0 ? (1.0 - e_out) * (1.0 - e_in) / (M_PI * lost) : 0.0;
}

/* 2 int_0^1 (1 - mu)^5 mu dmu = 2 B(2, 6) = 2 / 42. */
double kulla_conty_fresnel_average_schlick(double f0) { return f0 + (1.0 - f0) / 21.0; }

double kulla_conty_fresnel_scale(double f_avg, double e_avg)
{
    return f_avg * f_avg * e_avg / (1.0 - f_avg * (1.0 - e_avg));
}

int kulla_conty_lut_size_valid(int size) { return size >= KULLA_CONTY_MIN_SIZE && size <= KULLA_CONTY_MAX_SIZE; }

int kulla_conty_lut_build(kulla_conty_lut *lut, int size, int threads)
{
    *lut = (kulla_conty_lut){0, NULL, 0.0};
    double *estimate = kulla_conty_lut_size_valid(size) ? malloc(sizeof(double) * (size_t)size) : NULL;
    float *values = estimate ? malloc(sizeof(float) * (size_t)size) : NULL;
    if (!values) {
        free(estimate);
        return -1;
    }
#pragma omp parallel for num_threads(threads > 0 ? threads : 1) schedule(dynamic)
    for (int j = 0; j < size; ++j)
        values[j] = (float)kulla_conty_average_albedo((j + 0.5) / size, &estimate[j]);
    double worst = 0.0;
    for (int j = 0; j < size; ++j)
        worst = fmax(worst, estimate[j]);
    free(estimate);
    *lut = (kulla_conty_lut){size, values, worst};
    return 0;
}

void kulla_conty_lut_free(kulla_conty_lut *lut)
{
    free(lut->average_albedo);
    *lut = (kulla_conty_lut){0, NULL, 0.0};
}

float kulla_conty_lut_sample(const kulla_conty_lut *lut, float roughness)
{
    float x = fminf(fmaxf(roughness, 0.0f), 1.0f) * (float)lut->size - 0.5f;
    float base = floorf(x), t = x - base;
    int i0 = (int)base, last = lut->size - 1;
    int a = i0 < 0 ? 0 : (i0 > last ? last : i0), b = i0 + 1 < 0 ? 0 : (i0 + 1 > last ? last : i0 + 1);
    return lut->average_albedo[a] + t * (lut->average_albedo[b] - lut->average_albedo[a]);
}

const char *kulla_conty_lut_description(void)
{
    return "Kulla-Conty 2017 average albedo E_avg(r) = 2 int_0^1 E(mu, r) mu dmu of GGX single scattering "
           "(height-correlated Smith, alpha = r^2, E as in gtlab's DFG table); N values at texel centres "
           "r = (j + 0.5) / N, r the perceptual roughness; linear lookup, clamp to edge.";
}
