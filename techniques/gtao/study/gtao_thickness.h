/* The GTAO talk's thickness heuristic (issue 25, item 11; seeds/001,
 * "Thickness Heuristic": "assume object thickness similar to screen space
 * width", "conservative with architectural features such as 90 degree
 * corners"): GTAO with regular slices and no pattern or denoiser (`slices`
 * x `steps` per side, no radius limit) at thickness 0 (the height field of
 * infinite thickness, which GTAO then reproduces) and at each value of a
 * sweep. Per scene and value: the MSE against the 3-D reference, the
 * paired difference against thickness 0 (8x8-block standard error), and
 * the share of thickness 0's error against the 3-D reference (the height
 * field's error, less the reference's noise) it removes, and its own change
 * AO(thickness) - AO(0) (issue 42). The corner scene
 * holds the talk's 90 degree corners. */
#ifndef GTLAB_GTAO_GTAO_THICKNESS_H
#define GTLAB_GTAO_GTAO_THICKNESS_H

#include "gtao/gtao_fast_math.h"
#include "metrics/cluster_mean.h"
#include "project/scene_list.h"

enum { THICKNESS_VALUES = 4, THICKNESS_MAX_SCENES = STUDY_SCENES_MAX };
extern const float gtao_thickness_values[THICKNESS_VALUES]; /* 0.05, 0.1, 0.25, 0.5 */

typedef struct {
    char scene[64];
    double thickness;
    double mse_3d, mse_hf;
    cluster_mean vs_none_3d;  /* MSE(thickness) - MSE(0) against the 3-D reference */
    cluster_mean change;      /* the heuristic's own change, mean AO(thickness) - AO(0) */
    cluster_mean codes;       /* pixels whose 8-bit code it changes */
    double removed_percent; /* -vs_none_3d.mean / (MSE(0) - reference variance), in % */
} thickness_row;

typedef struct {
    int slices, steps, scene_count;
    double mse_none_3d[THICKNESS_MAX_SCENES], mse_none_hf[THICKNESS_MAX_SCENES];
    thickness_row rows[THICKNESS_MAX_SCENES][THICKNESS_VALUES];
    cluster_mean pooled_vs_none_3d[THICKNESS_VALUES];
    int best;          /* the value with the lowest pooled paired difference (the least harmful if all hurt) */
    int corner_scene;  /* index of "corner", or -1 */
} gtao_thickness_result;

int gtao_thickness_study(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_thickness_result *out,
                         gt_error *e);

#endif
