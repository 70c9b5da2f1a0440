/* Multiple-scattering energy compensation of Kulla & Conty 2017 ("Revisiting
 * Physically Based Shading at Imageworks", SIGGRAPH course; after Kelemen &
 * Szirmay-Kalos 2001): a single-scattering microfacet BRDF of directional
 * albedo E(mu) loses 1 - E(mu) of the energy a white surface should keep.
 * The compensation adds a diffuse-like lobe
 *   f_ms(mu_o, mu_i) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg))
 * whose cosine-weighted integral over mu_i is exactly 1 - E(mu_o), with the
 * cosine-weighted average albedo
 *   E_avg = 2 int_0^1 E(mu) mu dmu,
 * so a white surface reflects E(mu_o) + (1 - E(mu_o)) = 1 (the white
 * furnace). For a coloured Fresnel the lobe is scaled by
 *   F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),   F_avg = 2 int_0^1 F(mu) mu dmu,
 * which for Schlick's F = F0 + (1 - F0)(1 - mu)^5 is F0 + (1 - F0) / 21.
 *
 * E(mu, r) is the GGX single-scattering albedo of the split-sum DFG table
 * (luts/dfg_lut.h: height-correlated Smith, alpha = r^2); this file adds the
 * one table it needs besides: E_avg against perceptual roughness r, a 1-D
 * table of N values at texel centres r_j = (j + 0.5) / N, looked up linearly
 * with clamp-to-edge as a GPU samples a 1-D texture. */
#ifndef GTLAB_KULLA_CONTY_LUT_H
#define GTLAB_KULLA_CONTY_LUT_H

#define KULLA_CONTY_MIN_SIZE 4
#define KULLA_CONTY_MAX_SIZE 256

/* E_avg(r) by adaptive Gauss-Kronrod over mu of dfg_integrate's E; *error
 * (may be NULL): the quadrature's estimate. */
double kulla_conty_average_albedo(double roughness, double *error);

/* The compensation lobe f_ms for albedos e_out = E(mu_o), e_in = E(mu_i)
 * and e_avg = E_avg; 0 where nothing is lost (e_avg = 1). */
double kulla_conty_lobe(double e_out, double e_in, double e_avg);

/* F_avg of Schlick's Fresnel with reflectance f0 at normal incidence. */
double kulla_conty_fresnel_average_schlick(double f0);

/* The coloured lobe's scale F_avg^2 E_avg / (1 - F_avg (1 - E_avg)). */
double kulla_conty_fresnel_scale(double f_avg, double e_avg);

typedef struct {
    int size;
    float *average_albedo;     /* size values, E_avg((j + 0.5) / size) */
    double max_error_estimate; /* the largest quadrature estimate of them */
} kulla_conty_lut;

/* 1 when KULLA_CONTY_MIN_SIZE <= size <= KULLA_CONTY_MAX_SIZE. */
int kulla_conty_lut_size_valid(int size);
/* Fills the table (OpenMP, `threads` workers, each entry alone: the bits do
 * not depend on it). 0, or -1 (size out of range or no memory; lut empty). */
int kulla_conty_lut_build(kulla_conty_lut *lut, int size, int threads);
void kulla_conty_lut_free(kulla_conty_lut *lut);

/* Linear lookup at roughness r, clamp-to-edge: x = clamp(r, 0, 1) N - 0.5,
 * i0 = floor(x) clamped to [0, N - 1], weight x - i0 (in float, as a GPU). */
float kulla_conty_lut_sample(const kulla_conty_lut *lut, float roughness);

/* One paragraph describing the table and its axis, for file metadata. */
const char *kulla_conty_lut_description(void);

#endif
