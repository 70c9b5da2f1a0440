/* Importance sampling of an environment (core/optics/environment_map.h) by
 * luminance, and the multiple-importance-sampling weights that combine it
 * with BRDF sampling.
 *
 * The distribution. Texel (r, c) is drawn with probability
 *   P(r, c) = Y_rc Omega_r / I,   I = sum Y Omega = \int Y(w) dw,
 * Y the texel's Rec. 709 luminance and Omega_r its exact solid angle (the
 * sin theta weighting of pbrt's latitude-longitude sampler, integrated over
 * the texel's band rather than taken at its centre); a 2-D piecewise-
 * constant distribution (core/sampling/environment_distribution.h) over rows, then
 * columns. Within the texel the direction is uniform in solid angle (phi and
 * cos theta uniform over its ranges). So the density per unit solid angle is
 *   pdf(w) = P(r, c) / Omega_r = Y(w) / I,
 * exactly proportional to the piecewise-constant lookup: for a grey
 * environment L / pdf = I is the same for every sample. The rotation turns
 * the samples with the environment and leaves the density unchanged; the
 * intensity scales L and not the density. A constant environment is sampled
 * uniformly, pdf = 1 / (4 pi); an environment of luminance 0 everywhere
 * cannot be sampled (usable = 0; its radiance is 0, so BRDF sampling alone
 * is exact for it).
 *
 * MIS. The references draw each direction from a mixture: with probability
 * c from the BRDF's sampler (density p_b) and otherwise from the
 * environment's (p_e), and weight the sample by f / p_mix,
 *   p_mix = c p_b + (1 - c) p_e.
 * This is the one-sample model of multiple importance sampling with the
 * balance heuristic (Veach 1997, sec. 9.2.4 and 9.2.2): strategy i's weight
 * is w_i = c_i p_i / sum_j c_j p_j, the weights sum to 1 wherever some
 * p_i > 0, and f w_i / (c_i p_i) = f / p_mix whichever strategy drew the
 * direction. For the one-sample model the balance heuristic is the best
 * weighting (Veach, Theorem 9.4; the power heuristic's advantage holds for
 * the multi-sample model), and it costs one ray per vertex: no shadow ray
 * beside the BRDF ray. */
#ifndef GTLAB_CORE_OPTICS_ENVIRONMENT_SAMPLER_H
#define GTLAB_CORE_OPTICS_ENVIRONMENT_SAMPLER_H

#include "core/sampling/environment_distribution.h"
#include "core/optics/environment_map.h"

typedef struct {
    const environment_map *env;
    int usable;            /* 0: luminance 0 everywhere (never sample) */
    double integral;       /* I = \int Y dw (intensity 1) */
    /* per texel: its radiance (intensity included) and Y / I, the density per
     * unit solid angle, side by side: a lookup touches one cache line */
    float (*texel)[4];
    double *row_cos;       /* cos(pi r / H), r = 0 .. H: the rows' bounds */
    distribution_2d texels;
} environment_sampler;

/* env must outlive the sampler. Returns 0, or -1 with e (out of memory). */
int environment_sampler_init(environment_sampler *s, const environment_map *env, gt_error *e);
void environment_sampler_free(environment_sampler *s);

/* A unit world direction from u in [0, 1)^2, and its density. Only when usable. */
vec3 environment_sampler_sample(const environment_sampler *s, const float u[2], float *pdf);

/* The density of environment_sampler_sample at unit world direction w. */
float environment_sampler_pdf(const environment_sampler *s, vec3 w);

/* The radiance (intensity included) and the density at unit world
 * direction w from one texel lookup: environment_map_radiance and
 * environment_sampler_pdf at once. */
void environment_sampler_lookup(const environment_sampler *s, vec3 w, float rgb[3], float *pdf);

/* Many at once, the same bits as one at a time: environment_sampler_sample's
 * directions w[i] for the points u[i] (i < n; only when usable), and
 * environment_sampler_lookup's radiance and density at the unit world
 * directions w[i]. A lookup is a cache miss into 16 bytes per texel and a
 * draw two more (the conditional row's guide entry, then the CDF where the
 * search starts: a 1024 x 512 map has 6 MB of tables), each waiting on the
 * one before. So these take all n together, prefetching
 * (__builtin_prefetch) ahead of each read: the draws' rows (the marginal
 * is small) with their guide entries prefetched, then one loop that reads
 * draw i + 6's guide entry and prefetches its CDF line while it finishes
 * draw i (search, direction, drawn texel prefetched); the lookups' texel
 * indices (prefetched), then their loads. The misses of many directions
 * overlap instead of following one another. */
void environment_sampler_sample_many(const environment_sampler *s, int n, const float (*u)[2], vec3 *w);
void environment_sampler_lookup_many(const environment_sampler *s, int n, const vec3 *w, float (*rgb)[3],
                                     float *pdf);

/* The one-sample balance-heuristic weight of strategy a, chosen with
 * probability c_a, against strategy b: c_a p_a / (c_a p_a + c_b p_b)
 * (0 when both densities are 0). */
static inline double environment_mis_balance(double c_a, double p_a, double c_b, double p_b)
{
    double sum = c_a * p_a + c_b * p_b;
    return sum > 0.0 ? c_a * p_a / sum : 0.0;
}

#endif
