/* The exponential height fog; see height_fog_medium.h for the formulas. */
#include "core/optics/height_fog_medium.h"

#include <math.h>
#include <string.h>

#include "core/optics/phase_function.h"

height_fog_param height_fog_param_default(void)
{
    const double s = sqrt(0.5);
    height_fog_param p = {
        .beta_rs = {5.802e-6, 13.558e-6, 33.1e-6}, /* Bruneton 2017 */
        .beta_ms = 2.0e-5,
        .beta_ma = 2.2e-6,
        .mie_g = 0.76,
        .scale_height = 1000.0,
        .albedo_r = {1.0, 1.0, 1.0},
        .albedo_m = {1.0, 1.0, 1.0},
        .sun_color = {1.0, 1.0, 1.0},
        .amb_color = {0.2, 0.2, 0.2},
        .sun_direction = {0.0f, (float)s, (float)s},
        .floor_y = -INFINITY,
    };
    return p;
}

int height_fog_weather(const char *name, double elevation_deg, height_fog_param *p)
{
    *p = height_fog_param_default();
    if (strcmp(name, "dense") == 0) {
        p->scale_height = 150.0;
        p->beta_ms = 2e-3;
        p->beta_ma = 1e-4;
        p->mie_g = 0.6;
        for (int c = 0; c < 3; ++c)
            p->sun_color[c] = 0.8, p->amb_color[c] = 0.4;
    } else if (strcmp(name, "sunny") != 0) {
        return -1;
    }
    double e = elevation_deg * M_PI / 180.0, a = 35.0 * M_PI / 180.0;
    p->sun_direction = v3((float)(cos(e) * sin(a)), (float)sin(e), (float)(cos(e) * cos(a)));
    return 0;
}

/* 0 when every value is a number >= 0, else -1 naming it. */
static int check_non_negative(const double *v, int n, const char *name, const char *subject, gt_error *e)
{
    for (int i = 0; i < n; ++i)
        if (!(v[i] >= 0.0) || isinf(v[i]))
            return gt_error_set(e, subject, "%s must be a finite number >= 0 (got %g)", name, v[i]);
    return 0;
}

int height_fog_param_validate(const height_fog_param *p, const char *subject, gt_error *e)
{
    if (check_non_negative(p->beta_rs, 3, "the Rayleigh scattering coefficient", subject, e) ||
        check_non_negative(&p->beta_ms, 1, "the Mie scattering coefficient", subject, e) ||
        check_non_negative(&p->beta_ma, 1, "the Mie absorption coefficient", subject, e) ||
        check_non_negative(p->albedo_r, 3, "the Rayleigh albedo control", subject, e) ||
        check_non_negative(p->albedo_m, 3, "the Mie albedo control", subject, e) ||
        check_non_negative(p->sun_color, 3, "the sun colour", subject, e) ||
        check_non_negative(p->amb_color, 3, "the ambient colour", subject, e))
        return -1;
    if (!(p->scale_height > 0.0))
        return gt_error_set(e, subject, "the scale height must be > 0 m (got %g)", p->scale_height);
    if (!(fabs(p->mie_g) < 1.0))
        return gt_error_set(e, subject, "the Mie asymmetry g must be in (-1, 1) (got %g)", p->mie_g);
    if (!v3_is_finite(p->sun_direction) || fabsf(v3_length(p->sun_direction) - 1.0f) > 1e-3f)
        return gt_error_set(e, subject, "the sun direction must be a unit vector");
    if (isnan(p->floor_y) || p->floor_y == INFINITY)
        return gt_error_set(e, subject, "the fog floor must be a number or -infinity");
    return 0;
}

double height_fog_density(const height_fog_param *p, double y)
{
    return y >= p->floor_y ? exp(-y / p->scale_height) : 0.0;
}

double height_fog_mean_factor(double x)
{
    return x > 0.0 ? -expm1(-x) / x : 1.0; /* expm1 keeps every digit as x -> 0 */
}

double height_fog_segment_density(const height_fog_param *p, double y0, double y1, double d)
{
    double low = fmin(y0, y1), high = fmax(y0, y1);
    if (high < p->floor_y || !(d > 0.0))
        return 0.0;
    if (low < p->floor_y) { /* keep the part above the floor */
        d *= (high - p->floor_y) / (high - low);
        low = p->floor_y;
    }
    return d * exp(-low / p->scale_height) * height_fog_mean_factor((high - low) / p->scale_height);
}

/* The distance at which the integral of exp(-y/H) from y0 (no floor)
 * reaches D; see the header. */
static double distance_unbounded(double y0, double dir_y, double h, double d_int)
{
    double k = dir_y / h, e = y0 / h;
    if (k < 0.0 && e > 600.0) /* exp(e) would overflow: log1p(x) = log(x) there */
        return (log(-k * d_int) + e) / -k;
    double scaled = d_int * exp(e), a = k * scaled;
    if (a >= 1.0)
        return INFINITY;
    double g = fabs(a) > 1e-300 ? -log1p(-a) / a : 1.0;
    return scaled * g;
}

double height_fog_distance_at(const height_fog_param *p, double y0, double dir_y, double density_integral)
{
    double skipped = 0.0;
    if (y0 < p->floor_y) { /* below the fog: reach its floor first */
        if (!(dir_y > 0.0))
            return INFINITY;
        skipped = (p->floor_y - y0) / dir_y;
        y0 = p->floor_y;
    } else if (dir_y < 0.0 && p->floor_y > -INFINITY) {
        double to_floor = (p->floor_y - y0) / dir_y;
        if (density_integral > height_fog_segment_density(p, y0, p->floor_y, to_floor))
            return INFINITY;
    }
    return skipped + distance_unbounded(y0, dir_y, p->scale_height, density_integral);
}

void height_fog_extinction(const height_fog_param *p, double beta_t[3])
{
    for (int c = 0; c < 3; ++c)
        beta_t[c] = p->beta_rs[c] + p->beta_ms + p->beta_ma;
}

void height_fog_scattering(const height_fog_param *p, double beta_s[3])
{
    for (int c = 0; c < 3; ++c)
        beta_s[c] = p->beta_rs[c] + p->beta_ms;
}

void height_fog_sun_scattering(const height_fog_param *p, double mu, double s[3])
{
    double pr = rayleigh_phase(mu), pm = henyey_greenstein_phase(mu, p->mie_g);
    for (int c = 0; c < 3; ++c)
        s[c] = p->albedo_r[c] * p->beta_rs[c] * pr + p->albedo_m[c] * p->beta_ms * pm;
}

void height_fog_sun_transmittance(const height_fog_param *p, double y, double t[3])
{
    double beta_t[3], sin_elevation = p->sun_direction.y;
    height_fog_extinction(p, beta_t);
    double column = p->scale_height * exp(-fmax(y, p->floor_y) / p->scale_height);
    for (int c = 0; c < 3; ++c) {
        if (beta_t[c] == 0.0)
            t[c] = 1.0;
        else
            t[c] = sin_elevation > 0.0 ? exp(-beta_t[c] * column / sin_elevation) : 0.0;
    }
}
