/* Single scattering of atmosphere_scattering.h (Bruneton 2017,
 * ComputeSingleScatteringIntegrand without the phase) and the ray rules. */
#include <math.h>

#include "core/sampling/quadrature.h"
#include "atmosphere/atmosphere_scattering.h"
#include "atmosphere/atmosphere_scattering_parts.h"

/* d 4^-k and d (1 - 4^-k) for k = 1..5, d / 2, and the ends. */
void atmosphere_ray_breaks(double d, double breaks[ATMOSPHERE_RAY_BREAKS])
{
    breaks[0] = 0.0, breaks[6] = 0.5 * d, breaks[12] = d;
    for (int k = 1; k <= 5; ++k) {
        double f = pow(0.25, k);
        breaks[6 - k] = f * d, breaks[6 + k] = (1.0 - f) * d;
    }
}

void atmosphere_ray_rule(double d, double s[ATMOSPHERE_RAY_NODES], double w[ATMOSPHERE_RAY_NODES])
{
    static const double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    static const double wx[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    double b[ATMOSPHERE_RAY_BREAKS];
    atmosphere_ray_breaks(d, b);
    for (int p = 0; p < ATMOSPHERE_RAY_PANELS; ++p) {
        double centre = 0.5 * (b[p] + b[p + 1]), half = 0.5 * (b[p + 1] - b[p]);
        for (int j = 0; j < 4; ++j)
            s[4 * p + j] = centre + half * x[j], w[4 * p + j] = half * wx[j];
    }
}

void atmosphere_view_integrands(const atmosphere_solution *s, atmosphere_method how, const atmosphere_view_ray *ray,
                                double dist, double single[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS],
                                double multiple[ATMOSPHERE_CHANNELS])
{
    const atmosphere_model *m = &s->model;
    double r_s = atmosphere_radius_at(ray->r, ray->mu, dist);
    double mu_s_at = fmax(-1.0, fmin(1.0, (ray->r * ray->mu_s + dist * ray->nu) / r_s)), view[3], sun[3], J[3];
    atmosphere_transmittance(s, how, ray->r, ray->mu, dist, view);
    if (multiple) {
        double mu_at = fmax(-1.0, fmin(1.0, (ray->r * ray->mu + dist) / r_s));
        atmosphere_ms_lookup(m, s->density, r_s, mu_at, mu_s_at, J);
        for (int c = 0; c < 3; ++c)
            multiple[c] = view[c] * J[c];
    }
    if (!single)
        return;
    atmosphere_transmittance_to_sun(s, how, r_s, mu_s_at, sun);
    atmosphere_coefficients k = atmosphere_coefficients_at(m, s->t, r_s - m->bottom_radius);
    for (int i = 0; i < ATMOSPHERE_SPECIES; ++i)
        for (int c = 0; c < 3; ++c)
            single[i][c] = m->solar_irradiance[c] * view[c] * sun[c] * k.scattering[i][c];
}

void atmosphere_single_integrand(const atmosphere_solution *s, atmosphere_method how, double r, double mu,
                                 double mu_s, double dist, double out[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS])
{
    atmosphere_view_ray ray = {r, mu, mu_s, mu * mu_s, dist};
    atmosphere_view_integrands(s, how, &ray, dist, out, NULL);
}

double atmosphere_single_scale(const atmosphere_solution *s, int species, int c)
{
    const atmosphere_model *m = &s->model;
    atmosphere_coefficients k = atmosphere_coefficients_at(m, s->t, 0.0);
    double h = 0.0, weight[2] = {1.0 - s->t, s->t};
    for (int w = 0; w < ATMOSPHERE_WEATHERS; ++w)
        h += weight[w] * (species == ATMOSPHERE_RAYLEIGH ? m->weathers[w].rayleigh_scale_height
                                                         : m->weathers[w].mie_scale_height);
    return m->solar_irradiance[c] * k.scattering[species][c] * h;
}

/* One component (species i, channel c) of the integrand, for core/sampling/quadrature.h. */
typedef struct {
    const atmosphere_solution *s;
    atmosphere_method how;
    double r, mu, mu_s;
    int species, channel;
} single_component;

static double single_component_at(double dist, void *ctx)
{
    const single_component *q = ctx;
    double v[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS];
    atmosphere_single_integrand(q->s, q->how, q->r, q->mu, q->mu_s, dist, v);
    return v[q->species][q->channel];
}

/* The fixed rule's sum. */
static void single_by_rule(const atmosphere_solution *s, double r, double mu, double mu_s,
                           double out[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS])
{
    double x[ATMOSPHERE_RAY_NODES], w[ATMOSPHERE_RAY_NODES];
    atmosphere_ray_rule(atmosphere_distance_to_boundary(&s->model, r, mu), x, w);
    for (int i = 0; i < ATMOSPHERE_SPECIES; ++i)
        for (int c = 0; c < 3; ++c)
            out[i][c] = 0.0;
    for (int n = 0; n < ATMOSPHERE_RAY_NODES; ++n) {
        double v[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS];
        atmosphere_single_integrand(s, ATMOSPHERE_FAST, r, mu, mu_s, x[n], v);
        for (int i = 0; i < ATMOSPHERE_SPECIES; ++i)
            for (int c = 0; c < 3; ++c)
                out[i][c] += w[n] * v[i][c];
    }
}

double atmosphere_single_scattering(const atmosphere_solution *s, atmosphere_method how, double r, double mu,
                                    double mu_s, double tol, double out[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS])
{
    if (how == ATMOSPHERE_FAST) {
        single_by_rule(s, r, mu, mu_s, out);
        return 0.0;
    }
    double breaks[ATMOSPHERE_RAY_BREAKS], worst = 0.0;
    atmosphere_ray_breaks(atmosphere_distance_to_boundary(&s->model, r, mu), breaks);
    for (int i = 0; i < ATMOSPHERE_SPECIES; ++i)
        for (int c = 0; c < 3; ++c) {
            single_component q = {s, how, r, mu, mu_s, i, c};
            double scale = atmosphere_single_scale(s, i, c), err = 0.0;
            out[i][c] = quadrature_gk15_split(single_component_at, &q, breaks, ATMOSPHERE_RAY_BREAKS, tol * scale,
                                              &err);
            worst = fmax(worst, scale > 0.0 ? err / scale : 0.0);
        }
    return worst;
}
