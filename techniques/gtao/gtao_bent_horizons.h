/* The GTAO talk's first bent-normal estimator (seeds/001, "Bent Normal"):
 *
 *     b = 0.5 (h1_vec + h2_vec)
 *
 * per slice, h_vec the unit vector towards horizon h in the slice (angle h
 * from the view vector v towards the slice's side vector), summed over the
 * slices (each weighted by d psi / d phi, gtao_slice_weight) and
 * normalised. By the sum-to-product identities
 *     0.5 (h1_vec + h2_vec) = cos((h2 - h1) / 2) * dir((h1 + h2) / 2),
 * each slice points halfway between its horizons (the talk's faster
 * estimator, gtao_bent_halfway_angle) with length cos of half the open
 * angle: a slice open over its whole half-circle contributes nothing, so
 * the most occluded slices steer the sum. gtlab's other two estimators are
 * in gtao_render: the halfway direction weighted by the slice's visibility
 * (bent_halfway = 1) and the exact cosine-weighted mean direction of the
 * visible arc (bent_halfway = 0), which is the reference's definition. */
#ifndef GTLAB_GTAO_GTAO_BENT_HORIZONS_H
#define GTLAB_GTAO_GTAO_BENT_HORIZONS_H

#include "gtao/gtao.h"

/* 0.5 (h1_vec + h2_vec) as components along v (bv) and along the side (bs). */
void gtao_bent_horizon_average(float h1, float h2, float *bv, float *bs);

/* One frame (p's slices, steps, pattern; no denoiser): the world-space
 * bent normal by the horizon-vector average in bent[0..2]; the pixel's
 * normal where the sum vanishes (every slice open), 0 on the background. */
void gtao_bent_horizons_frame(const ss_gbuffer *g, const gtao_params *p, int frame, float *const *bent);

#endif
