/* AO images against the scene's references; see ao_image_score.h. */
#include "gtao/ao_image_score.h"

#include <math.h>

#include "metrics/flip.h"
#include "metrics/image_error.h"
#include "metrics/ssim.h"

int ao_image_score_compute(const gtao_scene_refs *r, const float *ao, const float *gtao, ao_image_score *out,
                           gt_error *e)
{
    image_error_stats hf, r3;
    ssim_result ss;
    flip_result flip;
    hf.rmse = NAN;
    if ((r->hf_ao && image_error_compute(ao, r->hf_ao, r->mask, r->width, r->height, r->scene, &hf, e) != 0) ||
        image_error_compute(ao, r->ref3d, r->mask, r->width, r->height, r->scene, &r3, e) != 0 ||
        ssim_compute(ao, r->ref3d, r->mask, r->width, r->height, r->scene, NULL, &ss, e) != 0 ||
        flip_grey(r->ref3d, ao, r->mask, r->width, r->height, r->scene, NULL, &flip, e) != 0)
        return -1;
    out->rmse_hf = hf.rmse;
    out->rmse_3d = r3.rmse;
    out->mean_ao = r3.mean_a;
    out->dssim_3d = ss.dssim;
    out->flip_3d = flip.mean;
    if (cluster_mean_paired_sq_error(ao, gtao, r->ref3d, r->mask, r->width, r->height, CLUSTER_MEAN_SIDE,
                                     &out->vs_gtao_3d) != 0)
        return gt_error_set(e, r->scene, "out of memory");
    return 0;
}

void ao_image_score_pool(const ao_image_score *first, size_t stride, int count, cluster_mean *paired,
                         double *rmse_3d)
{
    cluster_mean parts[AO_IMAGE_SCORE_MAX_SCENES] = {{0}};
    double mse = 0.0;
    size_t pixels = 0;
    int n = count < AO_IMAGE_SCORE_MAX_SCENES ? count : AO_IMAGE_SCORE_MAX_SCENES;
    for (int s = 0; s < n; ++s) {
        const ao_image_score *x = (const ao_image_score *)((const char *)first + (size_t)s * stride);
        parts[s] = x->vs_gtao_3d;
        mse += x->rmse_3d * x->rmse_3d * (double)x->vs_gtao_3d.pixels;
        pixels += x->vs_gtao_3d.pixels;
    }
    *paired = cluster_mean_pool(parts, n);
    *rmse_3d = pixels ? sqrt(mse / (double)pixels) : 0.0;
}
