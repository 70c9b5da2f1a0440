/* The GTAO talk's conservative distance fade (issue 25, item 12; seeds/001,
 * "Minimizing Artifacts": "150 inches of full effect, from 150 to 200
 * soften sample contribution from 1 to 0", "ensure ground truth near
 * occlusion") scored like for like: a 3-D reference whose occluders fade
 * the same way with distance (techniques/ao/ao_integrator.h, fade_start), with
 * the fade's end D a quarter of the camera's distance to its target and its
 * start 0.75 D (the talk's 150/200), rendered at the AO reference's camera.
 * GTAO (regular slices, no pattern or denoiser, `slices` x `steps` per
 * side) with radius D and falloff 0.25 is scored against it and against
 * the unbounded reference; the difference of the two squared errors per
 * pixel, (a - unbounded)^2 - (a - faded)^2, is the bias of scoring a faded
 * GTAO against the unbounded reference (8x8-block standard errors).
 * The fade's own change (issue 42): the talk's soft clamp against a hard
 * one at the same distance ("soft-clamp integration sampling distance"):
 * GTAO with the fade minus the same GTAO cut off hard at D (the same
 * samples, falloff 0), against the reference's same change (faded minus a
 * reference cut off hard at D); their mean difference is what the fade
 * does to GTAO that it does not do to the truth, free of GTAO's own error
 * at that radius. (Against GTAO with no radius limit the change would hold
 * that GTAO's sparser samples' error too.) */
#ifndef GTLAB_GTAO_GTAO_DISTANCE_FADE_H
#define GTLAB_GTAO_GTAO_DISTANCE_FADE_H

#include "gtao/gtao_fast_math.h"
#include "metrics/cluster_mean.h"
#include "project/scene_list.h"

enum { FADE_MAX_SCENES = STUDY_SCENES_MAX };

typedef struct {
    char scene[64];
    double fade_end, fade_start; /* world units */
    double rmse_faded, rmse_unbounded;  /* GTAO with the fade against each reference */
    cluster_mean signed_vs_faded;         /* mean (GTAO - faded reference) */
    cluster_mean reference_gap;           /* mean (faded - unbounded reference): what the fade leaves out */
    cluster_mean scoring_bias;            /* mean (a - unbounded)^2 - (a - faded)^2 */
    cluster_mean gtao_change;             /* mean (GTAO faded - GTAO cut off hard at D) */
    cluster_mean reference_change;        /* mean (faded - cut-off reference) */
    cluster_mean change_vs_truth;         /* mean (GTAO faded - GTAO cut off) - (faded - cut-off reference) */
} fade_row;

typedef struct {
    int slices, steps, spp, scene_count;
    fade_row rows[FADE_MAX_SCENES];
    cluster_mean pooled_signed_vs_faded, pooled_reference_gap, pooled_scoring_bias;
    cluster_mean pooled_gtao_change, pooled_change_vs_truth, pooled_reference_change;
} gtao_distance_fade_result;

int gtao_distance_fade_study(const study_context *ctx, const gtao_shortcuts_request *rq,
                             gtao_distance_fade_result *out, gt_error *e);

#endif
