/* The axes of the Decima atmosphere LUTs (atmosphere/atmosphere_luts.h) under
 * three parametrizations: where a parameter (theta_s, theta_v, y, t) sits
 * on the grid of an axis of n points, and the parameter a grid point
 * holds. One definition for the build (grid point -> parameter) and the
 * lookup (parameter -> position); pure functions.
 *
 * A position p is in grid units: point i holds the texel i (a GPU samples
 * texture coordinate (p + 0.5) / n); the lookup interpolates linearly
 * between floor(p) and floor(p) + 1 within [lo, hi], the index range of
 * the part of the axis p lies in (the whole axis, or one half of the view
 * axis split at the horizon, so that filtering never crosses it).
 *
 * ATMOSPHERE_PARAM_LINEAR (gtlab's first table; README.md):
 *   theta_s in [0, 96 deg], theta_v in [0, 180 deg], y in [0, y_max],
 *   each linear in the angle or altitude, grid points at both ends.
 *
 * ATMOSPHERE_PARAM_YUSOV (Yusov 2013, "Outdoor Light Scattering Sample
 * Update", GDC 2013, and GPU Pro 4 "Practical implementation of light
 * scattering effects using epipolar sampling and 1D min/max binary trees",
 * the improved 4-D in-scattering parametrization, the talk's "[Yus13]";
 * its sun-view axis is dropped here as the talk drops theta_sv [Ele09]):
 *   y:       u = ((h - m) / (y_max - 2 m))^(1/2), h clamped to [m, y_max - m],
 *            m = 16 m (Yusov's safety margin), y_max the table's top (Yusov's
 *            atmosphere top: the talk's table is "near the ground");
 *   theta_v: the horizon's zenith cosine c_h = -sqrt(h (2 R + h)) / (R + h)
 *            (h clamped as above, R the planet's radius) splits the axis in
 *            two halves of n/2 points, each with its own end points: above
 *            the horizon (mu > c_h) f = ((mu - c_h) / (1 - c_h))^0.2 on points
 *            n/2 .. n-1 (horizon at n/2, zenith at n-1); below it
 *            f = ((c_h - mu) / (c_h + 1))^0.2 on points 0 .. n/2-1 (horizon
 *            at 0, nadir at n/2-1). A grid point holds mu kept 1e-4 off the
 *            horizon on its own side (Yusov);
 *   theta_s: Bruneton & Neyret's u = (atan(max(mu_s, -0.1975) tan(1.26 x 1.1))
 *            / 1.1 + 0.74) / 2 (Yusov uses it): mu_s in [-0.1975, 1], i.e.
 *            theta_s up to 101.4 deg, clamped below.
 *
 * ATMOSPHERE_PARAM_BRUNETON (Bruneton & Neyret 2008, "Precomputed
 * atmospheric scattering", section 4 and its code's texture coordinates):
 *   y:       u = rho / rho_max, rho = sqrt(r^2 - R^2) the distance to the
 *            horizon, rho_max its value at the table's top R + y_max; the
 *            ground's grid point holds r = R + 10 m (as the paper's 0.01 km);
 *   theta_v: split at the horizon as above, by distances: a ray that hits
 *            the ground (r mu < 0 and Delta = r^2 mu^2 - r^2 + R^2 > 0) at
 *            distance d = -r mu - sqrt(Delta) sits at (n/2 - 1)(1 - d / rho)
 *            (horizon at 0, nadir at n/2-1); any other ray, reaching the
 *            atmosphere's top R_t at d = -r mu + sqrt(Delta + H^2), H =
 *            sqrt(R_t^2 - R^2), at n/2 + (n/2 - 1) d / (rho + H) (horizon at
 *            n-1; the zenith at n/2 + (n/2-1)(R_t - r)/(rho + H): the points
 *            below it hold the zenith, as the paper clamps d to [R_t - r,
 *            0.999 (rho + H)] and the ground half's to [r - R, 0.999 rho],
 *            and keeps the latter's mu 0.001 below the horizon);
 *   theta_s: the formula above.
 *
 * t (the weather blend) is linear in [0, 1] under all three. A size-1
 * axis holds its low end. The nonlinear view axis needs an even size of at
 * least 4 (atmosphere_lut_parametrization_check). */
#ifndef GTLAB_ATMOSPHERE_LUT_AXES_H
#define GTLAB_ATMOSPHERE_LUT_AXES_H

#include <stddef.h>

typedef enum {
    ATMOSPHERE_PARAM_LINEAR,
    ATMOSPHERE_PARAM_YUSOV,
    ATMOSPHERE_PARAM_BRUNETON,
    ATMOSPHERE_PARAMS
} atmosphere_lut_parametrization;

/* "linear", "Yusov 2013", "Bruneton & Neyret 2008". */
const char *atmosphere_lut_parametrization_name(atmosphere_lut_parametrization kind);
/* "linear", "yusov2013", "bruneton2008": the files' names, ATTR_LUT_PARAMETRIZATION
 * and `gtlab lut atmosphere --parametrization`. */
const char *atmosphere_lut_parametrization_tag(atmosphere_lut_parametrization kind);
/* The kind whose tag is `tag`, or -1. */
int atmosphere_lut_parametrization_from_tag(const char *tag);
/* One sentence: the four axes' mappings of `kind`, for the files' ATTR_LUT. */
const char *atmosphere_lut_axes_description(atmosphere_lut_parametrization kind);

/* What the mappings depend on besides the sizes. */
typedef struct {
    atmosphere_lut_parametrization kind;
    double bottom_radius, top_radius; /* the planet's and the atmosphere's [m] */
    double max_altitude;              /* the table's y range [0, max_altitude] m */
} atmosphere_lut_frame;

#define ATMOSPHERE_LUT_LINEAR_THETA_S_MAX (96.0 * 3.14159265358979323846 / 180.0)
#define ATMOSPHERE_LUT_YUSOV_MARGIN 16.0    /* m */
#define ATMOSPHERE_LUT_BRUNETON_GROUND 10.0 /* m above the ground held by the lowest point */
#define ATMOSPHERE_LUT_MU_S_MIN (-0.1975)   /* the sun formula's lowest zenith cosine */

typedef struct {
    double p;   /* grid units */
    int lo, hi; /* the index range p interpolates in */
} atmosphere_lut_position;

/* The sun formula (ATMOSPHERE_PARAM_YUSOV and _BRUNETON): unit coordinate
 * of the zenith cosine mu_s, and its inverse. */
double atmosphere_lut_sun_unit(double mu_s);
double atmosphere_lut_sun_from_unit(double u);
/* The horizon's zenith cosine at altitude h over a planet of radius R. */
double atmosphere_lut_horizon_cosine(double h, double bottom_radius);

/* The largest sun zenith angle an axis of `kind` holds [rad]. */
double atmosphere_lut_theta_s_max(atmosphere_lut_parametrization kind);

/* The positions of (theta_s, theta_v, y, t) on the four axes of sizes n. */
void atmosphere_lut_positions(const atmosphere_lut_frame *f, const int n[4], double theta_s, double theta_v, double y,
                              double t, atmosphere_lut_position out[4]);
/* The parameters grid point i = (i_s, i_v, i_y, i_t) holds: theta_s, theta_v
 * [rad], y [m] and t into x[4]. */
void atmosphere_lut_grid_parameters(const atmosphere_lut_frame *f, const int n[4], const int i[4], double x[4]);

/* 0 when the sizes suit the parametrization (nonlinear: theta_v even, >= 4). */
int atmosphere_lut_parametrization_check(atmosphere_lut_parametrization kind, const int n[4], char *msg, size_t size);

#endif
