/* The three LUTs of the Decima height fog (Kojima Productions, SIGGRAPH
 * 2017 Advances, "Height fog: Precomputation"), in the talk's
 * parametrisation, for the atmosphere of atmosphere/atmosphere_model.h:
 *
 *   L_inscatter^i(theta_s, theta_v, y, t), i in {Rayleigh, Mie}: the
 *     in-scattered radiance along a view ray from altitude y at view zenith
 *     angle theta_v to the ground or the top, with the sun at zenith angle
 *     theta_s, WITHOUT the phase (the runtime forms L_background = sum_i
 *     p_i(theta_sv) L_inscatter^i: "ignore theta_sv dependency [Ele09]"):
 *       L^R = S_R + (sum_{k>=2} L^k) / Pbar_R(mu_v, mu_s),   L^M = S_M
 *     (atmosphere_scattering.h: S_i single scattering, L^k the azimuth-
 *     averaged orders, Pbar_R Rayleigh's azimuthal mean phase). Multiple
 *     scattering goes into the Rayleigh table as Bruneton & Neyret 2008 put
 *     it there, divided by Pbar_R so that p_R(theta_sv) L^R restores it
 *     exactly on the average over the sun's azimuth;
 *   L_sun(theta_s, y, t) = E_sun T_sun(y, theta_s): the solar irradiance
 *     reaching altitude y (transmittance to the top times the visible part
 *     of the disc) [W m^-2 nm^-1], what the fog multiplies by
 *     sum_i beta_si p_i / sum_i beta_ti;
 *   L_sky(theta_s, y, t) = (1/4pi) \int_{S^2} L_atm(y, w) dw, averaged over
 *     the sun's azimuth: the mean radiance of the sky light (all orders, no
 *     sun disc, black ground) arriving at y from all directions. For an
 *     isotropic scatterer beta_s L_sky is exactly the in-scatter of sky
 *     light, so it is the ambient term the fog multiplies by
 *     sum_i beta_si / sum_i beta_ti (the talk's L_amb).
 *
 * Axes (grid points at both ends, Bruneton's convention; a size-1 axis holds
 * its low end), in the linear parametrization (the default; the others,
 * Yusov 2013's and Bruneton & Neyret 2008's, are atmosphere/atmosphere_lut_axes.h:
 * their lookup is C only, so they are written as EXR only): theta_s in [0, ATMOSPHERE_LUT_THETA_S_MAX] (96 deg: civil
 * twilight), theta_v in [0, 180 deg], y in [0, max_altitude] m, t in [0, 1];
 * value x of an axis of size N sits at position p = x / max (N - 1): a GPU
 * samples it at (p + 0.5) / N. The lookup (linear in each axis, clamped) is
 * atmosphere/atmosphere_luts.inc, the same text in C and in the shaders.
 *
 * Layouts: inscatter[((((t Ny + y) Nv + v) Ns + s) 2 + i) 3 + c],
 * sun and sky[((t Ny + y) Ns + s) 3 + c]. Memory, as the talk counts it:
 * 8 B per in-scatter texel (RGBA16F, Bruneton & Neyret's encoding of Mie
 * in alpha: (8, 64, 8, 4) = 128 KB) and 16 B per sun or sky texel (RGBA32F:
 * (64, 1, 4) = 4 KB). gtlab holds both species in float RGB; the encoding's
 * own error is not part of the measurements. */
#ifndef GTLAB_ATMOSPHERE_LUTS_H
#define GTLAB_ATMOSPHERE_LUTS_H

#include "atmosphere/atmosphere_lut_axes.h"
#include "atmosphere/atmosphere_model.h"
#include "atmosphere/atmosphere_scattering.h"

#define ATMOSPHERE_LUT_THETA_S_MAX ATMOSPHERE_LUT_LINEAR_THETA_S_MAX
#define ATMOSPHERE_LUT_THETA_V_MAX 3.14159265358979323846
#define ATMOSPHERE_LUT_MAX_ALTITUDE 2000.0 /* the talk: sizes "optimized for games on the ground or near the ground" */
enum { ATMOSPHERE_LUT_MAX_AXIS = 256 };

enum { ATMOSPHERE_AXIS_THETA_S, ATMOSPHERE_AXIS_THETA_V, ATMOSPHERE_AXIS_ALTITUDE, ATMOSPHERE_AXIS_WEATHER };
enum { ATMOSPHERE_TABLE_INSCATTER, ATMOSPHERE_TABLE_SUN, ATMOSPHERE_TABLE_SKY, ATMOSPHERE_TABLES };

/* Sizes per axis (theta_s, theta_v, y, t); the sun and sky tables ignore theta_v. */
typedef struct {
    int inscatter[4];
    int sun[4];
    int sky[4];
} atmosphere_lut_sizes;

/* The talk's example: (8, 64, 8, 4), (64, 1, 4), (64, 1, 4). */
atmosphere_lut_sizes atmosphere_lut_sizes_talk(void);
/* 0 when every axis is in 1..ATMOSPHERE_LUT_MAX_AXIS (theta_v of sun and sky is 1). */
int atmosphere_lut_sizes_check(const atmosphere_lut_sizes *sizes, char *msg, size_t size);
/* Bytes of one table at the talk's texel sizes. */
double atmosphere_lut_bytes(int table, const int size[4]);

typedef struct {
    atmosphere_model model;
    double max_altitude;
    atmosphere_lut_sizes sizes;
    atmosphere_lut_parametrization parametrization; /* of every table's axes */
    float *table[ATMOSPHERE_TABLES];
    double build_seconds;
} atmosphere_luts;

/* One paragraph describing the tables' layout and their parametrization's
 * axes (atmosphere_lut_axes_description), for file metadata, into text. */
void atmosphere_luts_description(const atmosphere_luts *luts, char *text, size_t size);

/* Builds the three tables: one atmosphere_solve per distinct t, then every
 * texel FAST (atmosphere_scattering.h). 0, or -1 (bad sizes or model: msg;
 * out of memory). Bits independent of `threads`. */
int atmosphere_luts_build(atmosphere_luts *luts, const atmosphere_model *m, const atmosphere_lut_sizes *sizes,
                          int threads, char *msg, size_t msg_size);
/* The same from precomputed solutions (atmosphere_solve), one for each
 * distinct t of the sizes' t axes, in any order (others unused): -1 with msg
 * when one is missing. A sweep of sizes solves each blend once. */
int atmosphere_luts_build_from(atmosphere_luts *luts, const atmosphere_solution *solutions, int count,
                               const atmosphere_lut_sizes *sizes, int threads, char *msg, size_t msg_size);
/* The same under a parametrization of the axes (atmosphere/atmosphere_lut_axes.h). */
int atmosphere_luts_build_parametrized(atmosphere_luts *luts, const atmosphere_solution *solutions, int count,
                                       const atmosphere_lut_sizes *sizes, atmosphere_lut_parametrization kind,
                                       int threads, char *msg, size_t msg_size);
void atmosphere_luts_free(atmosphere_luts *luts);
/* The frame of the tables' axes (their parametrization, radii, y range). */
atmosphere_lut_frame atmosphere_luts_frame(const atmosphere_luts *luts);
/* The distinct blends t of the three tables' t axes into blends (room for
 * 3 ATMOSPHERE_LUT_MAX_AXIS), in table order; returns their count: the
 * solutions atmosphere_luts_build_from needs. */
int atmosphere_lut_blends(const atmosphere_lut_sizes *sizes, double *blends);
/* The solution of blend t among `count`, or NULL. */
const atmosphere_solution *atmosphere_solution_find(const atmosphere_solution *solutions, int count, double t);

/* The value of an axis' grid point i of n. */
double atmosphere_lut_axis_value(int axis, int i, int n, double max_altitude);

/* The runtime lookups (atmosphere/atmosphere_luts.inc), per channel in float:
 * L_inscatter^species at (theta_s, theta_v, y, t) [radians, m], and the sun
 * or sky table at (theta_s, y, t). */
void atmosphere_lut_inscatter(const atmosphere_luts *luts, float theta_s, float theta_v, float y, float t,
                              float out[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS]);
void atmosphere_lut_light(const atmosphere_luts *luts, int table, float theta_s, float y, float t,
                          float out[ATMOSPHERE_CHANNELS]);

/* The talk's background radiance sum_i p_i(nu) L_inscatter^i (Rayleigh and
 * Cornette-Shanks phases, the model's g), at cosine nu between view and sun. */
void atmosphere_lut_background(const atmosphere_luts *luts, float theta_s, float theta_v, float y, float t, float nu,
                               float out[ATMOSPHERE_CHANNELS]);

#endif
