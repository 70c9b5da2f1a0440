/* The transmittance grid of atmosphere_scattering.h (Bruneton 2017's
 * transmittance texture and its parametrisation, in optical depth) and the
 * transmittance of a segment and to the sun, by grid or by quadrature. */
#include <math.h>

#include "atmosphere/atmosphere_scattering.h"
#include "atmosphere/atmosphere_scattering_parts.h"

static const double GRID_TOLERANCE = 1e-9;
static const double DIRECT_TOLERANCE = 1e-10;

/* Grid point (i along mu, j along r) -> (r, mu) (Bruneton 2017,
 * GetRMuFromTransmittanceTextureUv). */
static void grid_point(const atmosphere_model *m, int i, int j, double *r, double *mu)
{
    double H = sqrt(m->top_radius * m->top_radius - m->bottom_radius * m->bottom_radius);
    double rho = H * j / (ATMOSPHERE_T_R - 1.0), x_mu = i / (ATMOSPHERE_T_MU - 1.0);
    *r = sqrt(rho * rho + m->bottom_radius * m->bottom_radius);
    double d_min = m->top_radius - *r, d_max = rho + H, d = d_min + x_mu * (d_max - d_min);
    *mu = d == 0.0 ? 1.0 : (H * H - rho * rho - d * d) / (2.0 * *r * d);
    *mu = fmax(-1.0, fmin(1.0, *mu));
}

void atmosphere_transmittance_grid_fill(atmosphere_solution *s, int threads)
{
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
    for (int k = 0; k < ATMOSPHERE_T_R * ATMOSPHERE_T_MU; ++k) {
        double r, mu;
        grid_point(&s->model, k % ATMOSPHERE_T_MU, k / ATMOSPHERE_T_MU, &r, &mu);
        double d = atmosphere_distance_to_top(&s->model, r, mu);
        atmosphere_optical_depth(&s->model, s->t, r, mu, d, GRID_TOLERANCE, s->tau_top + 3 * k, NULL);
    }
}

/* Bilinear optical depth to the top of the ray (r, mu), which must not hit
 * the ground (GetTransmittanceTextureUvFromRMu, clamped to the grid). */
static void tau_to_top(const atmosphere_solution *s, double r, double mu, double tau[3])
{
    const atmosphere_model *m = &s->model;
    double H = sqrt(m->top_radius * m->top_radius - m->bottom_radius * m->bottom_radius);
    double rho = sqrt(fmax(0.0, r * r - m->bottom_radius * m->bottom_radius));
    double d = atmosphere_distance_to_top(m, r, mu), d_min = m->top_radius - r, d_max = rho + H;
    double x_mu = d_max > d_min ? (d - d_min) / (d_max - d_min) : 0.0;
    atmosphere_grid_axis a = atmosphere_grid_axis_at(x_mu * (ATMOSPHERE_T_MU - 1), ATMOSPHERE_T_MU);
    atmosphere_grid_axis b = atmosphere_grid_axis_at(rho / H * (ATMOSPHERE_T_R - 1), ATMOSPHERE_T_R);
    for (int c = 0; c < 3; ++c) {
        const double *g = s->tau_top + c;
        double lo = (1 - a.w) * g[3 * (b.i0 * ATMOSPHERE_T_MU + a.i0)] + a.w * g[3 * (b.i0 * ATMOSPHERE_T_MU + a.i1)];
        double hi = (1 - a.w) * g[3 * (b.i1 * ATMOSPHERE_T_MU + a.i0)] + a.w * g[3 * (b.i1 * ATMOSPHERE_T_MU + a.i1)];
        tau[c] = (1 - b.w) * lo + b.w * hi;
    }
}

/* Bruneton 2017 GetTransmittance: the segment's optical depth as the
 * difference of two rays' to the top (reversed when the ray hits the
 * ground, so neither of them does). */
static void segment_tau_by_grid(const atmosphere_solution *s, double r, double mu, double d, double tau[3])
{
    double r_d = atmosphere_radius_at(r, mu, d), mu_d = fmax(-1.0, fmin(1.0, (r * mu + d) / r_d));
    double a[3], b[3];
    int ground = atmosphere_ray_hits_ground(&s->model, r, mu);
    tau_to_top(s, r_d, ground ? -mu_d : mu_d, b);
    tau_to_top(s, r, ground ? -mu : mu, a);
    for (int c = 0; c < 3; ++c)
        tau[c] = fmax(0.0, ground ? b[c] - a[c] : a[c] - b[c]);
}

void atmosphere_transmittance(const atmosphere_solution *s, atmosphere_method how, double r, double mu, double d,
                              double T[ATMOSPHERE_CHANNELS])
{
    double tau[3];
    if (how != ATMOSPHERE_REFERENCE)
        segment_tau_by_grid(s, r, mu, d, tau);
    else
        atmosphere_optical_depth(&s->model, s->t, r, mu, d, DIRECT_TOLERANCE, tau, NULL);
    for (int c = 0; c < 3; ++c)
        T[c] = exp(-tau[c]);
}

void atmosphere_transmittance_to_sun(const atmosphere_solution *s, atmosphere_method how, double r, double mu_s,
                                     double T[ATMOSPHERE_CHANNELS])
{
    const atmosphere_model *m = &s->model;
    double visible = atmosphere_sun_visibility(m, r, mu_s), tau[3] = {0, 0, 0};
    double horizon = -sqrt(fmax(0.0, 1.0 - (m->bottom_radius / r) * (m->bottom_radius / r)));
    double mu = fmax(mu_s, horizon + 1e-12);
    if (visible > 0.0 && how != ATMOSPHERE_REFERENCE)
        tau_to_top(s, r, mu, tau);
    else if (visible > 0.0)
        atmosphere_optical_depth(m, s->t, r, mu, atmosphere_distance_to_top(m, r, mu), DIRECT_TOLERANCE, tau, NULL);
    for (int c = 0; c < 3; ++c)
        T[c] = visible * exp(-tau[c]);
}
