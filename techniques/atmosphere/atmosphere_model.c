/* The atmosphere's parameters, weathers, geometry and optical depth; see
 * atmosphere_model.h for the model and its sources. */
#include "atmosphere/atmosphere_model.h"

#include <math.h>
#include <stdio.h>

#include "core/sampling/quadrature.h"

atmosphere_weather atmosphere_weather_clear(void)
{
    return (atmosphere_weather){.rayleigh_scattering = {5.802e-6, 13.558e-6, 33.1e-6},
                                .rayleigh_scale_height = 8000.0,
                                .mie_scattering = {3.996e-6, 3.996e-6, 3.996e-6},
                                .mie_extinction = {4.440e-6, 4.440e-6, 4.440e-6},
                                .mie_scale_height = 1200.0};
}

atmosphere_weather atmosphere_weather_dense_fog(void)
{
    atmosphere_weather w = atmosphere_weather_clear();
    for (int c = 0; c < ATMOSPHERE_CHANNELS; ++c)
        w.mie_scattering[c] *= 50.0, w.mie_extinction[c] *= 50.0;
    w.mie_scale_height = 600.0;
    return w;
}

atmosphere_model atmosphere_model_default(void)
{
    return (atmosphere_model){.bottom_radius = 6360e3,
                              .top_radius = 6420e3,
                              .solar_irradiance = {1.474, 1.8504, 1.91198},
                              .sun_angular_radius = 0.004675,
                              .mie_g = 0.8,
                              .weathers = {atmosphere_weather_clear(), atmosphere_weather_dense_fog()}};
}

static int bad(char *msg, size_t size, const char *what)
{
    snprintf(msg, size, "atmosphere model: %s", what);
    return -1;
}

static int weather_check(const atmosphere_weather *w, char *msg, size_t size)
{
    if (!(w->rayleigh_scale_height > 0.0) || !(w->mie_scale_height > 0.0) || !isfinite(w->rayleigh_scale_height) ||
        !isfinite(w->mie_scale_height))
        return bad(msg, size, "scale heights must be positive and finite");
    for (int c = 0; c < ATMOSPHERE_CHANNELS; ++c) {
        double rs = w->rayleigh_scattering[c], ms = w->mie_scattering[c], me = w->mie_extinction[c];
        if (!(rs >= 0.0 && ms >= 0.0 && me >= ms) || !isfinite(rs) || !isfinite(me))
            return bad(msg, size, "coefficients must be finite, >= 0, and Mie extinction >= Mie scattering");
    }
    return 0;
}

int atmosphere_model_check(const atmosphere_model *m, char *msg, size_t size)
{
    if (!(m->bottom_radius > 0.0 && m->top_radius > m->bottom_radius) || !isfinite(m->top_radius))
        return bad(msg, size, "radii must satisfy 0 < bottom < top < infinity");
    if (!(fabs(m->mie_g) < 1.0))
        return bad(msg, size, "Mie asymmetry g must be in (-1, 1)");
    if (!(m->sun_angular_radius >= 0.0 && m->sun_angular_radius < 0.5))
        return bad(msg, size, "sun angular radius must be in [0, 0.5) rad");
    for (int c = 0; c < ATMOSPHERE_CHANNELS; ++c)
        if (!(m->solar_irradiance[c] >= 0.0) || !isfinite(m->solar_irradiance[c]))
            return bad(msg, size, "solar irradiance must be finite and >= 0");
    for (int w = 0; w < ATMOSPHERE_WEATHERS; ++w)
        if (weather_check(&m->weathers[w], msg, size) != 0)
            return -1;
    return 0;
}

atmosphere_coefficients atmosphere_coefficients_at(const atmosphere_model *m, double t, double altitude)
{
    atmosphere_coefficients k = {{{0}}, {0}};
    double weight[ATMOSPHERE_WEATHERS] = {1.0 - t, t};
    for (int w = 0; w < ATMOSPHERE_WEATHERS; ++w) {
        const atmosphere_weather *x = &m->weathers[w];
        double rho_r = weight[w] * exp(-altitude / x->rayleigh_scale_height);
        double rho_m = weight[w] * exp(-altitude / x->mie_scale_height);
        for (int c = 0; c < ATMOSPHERE_CHANNELS; ++c) {
            k.scattering[ATMOSPHERE_RAYLEIGH][c] += rho_r * x->rayleigh_scattering[c];
            k.scattering[ATMOSPHERE_MIE][c] += rho_m * x->mie_scattering[c];
            k.extinction[c] += rho_r * x->rayleigh_scattering[c] + rho_m * x->mie_extinction[c];
        }
    }
    return k;
}

double atmosphere_distance_to_top(const atmosphere_model *m, double r, double mu)
{
    double disc = r * r * (mu * mu - 1.0) + m->top_radius * m->top_radius;
    return fmax(0.0, -r * mu + sqrt(fmax(0.0, disc)));
}

double atmosphere_distance_to_ground(const atmosphere_model *m, double r, double mu)
{
    double disc = r * r * (mu * mu - 1.0) + m->bottom_radius * m->bottom_radius;
    return fmax(0.0, -r * mu - sqrt(fmax(0.0, disc)));
}

int atmosphere_ray_hits_ground(const atmosphere_model *m, double r, double mu)
{
    return mu < 0.0 && r * r * (mu * mu - 1.0) + m->bottom_radius * m->bottom_radius >= 0.0;
}

double atmosphere_distance_to_boundary(const atmosphere_model *m, double r, double mu)
{
    return atmosphere_ray_hits_ground(m, r, mu) ? atmosphere_distance_to_ground(m, r, mu)
                                                : atmosphere_distance_to_top(m, r, mu);
}

double atmosphere_radius_at(double r, double mu, double d)
{
    return sqrt(fmax(0.0, d * d + 2.0 * r * mu * d + r * r));
}

/* exp(-h / H) at distance s along the ray: the integrand of a column. */
typedef struct {
    double r, mu, bottom, scale_height;
} column_ray;

static double column_density(double s, void *ctx)
{
    const column_ray *q = ctx;
    return exp(-(atmosphere_radius_at(q->r, q->mu, s) - q->bottom) / q->scale_height);
}

/* \int_0^d exp(-h(s) / H) ds, split at the closest approach s = -r mu. */
static double column(const atmosphere_model *m, double r, double mu, double d, double scale_height, double tol,
                     double *error)
{
    column_ray q = {r, mu, m->bottom_radius, scale_height};
    double points[3] = {0.0, -r * mu, d};
    if (!(points[1] > 0.0 && points[1] < d))
        return quadrature_gk15(column_density, &q, 0.0, d, tol * scale_height, error);
    return quadrature_gk15_split(column_density, &q, points, 3, tol * scale_height, error);
}

void atmosphere_optical_depth(const atmosphere_model *m, double t, double r, double mu, double d, double tol,
                              double tau[ATMOSPHERE_CHANNELS], double *error)
{
    double weight[ATMOSPHERE_WEATHERS] = {1.0 - t, t}, err_tau[ATMOSPHERE_CHANNELS] = {0};
    for (int c = 0; c < ATMOSPHERE_CHANNELS; ++c)
        tau[c] = 0.0;
    for (int w = 0; w < ATMOSPHERE_WEATHERS; ++w) {
        const atmosphere_weather *x = &m->weathers[w];
        if (weight[w] == 0.0)
            continue;
        double er, em, cr = column(m, r, mu, d, x->rayleigh_scale_height, tol, &er);
        double cm = column(m, r, mu, d, x->mie_scale_height, tol, &em);
        for (int c = 0; c < ATMOSPHERE_CHANNELS; ++c) {
            tau[c] += weight[w] * (x->rayleigh_scattering[c] * cr + x->mie_extinction[c] * cm);
            err_tau[c] += weight[w] * (x->rayleigh_scattering[c] * er + x->mie_extinction[c] * em);
        }
    }
    if (error)
        *error = fmax(err_tau[0], fmax(err_tau[1], err_tau[2]));
}

/* Bruneton 2017 GetTransmittanceToSun: the disc's fraction above the
 * horizon, whose cosine at r is -sqrt(1 - (R_b / r)^2). */
double atmosphere_sun_visibility(const atmosphere_model *m, double r, double mu_s)
{
    double sin_h = m->bottom_radius / r, cos_h = -sqrt(fmax(0.0, 1.0 - sin_h * sin_h));
    double a = m->sun_angular_radius * sin_h;
    if (a <= 0.0)
        return mu_s >= cos_h ? 1.0 : 0.0;
    double x = fmin(1.0, fmax(0.0, (mu_s - cos_h + a) / (2.0 * a)));
    return x * x * (3.0 - 2.0 * x);
}
