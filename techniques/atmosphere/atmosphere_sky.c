/* Multiple scattering along any ray and the sky's mean radiance
 * (atmosphere_scattering.h), FAST or REFERENCE. */
#include <math.h>

#include "core/sampling/quadrature.h"
#include "atmosphere/atmosphere_scattering.h"
#include "atmosphere/atmosphere_scattering_parts.h"

/* One channel of T(x, x_s) J(x_s) at distance s, for core/sampling/quadrature.h. */
typedef struct {
    const atmosphere_solution *s;
    atmosphere_method how;
    double r, mu, mu_s;
    int channel;
} ms_component;

static void ms_integrand(const atmosphere_solution *s, atmosphere_method how, double r, double mu, double mu_s,
                         double dist, double out[3])
{
    atmosphere_view_ray ray = {r, mu, mu_s, mu * mu_s, dist};
    atmosphere_view_integrands(s, how, &ray, dist, NULL, out);
}

static double ms_component_at(double dist, void *ctx)
{
    const ms_component *q = ctx;
    double v[3];
    ms_integrand(q->s, q->how, q->r, q->mu, q->mu_s, dist, v);
    return v[q->channel];
}

double atmosphere_multiple_scattering(const atmosphere_solution *s, atmosphere_method how, double r, double mu,
                                      double mu_s, double tol, double out[ATMOSPHERE_CHANNELS])
{
    double d = atmosphere_distance_to_boundary(&s->model, r, mu), worst = 0.0;
    if (how == ATMOSPHERE_FAST) {
        double x[ATMOSPHERE_RAY_NODES], w[ATMOSPHERE_RAY_NODES], v[3];
        atmosphere_ray_rule(d, x, w);
        out[0] = out[1] = out[2] = 0.0;
        for (int n = 0; n < ATMOSPHERE_RAY_NODES; ++n) {
            ms_integrand(s, how, r, mu, mu_s, x[n], v);
            for (int c = 0; c < 3; ++c)
                out[c] += w[n] * v[c];
        }
        return 0.0;
    }
    double breaks[ATMOSPHERE_RAY_BREAKS];
    atmosphere_ray_breaks(d, breaks);
    for (int c = 0; c < 3; ++c) {
        ms_component q = {s, how, r, mu, mu_s, c};
        double scale = atmosphere_single_scale(s, ATMOSPHERE_RAYLEIGH, c), err = 0.0;
        out[c] = quadrature_gk15_split(ms_component_at, &q, breaks, ATMOSPHERE_RAY_BREAKS, tol * scale, &err);
        worst = fmax(worst, scale > 0.0 ? err / scale : 0.0);
    }
    return worst;
}

/* The averaged radiance seen along mu' (single, phase-weighted, plus
 * multiple), all channels. */
static void sky_radiance(const atmosphere_solution *s, atmosphere_method how, double r, double mu, double mu_s,
                         double tol, double out[3])
{
    double S[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS], p[ATMOSPHERE_SPECIES];
    atmosphere_single_scattering(s, how, r, mu, mu_s, tol, S);
    atmosphere_multiple_scattering(s, how, r, mu, mu_s, tol, out);
    for (int i = 0; i < ATMOSPHERE_SPECIES; ++i)
        p[i] = atmosphere_azimuthal_phase(i, s->model.mie_g, mu, mu_s);
    for (int c = 0; c < 3; ++c)
        out[c] += p[ATMOSPHERE_RAYLEIGH] * S[ATMOSPHERE_RAYLEIGH][c] + p[ATMOSPHERE_MIE] * S[ATMOSPHERE_MIE][c];
}

/* [-1, 1] split at the horizon and at mu_s, sorted: 4 points. */
static void sky_breaks(const atmosphere_model *m, double r, double mu_s, double points[4])
{
    double horizon = -sqrt(fmax(0.0, 1.0 - (m->bottom_radius / r) * (m->bottom_radius / r)));
    double lo = fmin(horizon, mu_s), hi = fmax(horizon, mu_s);
    points[0] = -1.0, points[1] = fmax(-1.0, lo), points[2] = fmin(1.0, hi), points[3] = 1.0;
}

/* Composite 4-point Gauss-Legendre on `panels` equal panels of each piece
 * between the break points. */
static void sky_by_rule(const atmosphere_solution *s, atmosphere_method how, double r, double mu_s, double tol,
                        int panels, double out[3])
{
    static const double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    static const double wx[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    double points[4], v[3];
    sky_breaks(&s->model, r, mu_s, points);
    out[0] = out[1] = out[2] = 0.0;
    for (int piece = 0; piece < 3; ++piece)
        for (int panel = 0; panel < panels; ++panel) {
            double width = (points[piece + 1] - points[piece]) / panels, half = 0.5 * width;
            double centre = points[piece] + panel * width + half;
            for (int j = 0; j < 4 && half > 0.0; ++j) {
                sky_radiance(s, how, r, centre + half * x[j], mu_s, tol, v);
                for (int c = 0; c < 3; ++c)
                    out[c] += 0.5 * half * wx[j] * v[c];
            }
        }
}

/* FAST: 8 panels a piece. Otherwise 32 panels a piece, the error estimate
 * being the difference from 16; the inner integrals (one view ray per
 * node) REFERENCE at `tol` for REFERENCE, FAST for ADAPTIVE (their own error
 * is the in-scatter's, measured there). */
double atmosphere_sky_mean_radiance(const atmosphere_solution *s, atmosphere_method how, double r, double mu_s,
                                    double tol, double out[ATMOSPHERE_CHANNELS])
{
    if (how == ATMOSPHERE_FAST) {
        sky_by_rule(s, how, r, mu_s, 0.0, 8, out);
        return 0.0;
    }
    double coarse[3], worst = 0.0;
    atmosphere_method inner = how == ATMOSPHERE_REFERENCE ? ATMOSPHERE_REFERENCE : ATMOSPHERE_FAST;
    sky_by_rule(s, inner, r, mu_s, tol, 32, out);
    sky_by_rule(s, inner, r, mu_s, tol, 16, coarse);
    for (int c = 0; c < 3; ++c) {
        double scale = atmosphere_single_scale(s, ATMOSPHERE_RAYLEIGH, c) / (4.0 * 3.141592653589793);
        worst = fmax(worst, scale > 0.0 ? fabs(out[c] - coarse[c]) / scale : 0.0);
    }
    return worst;
}
