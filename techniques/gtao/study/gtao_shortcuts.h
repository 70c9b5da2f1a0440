/* The GTAO talk's performance shortcuts and denoisers measured (issue 25,
 * items 6-8; seeds/001, "Achieving the Performance Target", "Noise
 * Distribution", "Spatial/Temporal Denoiser Details"), each a study run per
 * scene inside the `gtao` stage (gtao_validation.h) on the AO
 * references' G-buffers, with results pooled over the scenes:
 *  - the spatio-temporal pattern (gtao_pattern.c): the 24-frame cycle,
 *    denoised, against the 96-direction brute force it stands for, and the
 *    talk's row order against Morton order;
 *  - half resolution and the MIN depth MIP chain (gtao_half_res.c): each
 *    against the full-resolution search as a function of the radius, and
 *    the talk's "4x samples per direction";
 *  - the denoisers (gtao_denoisers.c): the spatial filter's depth tests on
 *    flat pixels and at edges, the temporal filter's alternating window
 *    (the shift it removes) and the neighbourhood clamp's window size;
 * Uncertainty: errors against a deterministic target (the brute force) are
 * means over 8x8-pixel blocks (metrics/block_mean.h) with their standard
 * error; rankings are paired differences of squared errors over the same
 * blocks, so a verdict can come out "not significant". */
#ifndef GTLAB_GTAO_GTAO_SHORTCUTS_H
#define GTLAB_GTAO_GTAO_SHORTCUTS_H

#include "core/error.h"
#include "gtao/gtao.h"
#include "gtao/gtao_spatial_filter.h"
#include "metrics/block_mean.h"
#include "metrics/shift_fit.h"
#include "project/scene_list.h"

enum { GTAO_SHORTCUT_MAX_SCENES = STUDY_SCENES_MAX };

/* One scene as the gtao stage holds it. */
typedef struct {
    const char *name;
    const ss_gbuffer *g;
    const float *hf, *ref3d;      /* ao.V of the height-field and 3-D references */
    double hf_mean_variance;      /* mean ao.V stderr^2 of the height-field reference over the mask */
    double ref3d_mean_variance;
    float radius, max_radius_px;  /* the gtao stage's: no radius limit */
    float camera_distance;        /* from the camera to its target: the unit of the item-6 radii */
    int half_res_radius_stride;   /* half resolution: every n-th of its radius fractions (the quality table's) */
    int claim_radius_only;        /* half resolution: only the claims' radius (GTAO_HALF_RES_4X_RADIUS) */
    int no_four_x;                /* half resolution: not the "4x samples" runs */
    float falloff;                /* the cycle's (0: none, the references') */
} gtao_shortcut_scene;

/* The talk's configuration over its 24-frame cycle, rendered once per
 * scene and order (gtao_shortcuts.c) and observed by items 7 and 8: GTAO
 * medium at the stage's radius, one raw frame at a time, filtered by the
 * default 4x4 bilateral filter and accumulated (== gtao_render). */
enum { GTAO_CYCLE_FRAMES = 24, GTAO_CYCLE_ORDERS = 2, GTAO_CLAMP_WINDOWS = 5 };
extern const float gtao_clamp_windows[GTAO_CLAMP_WINDOWS]; /* 0, 0.25, 0.5 (the talk's), 1, 2 */
typedef struct {
    const float *brute;                      /* the 96 directions in one frame (regular slices, no filter) */
    const float *first[GTAO_CYCLE_ORDERS];   /* rows, Morton: after frame 0, denoised */
    const float *last[GTAO_CYCLE_ORDERS];    /* after the 24 frames, denoised */
    const float *raw_last;                   /* rows, 24 frames accumulated without the spatial filter */
    const float *raw_first;                  /* rows, frame 0 before the filter */
    const float *fixed_window_last;          /* rows, 24 frames, the filter's window never moved */
    const float *clamped_last[GTAO_CLAMP_WINDOWS]; /* rows, 24 frames, history clamped (gtao_temporal_clamped) */
} gtao_cycle;

/* Item 7: the pattern. Frames accumulated in the study: 1, 24. */
enum { GTAO_PATTERN_RUNS = 2, GTAO_PATTERN_DIRECTIONS = 96 };
extern const int gtao_pattern_frames[GTAO_PATTERN_RUNS];

typedef struct {
    char scene[64];
    double rmse_rows[GTAO_PATTERN_RUNS];   /* the talk's configuration, denoised, vs the brute force */
    double rmse_morton[GTAO_PATTERN_RUNS]; /* the same with the directions in Morton order */
    double rmse_raw_cycle;                 /* 24 frames without the spatial filter vs the brute force */
    double brute_rmse_hf;                  /* the brute force vs the height-field reference, less its noise */
} gtao_pattern_scene;

typedef struct {
    int scene_count;
    gtao_pattern_scene scenes[GTAO_SHORTCUT_MAX_SCENES];
    /* pooled over scenes, 8x8 blocks */
    block_mean cycle_se2;                           /* (24 frames denoised - brute force)^2 */
    block_mean order_difference[GTAO_PATTERN_RUNS]; /* (rows - brute)^2 - (Morton - brute)^2 */
    double cycle_rmse, cycle_rmse_se;               /* from cycle_se2 */
    double hf_noise_rmse;                           /* sqrt of the mean over scenes of the mean stderr^2 */
} gtao_pattern_result;

/* Item 6: half resolution and the MIN MIP chain. GTAO with 4 regular slices,
 * 4 samples per side, no denoiser, exact maths, depths point-sampled at full
 * resolution (the baseline) or fetched as below; half-resolution AO is
 * upsampled to full resolution by its block. */
typedef enum {
    GTAO_HALF_RES_FULL_MIP,     /* full resolution, MIP level by distance, point-sampled */
    GTAO_HALF_RES_FULL_MIP_MIN, /* full resolution, MIP, MIN-filtered (= min(Gather4)) */
    GTAO_HALF_RES_HALF,         /* half resolution, point-sampled */
    GTAO_HALF_RES_HALF_MIP_MIN, /* half resolution, MIP, MIN-filtered: the talk's */
    GTAO_HALF_RES_VARIANTS
} gtao_half_res_variant;
extern const char *const gtao_half_res_variant_names[GTAO_HALF_RES_VARIANTS];
enum { GTAO_HALF_RES_MAX_RADII = 5, GTAO_HALF_RES_STEPS = 4, GTAO_HALF_RES_SLICES = 4 };

typedef struct {
    double radius_fraction;                       /* of the camera distance; 0: no limit (the references') */
    block_mean se2[GTAO_HALF_RES_VARIANTS];       /* (variant - full resolution)^2 */
    block_mean bias[GTAO_HALF_RES_VARIANTS];      /* variant - full resolution */
    block_mean change[GTAO_HALF_RES_VARIANTS];    /* |variant - full resolution|: the shortcut's own change */
    block_mean codes[GTAO_HALF_RES_VARIANTS];     /* 1 where the variant changes the pixel's 8-bit code */
    double rmse[GTAO_HALF_RES_VARIANTS], rmse_se[GTAO_HALF_RES_VARIANTS];
    double bias_mean[GTAO_HALF_RES_VARIANTS], bias_se[GTAO_HALF_RES_VARIANTS];
} gtao_half_res_radius;

typedef struct {
    char scene[64];
    /* no radius limit, against the references, less their noise: full resolution, the talk's */
    double full_rmse_hf, talk_rmse_hf, full_rmse_3d, talk_rmse_3d;
} gtao_half_res_scene;

typedef struct {
    int radius_count;
    gtao_half_res_radius radii[GTAO_HALF_RES_MAX_RADII];
    int scene_count;
    gtao_half_res_scene scenes[GTAO_SHORTCUT_MAX_SCENES];
    /* "4x samples": at the radius fraction GTAO_HALF_RES_4X_RADIUS, against a
     * full-resolution search with GTAO_HALF_RES_CONVERGED_STEPS per side:
     * (MIN MIP, 4 steps)^2 - (point, 16 steps)^2, and each alone; "still
     * useful": (MIN MIP, 4 steps)^2 - (point-sampled MIP, 4 steps)^2 */
    block_mean four_x, four_x_min_se2, four_x_point_se2, min_vs_mip, mip_se2;
    double four_x_mean, four_x_se, four_x_min_rmse, four_x_point_rmse;
    double min_vs_mip_mean, min_vs_mip_se, mip_rmse;
    double talk_rmse_unbounded, talk_rmse_unbounded_se; /* the talk's vs full resolution, no radius limit */
    double hf_noise_rmse;
} gtao_half_res_result;
#define GTAO_HALF_RES_4X_RADIUS 0.2
enum { GTAO_HALF_RES_CONVERGED_STEPS = 32 };

/* Item 8: the denoisers, on the cycle. Depth tests: frame 0 (rows), each
 * filter, against the brute force, on edge pixels (within 2 pixels of a
 * background pixel or of a second depth difference above 2% of the depth:
 * silhouettes and creases) and flat ones. The alternating window: the
 * 24-frame accumulation's shift against the brute force (metrics/
 * shift_fit.h) with and without it. The clamp: 24 frames with the history
 * clamped, each window size, against no clamp. */
typedef struct {
    char scene[64];
    double edge_fraction;                                             /* of the covered pixels */
    double rmse_flat[GTAO_DEPTH_TESTS], rmse_edge[GTAO_DEPTH_TESTS];  /* 1 frame, vs the brute force */
    double shift_with[2], shift_without[2];                           /* (x, y) pixels, 24 frames */
    double rmse_with, rmse_without;                                   /* 24 frames, vs the brute force */
    double rmse_clamped[GTAO_CLAMP_WINDOWS];                          /* 24 frames, vs the brute force */
} gtao_denoisers_scene;

typedef struct {
    int scene_count;
    gtao_denoisers_scene scenes[GTAO_SHORTCUT_MAX_SCENES];
    /* (talk's final test, linear + 1st + 2nd)^2 - (log + 1st)^2, 8x8 blocks */
    block_mean d2_minus_log_edge, d2_minus_log_flat;
    block_mean d2_minus_d1_edge, d2_minus_d1_flat;
    shift_fit fit_with, fit_without;
    double shift_with[2], shift_with_se[2], shift_without[2], shift_without_se[2];
    double diagonal_rms_gradient; /* RMS change of the brute force per pixel of shift (t, t) (shift_fit.h) */
    block_mean bias_with, bias_without;                 /* 24 frames - brute force */
    block_mean clamp_minus_none[GTAO_CLAMP_WINDOWS];    /* (clamped)^2 - (no clamp)^2 */
} gtao_denoisers_result;

/* The claims rows in the talk's setting (issue 42, item 4;
 * gtao_talk_setting.h): a 1920x1080 G-buffer and its 960x540 half.
 * Half resolution's own change: the 960x540 pass with the MIN chain against
 * the 1920x1080 search (half_res, the claims' radius only); the MIN filter
 * within the 960x540 pass (half_pass: its "4x samples" runs); the pattern
 * and the denoisers on the 960x540 pass (the talk's: the AO, its filter and
 * accumulation run at half resolution). The cycle at the talk's radius
 * (gtao_talk_radius), the half-resolution runs at their own radius; no
 * reference, so no "against the references" figures. */
enum { GTAO_TALK_MAX_SCENES = 4 };
typedef struct {
    int scene_count;
    char scenes[GTAO_TALK_MAX_SCENES][64];
    int full_width, full_height, half_width, half_height;
    gtao_half_res_result half_res, half_pass;
    gtao_pattern_result pattern;
    gtao_denoisers_result denoisers;
    double seconds, cpu_seconds; /* wall clock and CPU time of the runs, G-buffers included (gtao_validation) */
} gtao_talk_result;

typedef struct {
    gtao_pattern_result pattern;
    gtao_half_res_result half_res;
    gtao_denoisers_result denoisers;
    gtao_talk_result talk; /* the claims rows at the talk's resolution */
} gtao_shortcuts_result;

/* Every shortcut study on one scene, its rows and pooled blocks added to r. */
int gtao_shortcuts_scene(const gtao_shortcut_scene *s, gtao_shortcuts_result *r, gt_error *e);
/* The claims rows' studies on one scene in the talk's setting: `full` the
 * 1920x1080 G-buffer, `half` its 960x540 half, camera_distance from the
 * camera to its target. */
int gtao_shortcuts_talk_scene(const char *name, const ss_gbuffer *full, const ss_gbuffer *half,
                              float camera_distance, gtao_talk_result *r, gt_error *e);
/* The pooled figures, after the last scene. */
void gtao_shortcuts_finish(gtao_shortcuts_result *r);

/* The studies, one file each. */
/* The brute force of the cycle (96 regular slices, otherwise GTAO medium). */
gtao_params gtao_cycle_params(const gtao_shortcut_scene *s, int pattern);
int gtao_pattern_scene_study(const gtao_shortcut_scene *s, const gtao_cycle *c, gtao_pattern_result *r,
                             gt_error *e);
void gtao_pattern_finish(gtao_pattern_result *r);
int gtao_half_res_scene_study(const gtao_shortcut_scene *s, gtao_half_res_result *r, gt_error *e);
void gtao_half_res_finish(gtao_half_res_result *r);
int gtao_denoisers_scene_study(const gtao_shortcut_scene *s, const gtao_cycle *c, gtao_denoisers_result *r,
                               gt_error *e);
void gtao_denoisers_finish(gtao_denoisers_result *r);

#endif
