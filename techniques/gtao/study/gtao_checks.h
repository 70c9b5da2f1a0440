/* The GTAO talk's shortcuts and baselines measured against the references
 * (issue 25, items 9-13): the five studies of the `gtao-shortcuts` stage in
 * one results struct. */
#ifndef GTLAB_GTAO_GTAO_CHECKS_H
#define GTLAB_GTAO_GTAO_CHECKS_H

#include "gtao/gtao_baselines.h"
#include "gtao/gtao_bent_normals.h"
#include "gtao/gtao_distance_fade.h"
#include "gtao/gtao_fast_math.h"
#include "gtao/gtao_thickness.h"
#include "gtao/vbao_study.h"

typedef struct {
    gtao_fast_math_result fast_math;
    gtao_baselines_result baselines;
    gtao_bent_normals_result bent;
    gtao_thickness_result thickness;
    gtao_distance_fade_result fade;
    vbao_study_result vbao; /* issue 27, item 1 */
} gtao_checks_result;

/* Runs the five studies in that order, then VBAO (with the sweep's best heuristic); -1 with e at the first failure. */
int gtao_checks_study(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_checks_result *out,
                      gt_error *e);

#endif
