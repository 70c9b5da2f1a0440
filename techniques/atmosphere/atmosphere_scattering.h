/* Light in the atmosphere of atmosphere/atmosphere_model.h for one weather blend
 * t: transmittance, single scattering and a Bruneton-style precomputation of
 * the multiple-scattering orders on internal grids (Bruneton & Neyret 2008
 * section 4; Bruneton 2017, "Precomputed Atmospheric Scattering: a New
 * Implementation", ComputeTransmittance / ComputeSingleScattering /
 * ComputeScatteringDensity / ComputeMultipleScattering).
 *
 * Coordinates: a point at radius r, a view ray of zenith cosine mu, the sun
 * at zenith cosine mu_s. The Decima LUT drops the view-sun azimuth ("ignore
 * theta_sv dependency [Ele09]": the runtime multiplies by the phases p_i(nu)),
 * so everything here is a function of (r, mu, mu_s) alone:
 *  - single scattering, per species i and without phase,
 *      S_i(r, mu, mu_s) = E_sun \int_0^d T(x, x_s) beta_s^i(x_s) T_sun(x_s) ds,
 *    d the distance to the ground or the top, x_s = x + s w; the sun's zenith
 *    cosine at x_s, (r mu_s + s nu) / r_s, is taken at nu = mu mu_s (the sun
 *    90 degrees of azimuth from the view: the mean of that cosine over the
 *    azimuth, which it is linear in); T_sun = transmittance to the top times
 *    the visible fraction of the sun's disc (atmosphere_sun_visibility; below
 *    the horizon the grazing ray's transmittance);
 *  - multiple scattering, azimuth-averaged: with Pbar_i(mu, mu') = (1/2pi)
 *    \int p_i dphi the azimuthal mean of a phase (Rayleigh; Mie: Cornette-
 *    Shanks, g), the averaged radiance of order 1 is
 *      L^1(r, mu', mu_s) = sum_i Pbar_i(mu', mu_s) S_i(r, mu', mu_s),
 *    the scattering density of order k >= 2 (BN08 eq. 7 averaged over the
 *    sun's azimuth: the double azimuthal integral factorises exactly)
 *      J^k(r, mu, mu_s) = sum_j beta_s^j(r) 2pi \int_{-1}^{1} Pbar_j(mu, mu') L^{k-1}(r, mu', mu_s) dmu'
 *    and L^k(r, mu, mu_s) = \int_0^d T(x, x_s) J^k(x_s) ds. Orders 2 ..
 *    ATMOSPHERE_ORDERS are summed; the ground is black (Bruneton's
 *    ground albedo, 0.1 in his demo, is 0 here: no light from the ground).
 *
 * Internal grids (per t):
 *  - transmittance: the optical depth to the top tau(r, mu) of rays not
 *    hitting the ground, 256 x 64 at Bruneton's coordinates x_mu = (d -
 *    d_min) / (d_max - d_min), x_r = rho / H (rho = sqrt(r^2 - R_b^2), H =
 *    sqrt(R_t^2 - R_b^2)), bilinear in tau; grid points by quadrature
 *    (atmosphere_optical_depth, 1e-9). A segment's optical depth is the
 *    difference of two rays' (Bruneton's GetTransmittance);
 *  - multiple scattering: r at altitudes (R_t - R_b) (k / (N_r - 1))^2, mu at
 *    the midpoints of N_mu equal cells of [-1, 1] (the sphere integral's
 *    nodes), mu_s at N_s points of [-0.2, 1]; the integral over mu' uses the
 *    cells' exact phase integrals (the discrete kernel conserves energy),
 *    the ray integrals a fixed composite 4-point Gauss-Legendre rule on 12
 *    panels graded towards both ends (fog ends rays in a few km).
 *
 * Each quantity at any (r, mu, mu_s) is evaluated either FAST (the LUT
 * build) or as a REFERENCE (the tests'); the multiple-scattering density is
 * the grid's in both. */
#ifndef GTLAB_ATMOSPHERE_SCATTERING_H
#define GTLAB_ATMOSPHERE_SCATTERING_H

#include "atmosphere/atmosphere_model.h"

enum { ATMOSPHERE_T_MU = 256, ATMOSPHERE_T_R = 64 };
enum { ATMOSPHERE_MS_R = 24, ATMOSPHERE_MS_MU = 64, ATMOSPHERE_MS_MU_S = 24 };
enum { ATMOSPHERE_ORDERS = 5 };
#define ATMOSPHERE_MS_MU_S_MIN (-0.2)

typedef struct {
    atmosphere_model model;
    double t;
    double *tau_top;      /* [ATMOSPHERE_T_R][ATMOSPHERE_T_MU][3] */
    double *density;      /* sum over k >= 2 of J^k: [MS_R][MS_MU][MS_MU_S][3] */
    double order_mean[ATMOSPHERE_ORDERS + 1]; /* mean of L^k (green) over the grid, k = 1.. */
} atmosphere_solution;

/* Precomputes the grids for blend t with `threads` workers (every grid
 * point alone: bits independent of the count). 0, or -1 out of memory. */
int atmosphere_solve(const atmosphere_model *m, double t, int threads, atmosphere_solution *s);
void atmosphere_solution_free(atmosphere_solution *s);

/* How a quantity is evaluated: FAST (the LUT build) with the transmittance
 * grid and the fixed Gauss-Legendre rules (the error estimate returned is
 * 0: the tests measure it against the others); ADAPTIVE with the grid and
 * adaptive Gauss-Kronrod integrals at the tolerance given (isolates the fixed
 * rules' error); REFERENCE as ADAPTIVE with every optical depth by
 * quadrature (1e-10) instead of the grid. */
typedef enum { ATMOSPHERE_FAST, ATMOSPHERE_ADAPTIVE, ATMOSPHERE_REFERENCE } atmosphere_method;

/* Transmittance of the segment [0, d] of the ray (r, mu), and to the sun. */
void atmosphere_transmittance(const atmosphere_solution *s, atmosphere_method how, double r, double mu, double d,
                              double T[ATMOSPHERE_CHANNELS]);
void atmosphere_transmittance_to_sun(const atmosphere_solution *s, atmosphere_method how, double r, double mu_s,
                                     double T[ATMOSPHERE_CHANNELS]);

/* S_i(r, mu, mu_s) into out[i][c]; REFERENCE: absolute tolerance `tol`
 * times E_sun beta_s^i(0) H_i, returns the largest error estimate relative
 * to that scale. */
double atmosphere_single_scattering(const atmosphere_solution *s, atmosphere_method how, double r, double mu,
                                    double mu_s, double tol, double out[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS]);
/* sum_{k>=2} L^k(r, mu, mu_s): the grid's density integrated along the ray;
 * tolerance and return as above (scale: E_sun beta_s^R(0) H_R). */
double atmosphere_multiple_scattering(const atmosphere_solution *s, atmosphere_method how, double r, double mu,
                                      double mu_s, double tol, double out[ATMOSPHERE_CHANNELS]);
/* The sky's mean radiance over the sphere of directions at r (no sun disc):
 * (1/2) \int_{-1}^{1} [sum_i Pbar_i(mu', mu_s) S_i + sum_{k>=2} L^k](r, mu', mu_s) dmu',
 * split at the horizon and at mu_s, by 4-point Gauss-Legendre on equal
 * panels of each piece: FAST 8 panels; otherwise 32, returning |32 panels -
 * 16 panels| relative to E_sun beta_s^R(0) H_R / 4pi, with the inner ray
 * integrals REFERENCE at `tol` (REFERENCE) or FAST (ADAPTIVE: the outer
 * rule's error alone). */
double atmosphere_sky_mean_radiance(const atmosphere_solution *s, atmosphere_method how, double r, double mu_s,
                                    double tol, double out[ATMOSPHERE_CHANNELS]);

/* ---- A view ray with the sun at its true azimuth (the combination images,
 * height_fog/aerial_perspective_study.h) ----------------------------------------------
 * The tables drop the view-sun azimuth; a pixel has it. The segment
 * [0, length] of the ray from radius r with zenith cosine mu, the sun at
 * zenith cosine mu_s and at cosine nu to the ray (nu = mu mu_s +
 * sqrt((1 - mu^2)(1 - mu_s^2)) cos phi, phi the azimuth between them): the
 * sun's zenith cosine at distance s is exactly (r mu_s + s nu) / r_s (the
 * functions above take nu = mu mu_s, the azimuthal mean). length at most
 * atmosphere_distance_to_boundary. */
typedef struct {
    double r, mu, mu_s, nu, length;
} atmosphere_view_ray;

/* The integrands at distance dist along the ray: single[i][c] = E_sun
 * T(x, x_s) beta_s^i(x_s) T_sun(x_s) and multiple[c] = T(x, x_s) J(x_s), J
 * the grid's density of the orders >= 2 at the point's zenith cosines
 * (trilinear); either may be NULL. */
void atmosphere_view_integrands(const atmosphere_solution *s, atmosphere_method how, const atmosphere_view_ray *ray,
                                double dist, double single[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS],
                                double multiple[ATMOSPHERE_CHANNELS]);

/* The radiance the segment scatters towards the ray's origin,
 *   L = sum_i p_i(nu) S_i + M,   S_i = \int_0^length single_i ds,   M = \int_0^length multiple ds,
 * p_R Rayleigh, p_M Cornette-Shanks (the model's g): the nine integrals by
 * one adaptive Gauss-Kronrod (core/sampling/quadrature.h, vector form) split at the
 * ray rule's breaks, each to tol times its scale (E_sun beta_s^i(0) H_i;
 * M: Rayleigh's), the transmittances as `how` says (FAST is taken as
 * ADAPTIVE). S (may be NULL) receives S_i, M (may be NULL) M. Returns the
 * largest error estimate relative to its scale. */
double atmosphere_view_radiance(const atmosphere_solution *s, atmosphere_method how, const atmosphere_view_ray *ray,
                                double tol, double L[ATMOSPHERE_CHANNELS],
                                double S[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS], double M[ATMOSPHERE_CHANNELS]);

/* Pbar_i(mu_a, mu_b) = (1/2pi) \int_0^{2pi} p_i(mu_a mu_b + sqrt((1 - mu_a^2)(1 - mu_b^2)) cos phi) dphi. */
double atmosphere_azimuthal_phase(int species, double g, double mu_a, double mu_b);

#endif
