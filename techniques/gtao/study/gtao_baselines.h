/* The baselines the GTAO talk cites beside HBAO and VO (issue 25, item 13):
 * Alchemy AO (McGuire et al. 2011, alchemy_ao.h) and CryENGINE 2's
 * SSAO (Mittring 2007, crytek_ssao.h), with the talk's "Possible
 * Pitfall" integrand (gtao_sin_n_pitfall.h) as a negative control.
 * Every technique runs one frame of the talk's pattern with the 4x4
 * denoiser, as gtao_validation runs HBAO and VO: GTAO medium, HBAO 8x8 (no
 * attenuation, no radius limit), VO 4 samples, Alchemy 12 samples and
 * Crytek 16 points (radius: a quarter of the camera's distance to its
 * target, as VO), and GTAO medium with the pitfall's integrand. Each is
 * scored against both references (RMSE, DSSIM), and ranked against GTAO
 * medium by the paired difference of squared errors against the 3-D
 * reference with its 8x8-block standard error (metrics/cluster_mean.h). */
#ifndef GTLAB_GTAO_GTAO_BASELINES_H
#define GTLAB_GTAO_GTAO_BASELINES_H

#include "gtao/ao_image_score.h"
#include "gtao/gtao_fast_math.h"
#include "metrics/cluster_mean.h"
#include "project/study_context.h"
#include "project/scene_list.h"

typedef enum {
    BASELINE_GTAO,
    BASELINE_HBAO,
    BASELINE_VO,
    BASELINE_ALCHEMY,
    BASELINE_CRYTEK,
    BASELINE_PITFALL,
    BASELINE_COUNT
} baseline_technique;
extern const char *const baseline_names[BASELINE_COUNT];

enum { BASELINES_MAX_SCENES = STUDY_SCENES_MAX };

typedef struct {
    char scene[64];
    char technique[48];
    ao_image_score score; /* vs_gtao_3d > 0 when worse than GTAO */
    double ms_per_frame;
} baseline_row;

typedef struct {
    int scene_count;
    baseline_row rows[BASELINES_MAX_SCENES][BASELINE_COUNT];
    cluster_mean pooled_vs_gtao_3d[BASELINE_COUNT]; /* pooled over scenes */
    double pooled_rmse_3d[BASELINE_COUNT];        /* sqrt of the pixel-weighted mean MSE */
} gtao_baselines_result;

int gtao_baselines_study(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_baselines_result *out,
                         gt_error *e);

#endif
