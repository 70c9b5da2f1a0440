/* One real-time AO image scored against a scene's two references
 * (gtao_scene_refs.h), the figures every AO ranking of the GTAO and
 * VBAO sections shows:
 *   rmse_hf   RMSE against the height-field reference (the estimator's error;
 *             NaN when the scene's refs have none, gtao_scene_refs_load_3d);
 *   rmse_3d   RMSE against the 3-D reference (what a viewer sees);
 *   dssim_3d  DSSIM against the 3-D reference (metrics/ssim.h);
 *   flip_3d   mean LDR-FLIP against the 3-D reference (metrics/flip.h: AO is
 *             in [0, 1], a grey image; the reference is FLIP's reference);
 *   vs_gtao_3d  the paired difference (AO - 3-D)^2 - (GTAO medium - 3-D)^2
 *             with its 8x8-block standard error (metrics/cluster_mean.h):
 *             < 0 where the technique is closer to the truth than GTAO.
 * All over the scene's mask. Pooled over scenes, the paired differences pool
 * as clusters and the RMSE is the square root of the pixel-weighted mean
 * square. */
#ifndef GTLAB_GTAO_AO_IMAGE_SCORE_H
#define GTLAB_GTAO_AO_IMAGE_SCORE_H

#include <stddef.h>

#include "gtao/gtao_scene_refs.h"
#include "metrics/cluster_mean.h"

enum { AO_IMAGE_SCORE_MAX_SCENES = 64 }; /* pooled at most */

typedef struct {
    double rmse_hf, rmse_3d, mean_ao, dssim_3d, flip_3d;
    cluster_mean vs_gtao_3d;
} ao_image_score;

/* Scores ao against r, paired with gtao (GTAO medium on the same scene).
 * Returns 0, or -1 with e (out of memory). */
int ao_image_score_compute(const gtao_scene_refs *r, const float *ao, const float *gtao, ao_image_score *out,
                           gt_error *e);

/* One technique's scores over `count` scenes, the k-th at
 * (const char *)first + k stride: the pooled paired difference and RMSE. */
void ao_image_score_pool(const ao_image_score *first, size_t stride, int count, cluster_mean *paired,
                         double *rmse_3d);

#endif
