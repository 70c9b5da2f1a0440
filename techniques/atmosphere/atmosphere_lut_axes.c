/* The atmosphere LUTs' axes under three parametrizations; see the header. */
#include "atmosphere/atmosphere_lut_axes.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PI 3.14159265358979323846

static const double SUN_SCALE = 1.1, SUN_END = 1.26, SUN_OFFSET = 0.74; /* 1 - 0.26 */
static const double YUSOV_VIEW_POWER = 0.2, YUSOV_HEIGHT_POWER = 0.5, YUSOV_HORIZON_GAP = 1e-4;
static const double BRUNETON_HORIZON_GAP = 1e-3, BRUNETON_FAR = 0.999;

const char *atmosphere_lut_parametrization_name(atmosphere_lut_parametrization kind)
{
    return kind == ATMOSPHERE_PARAM_YUSOV ? "Yusov 2013" : kind == ATMOSPHERE_PARAM_BRUNETON ? "Bruneton & Neyret 2008"
                                                                                             : "linear";
}

const char *atmosphere_lut_parametrization_tag(atmosphere_lut_parametrization kind)
{
    return kind == ATMOSPHERE_PARAM_YUSOV ? "yusov2013" : kind == ATMOSPHERE_PARAM_BRUNETON ? "bruneton2008" : "linear";
}

int atmosphere_lut_parametrization_from_tag(const char *tag)
{
    for (int k = 0; k < ATMOSPHERE_PARAMS; ++k)
        if (tag && strcmp(tag, atmosphere_lut_parametrization_tag((atmosphere_lut_parametrization)k)) == 0)
            return k;
    return -1;
}

/* The header's definitions, restated for a reader of the files (grid point i of n, u = i / (n - 1)). */
const char *atmosphere_lut_axes_description(atmosphere_lut_parametrization kind)
{
    if (kind == ATMOSPHERE_PARAM_YUSOV)
        return "axes (Yusov 2013, the talk's [Yus13], without the sun-view axis; grid point i of n at u = i / (n - "
               "1)): y: u = ((h - 16 m) / (y_max - 32 m))^0.5, h = y clamped to [16 m, y_max - 16 m]; theta_v: split at "
               "the horizon's zenith cosine c_h = -sqrt(h (2 R + h)) / (R + h), points n/2..n-1 above it at "
               "((mu - c_h) / (1 - c_h))^0.2 of their half (horizon at n/2, zenith at n-1), points 0..n/2-1 below "
               "it at ((c_h - mu) / (c_h + 1))^0.2 (horizon at 0, nadir at n/2-1), mu kept 1e-4 off the horizon, "
               "no filtering across it; theta_s: u = (atan(max(mu_s, -0.1975) tan(1.386)) / 1.1 + 0.74) / 2; "
               "t: u = t in [0, 1] (0 clear, 1 dense fog)";
    if (kind == ATMOSPHERE_PARAM_BRUNETON)
        return "axes (Bruneton & Neyret 2008; grid point i of n at u = i / (n - 1)): y: u = rho / rho_max, rho = "
               "sqrt(r^2 - R^2), rho_max at r = R + y_max, the lowest point at y = 10 m; theta_v: split at the "
               "horizon, rays to the ground (d their distance to it) on points 0..n/2-1 at (n/2 - 1)(1 - d / rho), "
               "others (d to the top R_t, H = sqrt(R_t^2 - R^2)) on points n/2..n-1 at n/2 + (n/2 - 1) d / (rho + "
               "H), d clamped to [r - R, 0.999 rho] and [R_t - r, 0.999 (rho + H)]; theta_s: u = (atan(max(mu_s, "
               "-0.1975) tan(1.386)) / 1.1 + 0.74) / 2; t: u = t in [0, 1] (0 clear, 1 dense fog)";
    return "axes (linear) with grid points at both ends: theta_s in [0, 96 deg], theta_v in [0, 180 deg], y in [0, "
           "y_max] m, t in [0, 1] (0 clear, 1 dense fog)";
}

static double clamp(double x, double lo, double hi) { return fmin(fmax(x, lo), hi); }

double atmosphere_lut_sun_unit(double mu_s)
{
    return 0.5 * (atan(fmax(mu_s, ATMOSPHERE_LUT_MU_S_MIN) * tan(SUN_END * SUN_SCALE)) / SUN_SCALE + SUN_OFFSET);
}

double atmosphere_lut_sun_from_unit(double u)
{
    return clamp(tan((2.0 * u - SUN_OFFSET) * SUN_SCALE) / tan(SUN_END * SUN_SCALE), -1.0, 1.0);
}

double atmosphere_lut_horizon_cosine(double h, double bottom_radius)
{
    h = fmax(h, 0.0);
    return -sqrt(h * (2.0 * bottom_radius + h)) / (bottom_radius + h);
}

double atmosphere_lut_theta_s_max(atmosphere_lut_parametrization kind)
{
    return kind == ATMOSPHERE_PARAM_LINEAR ? ATMOSPHERE_LUT_LINEAR_THETA_S_MAX : acos(ATMOSPHERE_LUT_MU_S_MIN);
}

/* A whole axis of n points at unit coordinate u in [0, 1]. */
static atmosphere_lut_position whole(double u, int n)
{
    return (atmosphere_lut_position){clamp(u, 0.0, 1.0) * (n - 1), 0, n - 1};
}

/* Half `upper` of an axis of n points at fraction f in [0, 1] of it. */
static atmosphere_lut_position half(int upper, double f, int n)
{
    int m = n / 2;
    return upper ? (atmosphere_lut_position){m + clamp(f, 0.0, 1.0) * (m - 1), m, n - 1}
                 : (atmosphere_lut_position){clamp(f, 0.0, 1.0) * (m - 1), 0, m - 1};
}

/* Yusov's clamped height. */
static double yusov_height(const atmosphere_lut_frame *f, double y)
{
    return clamp(y, ATMOSPHERE_LUT_YUSOV_MARGIN, f->max_altitude - ATMOSPHERE_LUT_YUSOV_MARGIN);
}

static double rho_of(const atmosphere_lut_frame *f, double r)
{
    return sqrt(fmax(r * r - f->bottom_radius * f->bottom_radius, 0.0));
}

static double top_h(const atmosphere_lut_frame *f)
{
    return sqrt(f->top_radius * f->top_radius - f->bottom_radius * f->bottom_radius);
}

static double altitude_unit(const atmosphere_lut_frame *f, double y)
{
    if (f->kind == ATMOSPHERE_PARAM_YUSOV) {
        double m = ATMOSPHERE_LUT_YUSOV_MARGIN;
        return pow(clamp((yusov_height(f, y) - m) / (f->max_altitude - 2.0 * m), 0.0, 1.0), YUSOV_HEIGHT_POWER);
    }
    if (f->kind == ATMOSPHERE_PARAM_BRUNETON)
        return rho_of(f, f->bottom_radius + clamp(y, 0.0, f->max_altitude)) /
               rho_of(f, f->bottom_radius + f->max_altitude);
    return y / f->max_altitude;
}

static double altitude_at(const atmosphere_lut_frame *f, int i, int n)
{
    double u = n > 1 ? (double)i / (n - 1) : 0.0;
    if (f->kind == ATMOSPHERE_PARAM_YUSOV) {
        double m = ATMOSPHERE_LUT_YUSOV_MARGIN;
        return m + pow(u, 1.0 / YUSOV_HEIGHT_POWER) * (f->max_altitude - 2.0 * m);
    }
    if (f->kind == ATMOSPHERE_PARAM_BRUNETON) {
        double rho = u * rho_of(f, f->bottom_radius + f->max_altitude);
        double y = sqrt(f->bottom_radius * f->bottom_radius + rho * rho) - f->bottom_radius;
        return i == 0 ? ATMOSPHERE_LUT_BRUNETON_GROUND : y;
    }
    return u * f->max_altitude;
}

static atmosphere_lut_position view_position(const atmosphere_lut_frame *f, int n, double y, double mu)
{
    if (f->kind == ATMOSPHERE_PARAM_YUSOV) {
        double c = atmosphere_lut_horizon_cosine(yusov_height(f, y), f->bottom_radius);
        if (mu > c)
            return half(1, pow(clamp((mu - c) / (1.0 - c), 0.0, 1.0), YUSOV_VIEW_POWER), n);
        return half(0, pow(clamp((c - mu) / (c + 1.0), 0.0, 1.0), YUSOV_VIEW_POWER), n);
    }
    double R = f->bottom_radius, r = R + fmax(y, 0.0), rho = rho_of(f, r), H = top_h(f);
    double rmu = r * mu, delta = rmu * rmu - r * r + R * R;
    if (rmu < 0.0 && delta > 0.0)
        return half(0, rho > 0.0 ? 1.0 - (-rmu - sqrt(delta)) / rho : 1.0, n);
    return half(1, (-rmu + sqrt(fmax(delta + H * H, 0.0))) / (rho + H), n);
}

/* The zenith cosine grid point i of n holds at altitude y. */
static double view_at(const atmosphere_lut_frame *f, int i, int n, double y)
{
    int m = n / 2, upper = i >= m;
    double frac = upper ? (double)(i - m) / (m - 1) : (double)i / (m - 1);
    if (f->kind == ATMOSPHERE_PARAM_YUSOV) {
        double c = atmosphere_lut_horizon_cosine(yusov_height(f, y), f->bottom_radius);
        double g = pow(frac, 1.0 / YUSOV_VIEW_POWER);
        double mu = upper ? fmax(c + g * (1.0 - c), c + YUSOV_HORIZON_GAP) : fmin(c - g * (c + 1.0), c - YUSOV_HORIZON_GAP);
        return clamp(mu, -1.0, 1.0);
    }
    double R = f->bottom_radius, Rt = f->top_radius, r = R + y, rho = rho_of(f, r), H = top_h(f);
    if (upper) {
        double d = clamp(frac * (rho + H), Rt - r, BRUNETON_FAR * (rho + H));
        return clamp((Rt * Rt - r * r - d * d) / (2.0 * r * d), -1.0, 1.0);
    }
    double d = clamp((1.0 - frac) * rho, r - R, BRUNETON_FAR * rho);
    double mu = d > 0.0 ? (R * R - r * r - d * d) / (2.0 * r * d) : -1.0;
    return clamp(fmin(mu, -sqrt(fmax(1.0 - (R / r) * (R / r), 0.0)) - BRUNETON_HORIZON_GAP), -1.0, 1.0);
}

void atmosphere_lut_positions(const atmosphere_lut_frame *f, const int n[4], double theta_s, double theta_v, double y,
                              double t, atmosphere_lut_position out[4])
{
    int linear = f->kind == ATMOSPHERE_PARAM_LINEAR;
    out[0] = whole(linear ? theta_s / ATMOSPHERE_LUT_LINEAR_THETA_S_MAX : atmosphere_lut_sun_unit(cos(theta_s)), n[0]);
    out[1] = linear || n[1] == 1 ? whole(theta_v / PI, n[1]) : view_position(f, n[1], y, cos(theta_v));
    out[2] = whole(altitude_unit(f, y), n[2]);
    out[3] = whole(t, n[3]);
}

void atmosphere_lut_grid_parameters(const atmosphere_lut_frame *f, const int n[4], const int i[4], double x[4])
{
    double u[4];
    for (int a = 0; a < 4; ++a)
        u[a] = n[a] > 1 ? (double)i[a] / (n[a] - 1) : 0.0;
    int linear = f->kind == ATMOSPHERE_PARAM_LINEAR;
    x[0] = linear ? u[0] * ATMOSPHERE_LUT_LINEAR_THETA_S_MAX : acos(atmosphere_lut_sun_from_unit(u[0]));
    x[2] = altitude_at(f, i[2], n[2]);
    x[1] = linear || n[1] == 1 ? u[1] * PI : acos(view_at(f, i[1], n[1], x[2]));
    x[3] = u[3];
}

int atmosphere_lut_parametrization_check(atmosphere_lut_parametrization kind, const int n[4], char *msg, size_t size)
{
    if (kind < 0 || kind >= ATMOSPHERE_PARAMS) {
        snprintf(msg, size, "atmosphere LUT: unknown parametrization %d", (int)kind);
        return -1;
    }
    if (kind != ATMOSPHERE_PARAM_LINEAR && (n[1] < 4 || n[1] % 2 != 0)) {
        snprintf(msg, size, "atmosphere LUT inscatter: the %s view axis needs an even size of at least 4, not %d",
                 atmosphere_lut_parametrization_name(kind), n[1]);
        return -1;
    }
    return 0;
}
