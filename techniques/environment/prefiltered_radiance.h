/* GGX pre-filtered radiance, the first factor of the split sum (Karis
 * 2013, "Real Shading in Unreal Engine 4", eqs. 5-7), and the split sum
 * itself with the DFG LUT (luts/dfg_lut.h) as its second factor:
 *
 *   L_spec(v) ~ P(R, r) (F0 A(n.v, r) + B(n.v, r))
 *   P(R, r)   = \int_{H(R)} L(l) D(h) (R.l) dl / \int_{H(R)} D(h) (R.l) dl,  h = normalize(l + R)
 *
 * P is the environment filtered with GGX's lobe under Karis's assumption
 * n = v = R (the lobe becomes symmetric about R, so one map per roughness
 * serves every view). It is evaluated as Karis's listing (PrefilterEnvMap)
 * does: N = `samples` half vectors from GGX's D (n.h)-distribution at
 * Hammersley points ((i + 0.5)/N, radical inverse of i), l = reflect(-R, h),
 * weights n.l, P = sum L(l) (n.l) / sum (n.l). Each sample reads a filtered
 * level of the source's solid-angle-weighted pyramid
 * (environment/environment_equirect.h) chosen by the ratio of the sample's solid
 * angle to a texel's (Colbert and Krivanek 2007, "GPU-Based Importance
 * Sampling", GPU Gems 3 ch. 20, eq. 13):
 *   lod = max(0, 1/2 log2(Omega_s / Omega_p) + 1),  Omega_s = 1 / (N pdf(l)),  pdf(l) = D(h) / 4
 * (at n = v, v.h = n.h, so pdf(l) = D (n.h) / (4 v.h) = D / 4), Omega_p the
 * source's mean texel solid angle 4 pi / (W H). Deterministic: the same
 * points for every texel, no noise; a constant environment gives that
 * constant exactly (the weights are normalised).
 *
 * Roughness per mip level (engines store one roughness per level of a
 * mip chain): level k of K has perceptual roughness r_k = k / (K - 1) and
 * width max(width >> k, 8); a lookup at roughness r reads the fractional
 * level r (K - 1), bilinear within each level, linear between the two, the
 * linear mapping of Karis's and LearnOpenGL's code. (Filament's
 * lod = (K - 1) r (2 - r) and UE4's log2-of-roughness mapping give more
 * levels to low roughness; with K = 6 the linear one's worst case is the
 * interpolation between r = 0 and 0.2.) Level 0 (r = 0, a mirror) is the
 * source read at the level whose texels match the output's. */
#ifndef GTLAB_ENVIRONMENT_PREFILTERED_RADIANCE_H
#define GTLAB_ENVIRONMENT_PREFILTERED_RADIANCE_H

#include "luts/dfg_lut.h"
#include "environment/environment_equirect.h"

enum { PREFILTERED_MAX_LEVELS = 12, PREFILTERED_MIN_WIDTH = 8 };

typedef struct {
    int levels, samples;
    int width[PREFILTERED_MAX_LEVELS], height[PREFILTERED_MAX_LEVELS];
    float *rgb[PREFILTERED_MAX_LEVELS];
} prefiltered_radiance;

/* r_k = k / (levels - 1). */
double prefiltered_level_roughness(int k, int levels);

/* P(R, r) at one direction from the source's pyramid with `samples`
 * points; out_solid_angle is the solid angle of the output texel (used at
 * r = 0 only). */
void prefiltered_radiance_filter(const equirect_pyramid *source, const double R[3], double roughness, int samples,
                                 double out_solid_angle, float out[3]);

/* Builds `levels` (2 .. PREFILTERED_MAX_LEVELS) levels, level 0 width x
 * width/2 (width even, >= PREFILTERED_MIN_WIDTH); OpenMP over `threads`,
 * every texel alone. Returns 0, or -1 when out of memory or a size is invalid. */
int prefiltered_radiance_build(prefiltered_radiance *p, const environment_equirect *env, int width, int levels,
                               int samples, int threads);
void prefiltered_radiance_free(prefiltered_radiance *p);

/* P(R, r) from the levels: the lookup a shader does. */
void prefiltered_radiance_lookup(const prefiltered_radiance *p, const double R[3], double roughness, float out[3]);

/* The split sum: P(R, r) (F0 A + B), A and B from dfg_lut_sample(n.v, r),
 * per channel of f0. */
void split_sum_specular(const prefiltered_radiance *p, const dfg_lut *dfg, const double R[3], double n_dot_v,
                        double roughness, const double f0[3], double out[3]);

#endif
