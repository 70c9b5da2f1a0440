/* The GTAO talk's bent-normal estimators against the 3-D reference's bent
 * normal (issue 25, item 10; seeds/001, "Bent Normal"):
 *   horizon vectors: b = 0.5 (h1_vec + h2_vec) per slice, summed
 *                    (gtao_bent_horizons.h);
 *   halfway angles:  "or faster: average both horizon angles and recover
 *                    3d vector", each slice weighted by its visibility
 *                    (gtao_render, bent_halfway = 1);
 *   arc mean:        gtlab's exact cosine-weighted mean direction of each
 *                    slice's visible arc (bent_halfway = 0), the reference's
 *                    own definition restricted to the height field.
 * GTAO runs with regular slices and no pattern or denoiser (`slices` x
 * `steps` per side, no radius limit), so the estimators see the same
 * horizons. Per scene: the distribution of the angle between each
 * estimate and the reference's bent normal (mean with its 8x8-block
 * standard error, median, 90th percentile, degrees), and each talk
 * estimator's paired difference of angle against the arc mean. The
 * reference's bent normal is a Monte Carlo mean, so the angles include its
 * noise; the paired differences cancel most of it. */
#ifndef GTLAB_GTAO_GTAO_BENT_NORMALS_H
#define GTLAB_GTAO_GTAO_BENT_NORMALS_H

#include "gtao/gtao_fast_math.h"
#include "metrics/cluster_mean.h"
#include "project/scene_list.h"

typedef enum { BENT_HORIZON_VECTORS, BENT_HALFWAY_ANGLES, BENT_ARC_MEAN, BENT_ESTIMATORS } bent_estimator;
extern const char *const bent_estimator_names[BENT_ESTIMATORS];

enum { BENT_MAX_SCENES = STUDY_SCENES_MAX };

typedef struct {
    char scene[64];
    char estimator[48];
    cluster_mean angle;        /* degrees */
    double median, p90;      /* degrees */
    cluster_mean vs_arc_mean;  /* angle minus the arc mean's angle, degrees (0 for the arc mean) */
} bent_row;

typedef struct {
    int slices, steps;
    int scene_count;
    bent_row rows[BENT_MAX_SCENES][BENT_ESTIMATORS];
    cluster_mean halfway_vs_horizons[BENT_MAX_SCENES]; /* angle(halfway angles) - angle(horizon vectors), degrees */
    cluster_mean pooled_halfway_vs_horizons;
    cluster_mean pooled_angle[BENT_ESTIMATORS], pooled_vs_arc_mean[BENT_ESTIMATORS];
} gtao_bent_normals_result;

int gtao_bent_normals_study(const study_context *ctx, const gtao_shortcuts_request *rq, gtao_bent_normals_result *out,
                            gt_error *e);

#endif
