/* The error of the atmosphere LUTs (atmosphere/atmosphere_luts.h) at random
 * points, split into its two sources (issue 16 items 3 and 5):
 *   quadrature:    the build's own evaluation (FAST, what the texels hold)
 *                  against the reference, at the point: FAST - REFERENCE;
 *   interpolation: the lookup against the build's evaluation at the point:
 *                  lookup - FAST (the texels are FAST values, so this is the
 *                  interpolation alone);
 *   total:         lookup - REFERENCE.
 * References: in-scatter by atmosphere_single_scattering and
 * atmosphere_multiple_scattering REFERENCE (every optical depth by
 * quadrature; tolerances 1e-7 and 1e-6 of their scales), the sun by the
 * quadrature's transmittance, the sky by atmosphere_sky_mean_radiance
 * ADAPTIVE (32-panel outer rule over FAST rays).
 *
 * Points: theta_s and y uniform over the axes' ranges (splitmix64 from the
 * seed), theta_v uniform over the sky seen from y, [0, 90 deg + the
 * horizon's dip acos(R_b / (R_b + y))] (the talk's L_background is the sky:
 * rays that reach the ground hit the scene's terrain first, where the fog
 * model takes over), t cycling over the blends of the solutions given
 * (choose them off the t grid so that the t interpolation is measured).
 * Error at a point: the largest over channels (and species) of
 *   |a - b| / (|b| + floor),   floor = 1e-3 x the table's largest reference value:
 * relative (the eye's contrast threshold is relative, Weber) where the
 * value is not negligible against the table's brightest. */
#ifndef GTLAB_ATMOSPHERE_LUT_ERRORS_H
#define GTLAB_ATMOSPHERE_LUT_ERRORS_H

#include "atmosphere/atmosphere_luts.h"

enum { ATMOSPHERE_LUT_VALUES = 6 }; /* per point and table: in-scatter R rgb, M rgb; sun/sky rgb */

typedef struct {
    double theta_s, theta_v, altitude, t;
} atmosphere_lut_point;

typedef struct {
    int count;
    atmosphere_lut_point *points;
    double *reference; /* [count][ATMOSPHERE_TABLES][ATMOSPHERE_LUT_VALUES] */
    double *fast;      /* the same, FAST */
    double floor[ATMOSPHERE_TABLES];
    double quadrature_estimate; /* the references' largest error estimate (relative to their scales) */
} atmosphere_lut_reference;

/* Draws `points` points over the blends of `solutions` and evaluates both
 * ways (parallel; bits independent of `threads`). 0, or -1 out of memory. */
int atmosphere_lut_reference_build(atmosphere_lut_reference *ref, const atmosphere_solution *solutions, int count,
                                   int points, unsigned seed, int threads);
void atmosphere_lut_reference_free(atmosphere_lut_reference *ref);

typedef struct {
    double max, rms, p95;
    double p95_se; /* the 95th percentile's bootstrap standard error (core/statistics/bootstrap.h; -1 out of memory) */
} atmosphere_error_stats;

/* The daytime subset: the sun at least 10 degrees above the horizon. */
#define ATMOSPHERE_DAY_THETA_S (80.0 * 3.14159265358979323846 / 180.0)

typedef struct {
    atmosphere_error_stats interpolation, quadrature, total;
    atmosphere_error_stats day_total;      /* total over the points with theta_s <= ATMOSPHERE_DAY_THETA_S */
    atmosphere_error_stats twilight_total; /* total over the others (the sun lower: twilight) */
    int day_points, twilight_points;       /* how many points each holds */
} atmosphere_table_error;

/* The three tables' errors at the reference's points. */
int atmosphere_lut_errors(const atmosphere_luts *luts, const atmosphere_lut_reference *ref,
                          atmosphere_table_error out[ATMOSPHERE_TABLES]);

/* The sky a viewer sees through the in-scatter table (issue 42): pixels
 * of sky-dome images, L_background = sum_i p_i(nu) L_inscatter^i (the
 * talk's sky), the lookup against the same definition evaluated at the
 * pixel's own parameters by the build's evaluator (FAST, what the texels
 * hold): the table's interpolation alone, what its size and parametrization
 * decide (the build's quadrature, 0.1-0.3%, is the precomputation's, not
 * the table's).
 * Pixels: y uniform over [0, ATMOSPHERE_LUT_MAX_ALTITUDE] (the talk: "on
 * the ground or near the ground"), theta_s uniform over [theta_s_low,
 * theta_s_high], the view direction uniform over the solid angle of the sky
 * seen from y (zenith cosine uniform over [horizon, 1], azimuth to the sun
 * uniform: every direction of a sky dome weighted as the eye sees it), t
 * cycling over the solutions' blends.
 * Error of a pixel: max_c |L^_c - L_c| / max_c L_c, relative to the pixel's
 * brightest channel: exposure-independent (an auto-exposed image maps
 * relative radiance to code values), and a dim channel of a bright pixel
 * counts at the pixel's scale. */
typedef struct {
    int count;
    atmosphere_lut_point *points;
    double *nu;    /* [count] the cosine between view and sun */
    double *truth; /* [count][3] */
} atmosphere_sky_sample;

int atmosphere_sky_sample_build(atmosphere_sky_sample *sample, const atmosphere_solution *solutions, int count,
                                int pixels, double theta_s_low, double theta_s_high, unsigned seed, int threads);
void atmosphere_sky_sample_free(atmosphere_sky_sample *sample);
/* The pixels' errors' statistics (max, rms, p95 with its bootstrap s.e.). */
int atmosphere_sky_errors(const atmosphere_luts *luts, const atmosphere_sky_sample *sample,
                          atmosphere_error_stats *out);

#endif
