/* The exponential height fog of the Decima talk (Kojima Productions,
 * "Height fog", SIGGRAPH 2017 Advances; issue 16), once, for the reference
 * integrators (techniques/height_fog/height_fog_integrator.h) and the analytic model
 * (height_fog/height_fog.h). World up is +Y (glTF), altitudes in metres.
 *
 * Medium. Rayleigh scattering beta_Rs (RGB), Mie scattering beta_Ms and Mie
 * absorption beta_Ma (grey), all at altitude 0, scaled by one density
 *
 *   rho(y) = exp(-y / H)            (y >= floor_y; 0 below the floor)
 *
 * so beta_t = beta_Rs + beta_Ms + beta_Ma and the albedo beta_s / beta_t are
 * the same at every altitude. H = +infinity is a homogeneous medium. The
 * floor (default -infinity: none) bounds the medium from below, so a medium
 * without a ground still lets light out (the energy test).
 *
 * Optical depth. Along a straight segment of length d between altitudes y0
 * and y1 (Delta = y1 - y0), the integral of rho is
 *
 *   D = d exp(-y0/H) (1 - exp(-Delta/H)) / (Delta/H)
 *     = d exp(-y_low/H) f(|Delta| / H),   f(x) = (1 - e^-x) / x = -expm1(-x)/x,
 *
 * (the two forms are equal: factor out the denser end, y_low = min(y0, y1)).
 * The second has no cancellation: f is evaluated by expm1, exact to rounding
 * as x -> 0 (horizontal segments, H -> infinity; f(0) = 1), and it is
 * symmetric in y0, y1 bit for bit. tau_c = beta_t,c D.
 *
 * Lights. A directional sun of irradiance sun_color (RGB, on a plane normal
 * to it) from the unit direction sun_direction (pointing to the sun), and a
 * uniform sky of radiance amb_color. The talk's "albedo controls" albedo_R
 * and albedo_M tint the sun's scattering only (as its HeightFog() does):
 *
 *   S_sun(mu) = albedo_R beta_Rs p_R(mu) + albedo_M beta_Ms p_HG(mu, g)   [1/(m sr)]
 *
 * with mu = dot(sun_direction, view direction) (core/optics/phase_function.h). */
#ifndef GTLAB_CORE_OPTICS_HEIGHT_FOG_MEDIUM_H
#define GTLAB_CORE_OPTICS_HEIGHT_FOG_MEDIUM_H

#include "core/error.h"
#include "core/vec3.h"

/* The talk's HeightFogParam plus the sun's direction and the floor. */
typedef struct {
    double beta_rs[3];    /* mBetaRs: Rayleigh scattering at y = 0 [1/m] */
    double beta_ms;       /* mBetaMs: Mie scattering at y = 0 [1/m] */
    double beta_ma;       /* mBetaMa: Mie absorption at y = 0 [1/m] */
    double mie_g;         /* mMieAsymmetry, |g| < 1 */
    double scale_height;  /* mScaleHeight H [m], > 0; +infinity: homogeneous */
    double albedo_r[3];   /* mAlbedoR, >= 0 */
    double albedo_m[3];   /* mAlbedoM, >= 0 */
    double sun_color[3];  /* mSunColor: the sun's irradiance, >= 0 */
    double amb_color[3];  /* mAmbColor: the sky's uniform radiance, >= 0 */
    vec3 sun_direction;   /* unit, towards the sun */
    double floor_y;       /* no fog below [m]; -infinity: none */
} height_fog_param;

/* Clear air at sea level with a little haze (Bruneton 2017's Rayleigh
 * coefficients, H = 1 km for the fog), white sun 45 degrees up, grey sky,
 * unit albedo controls, no floor. */
height_fog_param height_fog_param_default(void);

/* The two weathers of the study (the talk precomputes "sunny" and "dense
 * fog"), with the sun at elevation_deg above the horizon, turned 35 degrees
 * from +Z towards +X: "sunny" is the default above; "dense" a ground fog of
 * H = 150 m, beta_Ms = 2e-3 /m (about 2 km visibility at y = 0), beta_Ma =
 * 1e-4 /m, a greyer sun and a brighter sky. Returns 0, or -1 for another name. */
int height_fog_weather(const char *name, double elevation_deg, height_fog_param *p);

/* 0, or -1 with e naming `subject` and the first bad parameter: a NaN or
 * negative coefficient, colour or albedo control, H <= 0 or NaN, |g| >= 1,
 * a sun direction that is not unit length (1e-3) or is NaN, a NaN floor.
 * The sun below the horizon is valid: it lights nothing through an infinite
 * flat fog layer (height_fog_sun_transmittance returns 0 there). */
int height_fog_param_validate(const height_fog_param *p, const char *subject, gt_error *e);

/* rho(y) above. */
double height_fog_density(const height_fog_param *p, double y);

/* f(x) = (1 - e^-x) / x for x >= 0, f(0) = 1, without cancellation. */
double height_fog_mean_factor(double x);

/* The integral of rho along a straight segment of length d >= 0 from
 * altitude y0 to altitude y1 (the floor clips it). Symmetric in y0, y1. */
double height_fog_segment_density(const height_fog_param *p, double y0, double y1, double d);

/* The inverse: the distance along a ray from altitude y0 whose unit
 * direction has vertical component dir_y at which the integral of rho
 * reaches D >= 0, or +infinity if it never does (upwards through a thin top,
 * or down through the floor). Closed form: with k = dir_y / H and
 * a = k D exp(y0/H), t = -log1p(-a) / k (t = D exp(y0/H) g(a) with
 * g(a) = -log1p(-a)/a as k -> 0, no cancellation). Free-flight sampling
 * (Monte Carlo) and the quadrature's change of variable use it. */
double height_fog_distance_at(const height_fog_param *p, double y0, double dir_y, double density_integral);

/* beta_t and beta_s per channel at y = 0. */
void height_fog_extinction(const height_fog_param *p, double beta_t[3]);
void height_fog_scattering(const height_fog_param *p, double beta_s[3]);

/* S_sun(mu) above, per channel. */
void height_fog_sun_scattering(const height_fog_param *p, double mu, double s[3]);

/* The fog's transmittance towards the sun from altitude y: exp(-beta_t D)
 * with D = H rho(y) / sin(elevation) (the column above y, slanted); 0 when
 * the sun is at or below the horizon (an infinite flat layer blocks it), 1
 * without fog. */
void height_fog_sun_transmittance(const height_fog_param *p, double y, double t[3]);

#endif
