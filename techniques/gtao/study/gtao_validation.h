/* GTAO (each preset, one frame and temporally converged), HBAO and volumetric
 * obscurance scored against the two references of the GTAO talk's
 * methodology, at the AO references' cameras and pixels (the `gtao` stage of
 * `gtlab all`):
 *  (a) the height-field Monte Carlo reference, rendered here: rays blocked
 *      only by the depth buffer taken as a height field of infinite
 *      thickness, what any screen-space technique could know; GTAO is exact
 *      for it, so its distance is the sampling/denoising error;
 *  (b) the 3-D ray-traced AO of the AO references: the distance adds the
 *      height-field assumption's error, which (a) vs (b) measures.
 * With both references' Monte Carlo noise taken out
 * (metrics/noise_corrected.h), the talk's configuration's squared error
 * splits into a sampling part (GTAO medium, one frame, vs (a)) and a
 * height-field part ((a) vs (b)). Plus the convergence of brute-force GTAO
 * with slices x steps on one scene, and GTAO's parameters fitted to the 3-D
 * references (gtao_params.h).
 *
 * Every technique runs with no radius limit (the references have none): the
 * screen radius is the image width, no falloff; VO, which needs a finite
 * sphere, takes a quarter of the camera's distance to its target.
 *
 * Writes <output>/gtao/<scene>_heightfield.exr, <output>/gtao/
 * gtao_convergence.dat and <output>/figures/gtao_err_{hf_vs_3d,medium_vs_hf,
 * medium_vs_3d}_<scene>.png (|error| from 0 to 0.25). */
#ifndef GTLAB_GTAO_GTAO_VALIDATION_H
#define GTLAB_GTAO_GTAO_VALIDATION_H

#include "gtao/gtao.h"
#include "gtao/gtao_params.h"
#include "gtao/gtao_params_fit.h"
#include "gtao/gtao_shortcuts.h"
#include "project/study_context.h"
#include "project/scene_list.h"

/* The folder below the output folder that holds the study's files. */
#define GTAO_VALIDATION_DIR "gtao"
/* The convergence data in it: one gnuplot data block per steps value (in
 * gtao_convergence_steps order, blocks separated by two blank lines), one
 * line per slices value: slices steps slices*steps rmse_vs_hf rmse_vs_3d. */
#define GTAO_CONVERGENCE_DATA "gtao_convergence.dat"
/* The scene of the convergence study. */
#define GTAO_CONVERGENCE_SCENE "boxes"

enum {
    GTAO_VALIDATION_MAX_SCENES = STUDY_SCENES_MAX,
    GTAO_VALIDATION_MAX_VARIANTS = 16, /* 13 at production quality */
    GTAO_CONVERGENCE_STEPS = 4,
    GTAO_CONVERGENCE_SLICES = 5
};
extern const int gtao_convergence_steps[GTAO_CONVERGENCE_STEPS];   /* 2, 4, 8, 16 per side */
extern const int gtao_convergence_slices[GTAO_CONVERGENCE_SLICES]; /* 1, 2, 4, 8, 16 */

typedef enum { AO_TECHNIQUE_GTAO, AO_TECHNIQUE_HBAO, AO_TECHNIQUE_VO } ao_technique_kind;

/* One technique variant on one scene, scored against both references. */
typedef struct {
    char scene[64];
    ao_technique_kind technique;
    int preset;     /* a gtao_preset_id (GTAO); -1 for HBAO (8 directions x 8 steps) and VO (4 samples) */
    int frames;     /* frames accumulated: 1, or the converged frame count */
    int converged;  /* the temporally accumulated run */
    char label[48]; /* "GTAO medium, 1 frame" */
    double dssim_hf, rmse_hf; /* against the height-field reference */
    double dssim_3d, rmse_3d; /* against the 3-D reference */
    double flip_3d;           /* mean LDR-FLIP against the 3-D reference (metrics/flip.h) */
    double ms_per_frame;      /* wall clock on this machine */
} ao_variant_row;

/* The error of the talk's configuration split with the references' noise
 * taken out: RMSE^2 = sampling^2 + model^2 in expectation, each part as the
 * noise-corrected RMSE (0: within the noise). */
typedef struct {
    int valid;                      /* 0 when GTAO medium (1 frame) or ultra (converged) was not run */
    double model_rmse;              /* height field vs 3-D, less both references' noise */
    double sampling_rmse;           /* GTAO medium, one frame (the talk's configuration) vs height field,
                                       less its noise */
    double converged_sampling_rmse; /* GTAO ultra, converged, vs height field, less its noise */
    int exact_valid;                /* brute-force GTAO (exact horizons) was run */
    double exact_rmse_hf;           /* its RMSE against the height field, noise included */
    double exact_sampling_rmse;     /* the same less the reference's noise (0: within it) */
    double hf_noise_rmse;           /* the height-field reference's noise, sqrt(mean stderr^2) */
    double sampling_percent, model_percent; /* shares of sampling^2 + model^2 */
} ao_error_split;

typedef struct {
    char scene[64];
    int variant_count;
    ao_variant_row variants[GTAO_VALIDATION_MAX_VARIANTS]; /* GTAO by preset, then HBAO, VO */
    double hf_vs_3d_rmse, hf_vs_3d_dssim; /* the height-field assumption's error (noise included) */
    double hf_noise_floor_dssim;          /* even vs odd samples of the height-field reference */
    double hf_mean_variance, ref3d_mean_variance; /* mean ao.V stderr^2 over the mask of each reference */
    ao_error_split split;
} gtao_validation_scene;

typedef struct {
    int slices, steps; /* regular slices, samples per side; no pattern, no denoiser */
    double rmse_hf, rmse_3d;
} gtao_convergence_row;

typedef struct {
    int heightfield_spp;  /* samples per pixel of the height-field references (the most, with a budget) */
    double heightfield_noise_budget; /* the standard error their pixels stop at (0: every pixel takes all) */
    int converged_frames; /* 24 (the talk's full cycle) or 6 at preview quality */
    int scene_count;
    gtao_validation_scene scenes[GTAO_VALIDATION_MAX_SCENES]; /* study_scene_at order */
    char convergence_scene[64]; /* GTAO_CONVERGENCE_SCENE, or a project's first scene */
    int convergence_count;
    gtao_convergence_row convergence[GTAO_CONVERGENCE_STEPS * GTAO_CONVERGENCE_SLICES]; /* by steps, then slices */
    gtao_fit_request fit_request; /* train/test point into fit_train/fit_test */
    char fit_train[GTAO_VALIDATION_MAX_SCENES * 48], fit_test[GTAO_VALIDATION_MAX_SCENES * 48];
    gtao_fit_result fit;
    gtao_shortcuts_result shortcuts; /* issue 25, items 6-8 (gtao_shortcuts.h) */
} gtao_validation_result;

typedef struct {
    const char *ao_references_dir; /* <scene>.exr AO references with their G-buffer and camera */
} gtao_validation_request;

/* The variant of `technique` and GTAO `preset` (-1 for HBAO and VO), one frame
 * or converged, or NULL if it was not run. */
const ao_variant_row *gtao_validation_find(const gtao_validation_scene *s, ao_technique_kind technique, int preset,
                                           int converged);

int gtao_validation_study(const study_context *ctx, const gtao_validation_request *rq, gtao_validation_result *out,
                          gt_error *e);

#endif
