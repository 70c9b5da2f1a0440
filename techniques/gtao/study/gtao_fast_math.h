/* The GTAO talk's fast arc cosine and square root measured in AO error
 * (issue 25, item 9; seeds/001, "Cosine Weighting LUT vs Analytical"), and
 * the arc cosine's polynomial refitted to the references.
 *
 * (a) The talk's configuration (GTAO medium, one frame) with fast_math on
 *     and off on every scene: the shortcut's own change, mean |on - off|
 *     and the share of pixels whose 8-bit code it changes (the claim's
 *     figure, issue 42), and the paired difference of their squared errors
 *     against the height-field reference (block standard errors,
 *     metrics/cluster_mean.h).
 * (b) The arc cosine alone, on fixed horizons: GTAO with regular slices and
 *     no pattern (`slices` x `steps` per side, no radius limit) searches
 *     each pixel's horizons once (gtao_fast_acos.h) and replays the
 *     slice integrals with each variant: exact acosf; the talk's polynomial
 *     with the sqrt constant as transcribed (0x1FB01DF5) and as Drobot's
 *     (0x1FBD1DF5); the slope c1 refitted; the slope and the constant c0
 *     refitted. The refits minimise sum over scenes and pixels of
 *     (AO - height-field reference)^2 with Ceres (fitters/ceres_bridge.h);
 *     their standard errors are jackknifed over scenes (each scene left out
 *     in turn), and each scene's held-out error is its paired difference
 *     against the talk's polynomial with the fit made without it.
 * (c) (a)'s change in the talk's setting (issue 42, item 4;
 *     gtao_talk_setting.h): GTAO medium on and off on the 960x540
 *     half-resolution pass of a 1920x1080 frame of the talk-setting scenes,
 *     at the talk's radius (no reference needed: the shortcut's own change). */
#ifndef GTLAB_GTAO_GTAO_FAST_MATH_H
#define GTLAB_GTAO_GTAO_FAST_MATH_H

#include "gtao/gtao_fast_acos.h"
#include "metrics/cluster_mean.h"
#include "project/study_context.h"
#include "project/scene_list.h"

typedef enum {
    FAST_ACOS_EXACT,
    FAST_ACOS_TRANSCRIBED, /* the talk's slope, the slide's sqrt constant */
    FAST_ACOS_TALK,        /* the talk's slope, Drobot's constant (gtao_fast_acos) */
    FAST_ACOS_SLOPE,       /* c1 refitted */
    FAST_ACOS_BOTH,        /* c1 and c0 refitted */
    FAST_ACOS_SLOPE_REFERENCE, /* c1 refitted to the height-field references */
    FAST_ACOS_VARIANTS
} fast_acos_variant;
extern const char *const fast_acos_variant_names[FAST_ACOS_VARIANTS];

enum { FAST_MATH_MAX_SCENES = STUDY_SCENES_MAX, FAST_MATH_TALK_SCENES = 4 };

typedef struct {
    char scene[64];
    /* (a) GTAO medium, one frame: fast_math on minus off */
    double medium_shift_mean, medium_shift_max; /* mean and max |AO_on - AO_off| */
    cluster_mean medium_change, medium_codes;    /* |AO_on - AO_off|; pixels whose 8-bit code differs */
    cluster_mean medium_paired_hf;                /* mean (on - hf)^2 - (off - hf)^2 */
    /* (b) replayed horizons, per variant */
    double rmse_hf[FAST_ACOS_VARIANTS], rmse_3d[FAST_ACOS_VARIANTS];
    double shift_mean[FAST_ACOS_VARIANTS], shift_max[FAST_ACOS_VARIANTS]; /* |AO - AO_exact| */
    cluster_mean paired_hf[FAST_ACOS_VARIANTS]; /* mean (AO - hf)^2 - (AO_exact - hf)^2 */
    double heldout_slope_gain, heldout_both_gain; /* mean (refit - hf)^2 - (talk - hf)^2, fitted without this scene */
} gtao_fast_math_scene;

typedef struct {
    int slices, steps, fit_stride; /* replay configuration; fits use every fit_stride-th pixel */
    gtao_acos_poly poly[FAST_ACOS_VARIANTS];
    double function_error[FAST_ACOS_VARIANTS]; /* max |acos~(x) - acos(x)| over a grid of [-1, 1] (radians) */
    double slope_jackknife_se, both_jackknife_se[2]; /* c1; c1 and c0 */
    double slope_ceres_se;                           /* Ceres' (pixels taken as independent: too small) */
    double objective_start[3], objective_end[3];     /* slope, both, slope to the references: cost at the talk's
                                                        values, at the optimum */
    int iterations[3];
    int at_bound[3];                                 /* 1 if the optimum rests on a bound of the fit's box
                                                        (c1 in [-1, 1], c0 in [1, 2.5]): not an interior optimum */
    int scene_count;
    gtao_fast_math_scene scenes[FAST_MATH_MAX_SCENES];
    /* pooled over scenes (pixel-weighted means, block standard errors combined) */
    cluster_mean medium_paired_hf, medium_change, medium_codes;
    double medium_shift_mean, medium_shift_max;
    double heldout_slope_gain_mean, heldout_slope_gain_se; /* mean over scenes, s.e. over scenes */
    double heldout_both_gain_mean, heldout_both_gain_se;
    double hf_mean_variance; /* the height-field references' noise, MSE units, mean over scenes */
    /* (c): the talk's setting */
    int talk_scene_count, talk_width, talk_height; /* the pass's size */
    char talk_scenes[FAST_MATH_TALK_SCENES][64];
    cluster_mean talk_change, talk_codes; /* pooled |AO_on - AO_off|, pixels whose 8-bit code differs */
    double talk_shift_max;
} gtao_fast_math_result;

typedef struct {
    const char *ao_references_dir; /* <scene>.exr */
    const char *gtao_dir;          /* <scene>_heightfield.exr */
} gtao_shortcuts_request;

int gtao_fast_math_study(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_fast_math_result *out,
                         gt_error *e);

#endif
