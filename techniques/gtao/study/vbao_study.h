/* Visibility-bitmask AO (Therrien et al. 2023, vbao.h) beside GTAO
 * on the AO references' scenes (issue 27, item 1), run in the
 * `gtao-shortcuts` stage after the thickness heuristic's sweep:
 *  - the ranking: GTAO medium and high, GTAO medium with the heuristic at
 *    the sweep's best value, VBAO medium with the paper's choices and with
 *    gtlab's (cosine sectors, back face at depth + T), VBAO high (gtlab's),
 *    each one frame of the pattern with the 4x4 denoiser and no radius
 *    limit, scored against the 3-D reference and ranked by the paired
 *    difference of squared errors against GTAO medium (8x8-block standard
 *    error, metrics/cluster_mean.h);
 *  - VBAO's error split at its thickness T: the estimator's (VBAO medium,
 *    gtlab's choices, against the thickness-T height-field reference this
 *    study renders, techniques/ao/heightfield_ao_integrator.h) and the screen
 *    space's (that reference against the 3-D one), each less the
 *    references' noise, beside the infinite height field's;
 *  - the best constant thickness per scene: a golden-section search over
 *    log T of VBAO medium's MSE against the 3-D reference.
 * T is a fraction VBAO_THICKNESS_FRACTION of the camera's distance to its
 * target (the scenes' sizes differ; the paper gives no scale). Writes
 * <gtao_dir>/<scene>_heightfield_thickness.exr. */
#ifndef GTLAB_GTAO_VBAO_STUDY_H
#define GTLAB_GTAO_VBAO_STUDY_H

#include "gtao/ao_image_score.h"
#include "gtao/gtao_fast_math.h"
#include "metrics/cluster_mean.h"
#include "project/scene_list.h"

#define VBAO_THICKNESS_FRACTION 0.05
enum { VBAO_MAX_SCENES = STUDY_SCENES_MAX };

typedef enum {
    VBAO_ROW_GTAO_MEDIUM,
    VBAO_ROW_GTAO_HIGH,
    VBAO_ROW_GTAO_HEURISTIC,
    VBAO_ROW_PAPER_MEDIUM,
    VBAO_ROW_EXACT_MEDIUM,
    VBAO_ROW_EXACT_HIGH,
    VBAO_ROW_COUNT
} vbao_row_kind;
extern const char *const vbao_row_names[VBAO_ROW_COUNT];

typedef struct {
    char scene[64];
    char technique[48];
    ao_image_score score; /* rmse_hf: against the infinite height field */
    double ms_per_frame;
} vbao_row;

typedef struct {
    char scene[64];
    double thickness;          /* T, view-space units */
    double estimator_rmse;     /* VBAO medium (gtlab's) vs the thickness-T height field, less its noise */
    double screen_rmse;        /* the thickness-T height field vs 3-D, less both references' noise */
    double screen_rmse_infinite; /* the infinite height field vs 3-D, the same way */
    double best_thickness;     /* the search's T */
    double best_fraction;      /* of the camera distance */
    double best_mse_3d, default_mse_3d, infinite_mse_3d; /* VBAO medium at best T, at T, at infinity */
} vbao_split_row;

typedef struct {
    int scene_count, heightfield_spp;
    double heuristic_thickness; /* the GTAO heuristic's value in its row */
    vbao_row rows[VBAO_MAX_SCENES][VBAO_ROW_COUNT];
    vbao_split_row split[VBAO_MAX_SCENES];
    cluster_mean pooled_vs_gtao_3d[VBAO_ROW_COUNT];
    double pooled_rmse_3d[VBAO_ROW_COUNT];
} vbao_study_result;

/* heuristic: the GTAO thickness heuristic's value for its row. */
int vbao_study(const study_context *ctx, const gtao_shortcuts_request *rq, float heuristic, vbao_study_result *out,
               gt_error *e);

#endif
