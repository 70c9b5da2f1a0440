/* Internals shared by the atmosphere_*.c files behind
 * atmosphere/atmosphere_scattering.h: grid axes, the internal multiple-scattering
 * grid's coordinates, the fixed ray rule and the integrands. */
#ifndef GTLAB_ATMOSPHERE_SCATTERING_PARTS_H
#define GTLAB_ATMOSPHERE_SCATTERING_PARTS_H

#include "atmosphere/atmosphere_scattering.h"

/* Linear interpolation along one axis at position x (grid units, clamped to
 * [0, n - 1]): the two points and the weight of the second. */
typedef struct {
    int i0, i1;
    double w;
} atmosphere_grid_axis;
static inline atmosphere_grid_axis atmosphere_grid_axis_at(double x, int n)
{
    x = x > 0.0 ? (x < n - 1.0 ? x : n - 1.0) : 0.0; /* NaN: 0 */
    int i0 = (int)x; /* x >= 0: truncation is floor */
    atmosphere_grid_axis a = {i0, i0 + 1 < n ? i0 + 1 : i0, x - i0};
    return a;
}

void atmosphere_transmittance_grid_fill(atmosphere_solution *s, int threads);

/* The multiple-scattering grid (atmosphere_ms_grid.c): radius of row k, mu
 * of cell a, mu_s of column m, and the grid position (fractional indices) of
 * a point. */
double atmosphere_ms_radius(const atmosphere_model *m, int k);
double atmosphere_ms_mu(int a);
double atmosphere_ms_mu_s(int m);
size_t atmosphere_ms_index(int k, int a, int m);
/* Trilinear value of a grid field (3 channels) at (r, mu, mu_s). */
void atmosphere_ms_lookup(const atmosphere_model *m, const double *field, double r, double mu, double mu_s,
                          double out[3]);

/* The fixed ray rule: ATMOSPHERE_RAY_NODES distances and weights on [0, d],
 * and the break points (ATMOSPHERE_RAY_BREAKS) the adaptive rule splits at. */
enum { ATMOSPHERE_RAY_PANELS = 12, ATMOSPHERE_RAY_NODES = 4 * ATMOSPHERE_RAY_PANELS };
enum { ATMOSPHERE_RAY_BREAKS = ATMOSPHERE_RAY_PANELS + 1 };
void atmosphere_ray_breaks(double d, double breaks[ATMOSPHERE_RAY_BREAKS]);
void atmosphere_ray_rule(double d, double s[ATMOSPHERE_RAY_NODES], double w[ATMOSPHERE_RAY_NODES]);

/* The single-scattering integrand E_sun T(x, x_s) beta_s^i(x_s) T_sun(x_s)
 * at distance s along (r, mu) with the sun at mu_s (nu = mu mu_s). */
void atmosphere_single_integrand(const atmosphere_solution *s, atmosphere_method how, double r, double mu,
                                 double mu_s, double dist, double out[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS]);
/* The scale E_sun,c beta_s^i,c(0) H_i of S_i (tolerances are relative to it). */
double atmosphere_single_scale(const atmosphere_solution *s, int species, int c);

/* Fills s->density (orders 2..ATMOSPHERE_ORDERS) and s->order_mean. */
int atmosphere_multiple_scattering_solve(atmosphere_solution *s, int threads);

#endif
