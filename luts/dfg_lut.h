/* The split-sum DFG (environment BRDF) LUT of Karis 2013, "Real Shading in
 * Unreal Engine 4" (SIGGRAPH course notes, eqs. 4-8).
 *
 * The BRDF: GGX D and Smith height-correlated G2 from core/optics/ggx.h (alpha =
 * ggx_alpha(r) = r^2, r the perceptual roughness), Schlick Fresnel
 *   F(v.h) = F0 + (1 - F0) Fc,   Fc = (1 - v.h)^5          (Schlick 1994, eq. 15)
 *   f_r(v, l) = F D(h) G2(v, l) / (4 (n.v)(n.l))
 * The split sum's second factor, the directional albedo under a white
 * environment, is linear in F0 (Karis 2013, eq. 8):
 *   \int_H f_r(v, l) (n.l) dl = F0 A(n.v, r) + B(n.v, r)
 *   A = \int_H (f_r / F) (1 - Fc) (n.l) dl                 ("scale")
 *   B = \int_H (f_r / F) Fc (n.l) dl                       ("bias")
 * The third channel stores E(n.v, r) = A + B = \int_H (f_r / F) (n.l) dl, the
 * single-scattering albedo of a white (F = 1) GGX surface: what the
 * multiple-scattering energy compensation of Kulla & Conty 2017 ("Revisiting
 * Physically Based Shading at Imageworks", E(mu)) and Fdez-Aguera 2019 ("A
 * Multiple-Scattering Microfacet Model for Real-Time Image-based Lighting",
 * E_ss = f_ab.x + f_ab.y) are built on. A shader uses it as Filament does:
 *   specular = (F0 A + B) * prefiltered radiance * (1 + F0 (1 / E - 1))
 * the factor (dfg_energy_compensation) scaling the single-scattering lobe up
 * by the energy 1 - E that a white surface loses to masking (exact for
 * F0 = 1, an approximation for F0 < 1). E is computed in double and rounded
 * once, so it is not exactly float(A) + float(B).
 *
 * Quadrature (deterministic, core/sampling/quadrature.h adaptive Gauss-Kronrod): over
 * the half vector h, in the coordinates (s, phi) of GGX's own cumulative
 * distribution (Walter et al. 2007, eqs. 35-36):
 *   tan^2 theta_h = alpha^2 s / (1 - s),   D(h) cos theta_h dw_h = ds dphi / (2 pi)
 * With l = reflect(v, h), dl = 4 (v.h) dw_h (Walter 2007, eq. 14), so
 *   \int (f_r / F) (n.l) w dl = (1/2pi) \int ds \int dphi G2(v, l) (v.h) w / ((n.v) cos theta_h)
 * D is absorbed by the Jacobian: the integrand has no peak at any roughness
 * (at r -> 0 it is the constant G2 ~ 1 of the mirror), so there is no
 * roughness clamp and no loss of digits in D near n.h = 1. What is left of
 * the lobe's scale is where Fresnel and G2 vary, theta_h ~ 0.1 .. 1, which
 * the s axis squeezes into 1 - s ~ alpha^2 / theta_h^2: the s integral is
 * split at s(theta_h) for theta_h = 2 alpha 4^k (as specular_occlusion_lut.c
 * splits theta at the lobe's scale) so bisection never needs to reach it.
 * l is above the horizon (n.l = 2 (v.h) cos theta_h - n.v > 0) exactly when
 *   cos phi > c = (n.v) (tan^2 theta_h - 1) / (2 tan theta_h sin theta_v)
 * (phi measured from v's azimuth), so the inner integral runs over [0,
 * acos c] (doubled by symmetry) with no kink inside; the outer one is split
 * where c = -1 and c = +1, theta_h = pi/4 -/+ theta_v / 2, and ends there.
 * Tolerances: 1e-7 absolute on each channel (outer), 1e-8 relative to the
 * inner integrand's bound pi / (n.v cos theta_h); the reported error estimate is the sum of the outer estimate and
 * the inner estimates' bound, for the worse of A and B.
 *
 * Axes (as Filament and UE4 tabulate it): texel (i, j) of an N x N table is
 * data[(j N + i) * 3 + c], c = 0 A, 1 B, 2 E; column i at n.v = (i + 0.5) / N,
 * row j at r = (j + 0.5) / N: TEXEL CENTRES (not grid points, unlike
 * specular_occlusion_lut.h), so a GPU samples it at uv = (n.v, r) directly.
 * Row 0 (the top row of the images) is the smoothest. n.v is clamped to at
 * least DFG_MIN_N_DOT_V (Filament's MIN_N_DOT_V): at n.v = 0 the integrand's
 * G2 / n.v is 0/0; texel centres never reach the clamp for N <= 5000.
 *
 * The table is shared: the environment lighting's split sum
 * (techniques/environment/prefiltered_radiance.h, environment_approx.h) and the LTC
 * fit's magnitude and Fresnel term (techniques/ltc/ltc_fit.c) read it; the DFG technique
 * (techniques/dfg/) writes it in every format and studies its size. */
#ifndef GTLAB_LUTS_DFG_LUT_H
#define GTLAB_LUTS_DFG_LUT_H

#define DFG_MIN_N_DOT_V 1e-4
#define DFG_MIN_SIZE 32
#define DFG_MAX_SIZE 256

enum { DFG_SCALE, DFG_BIAS, DFG_ALBEDO, DFG_CHANNELS };

/* One paragraph describing the layout and axes, for file metadata. */
const char *dfg_lut_description(void);

/* (A, B, E) at (n.v, r) by quadrature into out[3]; returns the error
 * estimate (an absolute bound in practice, on A and on B). */
double dfg_integrate(double n_dot_v, double roughness, double out[3]);

/* Filament's energy-compensation factor 1 + F0 (1 / E - 1) for albedo E. */
double dfg_energy_compensation(double albedo, double f0);

typedef struct {
    int size;
    float *data;                  /* size * size * 3, layout above */
    float *error_estimate;        /* size * size: dfg_integrate's estimate per texel */
    double max_error_estimate;    /* the largest of them */
} dfg_lut;

/* 1 when DFG_MIN_SIZE <= size <= DFG_MAX_SIZE. */
int dfg_lut_size_valid(int size);
/* Fills a table (OpenMP, `threads` workers; every texel is computed alone,
 * so the bits do not depend on it). Returns 0, or -1 when the size is out of
 * range (lut left empty) or memory runs out. */
int dfg_lut_build(dfg_lut *lut, int size, int threads);
/* The same without the size check (the DFG interpolation study's 16^2,
 * techniques/dfg/dfg_interpolation.h). */
int dfg_lut_build_any_size(dfg_lut *lut, int size, int threads);
void dfg_lut_free(dfg_lut *lut);

/* Bilinear lookup at uv = (n.v, r) with clamp-to-edge, as a GPU samples the
 * texture (texel centres at (i + 0.5) / N) and as the generated shaders'
 * DFG() does (both are luts/table_lookup.inc), in float: x = clamp(n.v, 0, 1) N
 * - 0.5, i0 = floor(x), weights x - i0, indices clamped to [0, N - 1].
 * (Hardware filtering also rounds the weights to 8 fractional bits; that is
 * not modelled.) */
void dfg_lut_sample(const dfg_lut *lut, float n_dot_v, float roughness, float out[3]);

#endif
