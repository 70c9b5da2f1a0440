/* The bloom downsample's 13 -> 9 tap refit (INSIDE, Gjoel GDC 2016, seed
 * 002; issue 17 item 3) against two targets:
 *   (a) Jimenez 2014's 13-tap kernel's 6 x 6 texel weights (the talk's own
 *       setting: "fitted 13 -> 9 bilinear tex-samples", "worst weight-error
 *       of approximation is 0.08", "corner sample has 8% error on bilinear
 *       weights, top sample is exact");
 *   (a') the same with each tap's weight held at its block's sum (the
 *       kernel keeps its total: no energy lost per level);
 *   (b) a Gaussian of the same variance (the talk: "this should be done to
 *       a gaussian distribution"): the separable weights g(x) g(y) at the
 *       texel centres x in {+-1/2, +-3/2, +-5/2}, normalised, with sigma
 *       chosen so that their variance per axis equals the 13-tap's (7/4
 *       texel^2); its continuous mass outside the footprint is reported.
 * Each fit (bloom_tap_fit.h) is scored by its worst and RMS texel
 * weight error, the talk's measure (a tap's four bilinear weights
 * normalised to sum 1 against the target block's, worst over taps), the
 * frequency response against the target's over [0, pi]^2 (and at the
 * destination's Nyquist, pi/2 per source texel), the error off exact half
 * resolution (every phase of the output pixel against the source grid, and
 * the rows of 1920x1080's first odd step, 240x135 -> 120x67), and DSSIM of
 * tone-mapped pyramids of an HDR render (gtlab's sphere-light reference)
 * built with the 9 taps against those built with the target, per level.
 * Writes <output>/bloom/bloom_9tap.{hlsl,glsl}: offsets (source texels) and
 * weights. */
#ifndef GTLAB_BLOOM_BLOOM_STUDY_H
#define GTLAB_BLOOM_BLOOM_STUDY_H

#include "bloom/bloom_tap_fit.h"
#include "project/study_context.h"

#define BLOOM_DIR "bloom"

enum { BLOOM_FITS = 3, BLOOM_MAX_LEVELS = 6 };

typedef struct {
    int width, height, spp, levels; /* the HDR render and the pyramid's levels below it */
    unsigned seed;
} bloom_request;

typedef struct {
    const char *target;          /* "13 taps, least squares", "13 taps, weights held", "Gaussian" */
    int fit_target, reference;   /* bloom_kernels.h's targets: fitted to, scored against off half resolution */
    int hold_weights;            /* 1: each tap's weight held at its block's target sum */
    bloom_fit_result fit;
    double max_target_weight;
    double worst_normalised_error; /* the talk's measure: within a tap's four weights */
    int worst_normalised_tap;
    double response_max_error;   /* max |H_fit - H_reference| over [0, pi]^2 */
    double response_target_nyquist, response_fit_nyquist; /* H at (pi/2, 0) */
    double worst_any_phase;      /* max texel weight error 9 taps vs reference over phases in [0, 1[^2 */
    double worst_odd_mip, rms_odd_mip; /* over the rows of 240x135 -> 120x67 */
} bloom_target_result;

typedef struct {
    int width, height, exact_half; /* the level's size; 1 if exactly half the one above */
    double dssim[BLOOM_FITS];    /* 9-tap pyramid against the reference's, tone-mapped */
    double dssim_policy[BLOOM_FITS]; /* the talk's policy: 9 taps at exact halves, the reference elsewhere */
} bloom_level_result;

typedef struct {
    bloom_request request;
    double gaussian_sigma, gaussian_outside_mass;
    double jimenez_variance;       /* per axis, texel^2 */
    bloom_target_result targets[BLOOM_FITS];
    int exact_levels_1080, exact_levels_1088; /* exact halvings in the chains from 1920x1080 and 1920x1088 */
    int level_count;
    bloom_level_result levels[BLOOM_MAX_LEVELS];
} bloom_result;

/* The request of `gtlab all` at a quality: the HDR render's size and samples
 * and the pyramid's levels are the quality table's (bloom rows of
 * techniques/quality_table.txt); seed 1. */
bloom_request bloom_default_request(study_quality quality);

/* A target's 6 x 6 weights (bloom_kernels.h) and the Gaussian's sigma. */
void bloom_target_weights(int target, double weights[BLOOM_FOOTPRINT][BLOOM_FOOTPRINT], double *sigma);

int bloom_study(const study_context *ctx, const bloom_request *rq, bloom_result *out, gt_error *e);

#endif
