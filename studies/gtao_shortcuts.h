/* The GTAO talk's performance shortcuts and denoisers measured (issue 25,
 * items 6-8; seeds/001, "Achieving the Performance Target", "Noise
 * Distribution", "Spatial/Temporal Denoiser Details"), each a study run per
 * scene inside the `gtao` stage (studies/gtao_validation.h) on the AO
 * references' G-buffers, with results pooled over the scenes:
 *  - the spatio-temporal pattern (gtao_pattern.c): the 24-frame cycle,
 *    denoised, against the 96-direction brute force it stands for, and the
 *    talk's row order against Morton order;
 * Uncertainty: errors against a deterministic target (the brute force) are
 * means over 8x8-pixel blocks (metrics/block_mean.h) with their standard
 * error; rankings are paired differences of squared errors over the same
 * blocks, so a verdict can come out "not significant". */
#ifndef GTLAB_STUDIES_GTAO_SHORTCUTS_H
#define GTLAB_STUDIES_GTAO_SHORTCUTS_H

#include "core/error.h"
#include "metrics/block_mean.h"
#include "realtime/screen_space.h"

enum { GTAO_SHORTCUT_MAX_SCENES = 16 };

/* One scene as the gtao stage holds it. */
typedef struct {
    const char *name;
    const ss_gbuffer *g;
    const float *hf, *ref3d;      /* ao.V of the height-field and 3-D references */
    double hf_mean_variance;      /* mean ao.V stderr^2 of the height-field reference over the mask */
    double ref3d_mean_variance;
    float radius, max_radius_px;  /* the gtao stage's: no radius limit */
    int preview;                  /* preview quality: fewer runs */
} gtao_shortcut_scene;

/* Item 7: the pattern. Frames accumulated in the study: 1, 6, 24. */
enum { GTAO_PATTERN_RUNS = 3, GTAO_PATTERN_DIRECTIONS = 96 };
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
    block_mean cycle_se2;                          /* (24 frames denoised - brute force)^2 */
    block_mean order_difference[GTAO_PATTERN_RUNS]; /* (rows - brute)^2 - (Morton - brute)^2 */
    block_mean hf_variance;                        /* the height-field reference's stderr^2 */
    double cycle_rmse, cycle_rmse_se;              /* from cycle_se2 */
    double hf_noise_rmse;                          /* sqrt of the pooled mean stderr^2 */
} gtao_pattern_result;

typedef struct {
    gtao_pattern_result pattern;
} gtao_shortcuts_result;

/* Every shortcut study on one scene, its rows and pooled blocks added to r. */
int gtao_shortcuts_scene(const gtao_shortcut_scene *s, gtao_shortcuts_result *r, gt_error *e);
/* The pooled figures, after the last scene. */
void gtao_shortcuts_finish(gtao_shortcuts_result *r);

/* The studies, one file each. */
int gtao_pattern_scene_study(const gtao_shortcut_scene *s, gtao_pattern_result *r, gt_error *e);
void gtao_pattern_finish(gtao_pattern_result *r);

#endif
