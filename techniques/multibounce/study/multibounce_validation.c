/* Validation of the multi-bounce models against the references. Every
 * approximation takes V_d from the even-sample half and is scored against
 * V'_d of the odd-sample half: V_d and V'_d of one half come from the same
 * paths, and their shared noise would let an approximation score below the
 * reference's noise floor. The floors are the two halves of V'_d scored
 * against each other, so every figure has the same noise in it. */
#include <stdio.h>
#include <stdlib.h>

#include "core/reference_schema.h"
#include "metrics/image_error.h"
#include "metrics/ssim.h"
#include "multibounce/multibounce_parts.h"

void multibounce_apply_model(const multibounce_model *m, const float *visibility, const float *mask, size_t n,
                             float albedo, float *out)
{
    for (size_t i = 0; i < n; ++i)
        out[i] = mask[i] != 0.0f ? (float)gtao_multibounce(m, visibility[i], albedo) : 0.0f;
}

int multibounce_score_images(const float *approx, const float *target, const float *mask, const image *img,
                             const char *what, double *dssim, double *rmse, gt_error *e)
{
    ssim_result s;
    image_error_stats err;
    if (ssim_compute(approx, target, mask, img->width, img->height, what, NULL, &s, e) != 0 ||
        image_error_compute(approx, target, mask, img->width, img->height, what, &err, e) != 0)
        return -1;
    *dssim = s.dssim;
    *rmse = err.rmse;
    return 0;
}

/* The talk's model, our joint fit and our fit without scene k, each fed V_d
 * of the even half, scored against `target` (V'_d of the odd half). */
static int score_models(const multibounce_state *st, int k, float albedo, const float *target, const char *what,
                        multibounce_validation_row *v, gt_error *e)
{
    const image *img = &st->refs[k];
    const float *mask = image_channel_data(img, CH_MASK), *vd = image_channel_data(&st->halves[k][0], CH_AO);
    const multibounce_model talk = multibounce_model_jimenez2016();
    const multibounce_model *models[3] = {&talk, &st->analysis->joint[MB_JOINT_LINEAR].model,
                                          &st->analysis->heldout[k].model[MB_JOINT_LINEAR]};
    double *dssim[3] = {&v->dssim_talk, &v->dssim_ours, &v->dssim_ours_held_out};
    double *rmse[3] = {&v->rmse_talk, &v->rmse_ours, &v->rmse_ours_held_out};
    size_t n = image_pixel_count(img);
    float *approx = malloc(n * sizeof *approx);
    if (!approx)
        return gt_error_set(e, what, "out of memory");
    int rc = 0;
    for (int m = 0; m < 3 && rc == 0; ++m) {
        multibounce_apply_model(models[m], vd, mask, n, albedo, approx);
        rc = multibounce_score_images(approx, target, mask, img, what, dssim[m], rmse[m], e);
    }
    free(approx);
    return rc;
}

/* Scene k at albedo index a: the floors, V_d alone, and the models. */
static int validate(const multibounce_state *st, int k, int a, const char *scene, float albedo,
                    multibounce_validation_row *v, gt_error *e)
{
    const image *img = &st->refs[k], *even = &st->halves[k][0], *odd = &st->halves[k][1];
    const char *channel = st->plan.quantities[a].name;
    char what[256];
    snprintf(what, sizeof what, "%s %s", scene, channel);
    snprintf(v->scene, sizeof v->scene, "%s", scene);
    v->albedo = (double)albedo;
    const float *mask = image_channel_data(img, CH_MASK), *target = image_channel_data(odd, channel);
    if (multibounce_score_images(image_channel_data(even, channel), target, mask, img, what, &v->noise_floor_dssim,
              &v->noise_floor_rmse, e) != 0 ||
        multibounce_score_images(image_channel_data(even, CH_AO), target, mask, img, what, &v->dssim_v_d,
                                 &v->rmse_v_d, e) != 0)
        return -1;
    return score_models(st, k, albedo, target, what, v, e);
}

/* mean += row / count, field by field. */
static void add_to_mean(multibounce_validation_row *mean, const multibounce_validation_row *v, int count)
{
    mean->noise_floor_dssim += v->noise_floor_dssim / count;
    mean->noise_floor_rmse += v->noise_floor_rmse / count;
    mean->dssim_v_d += v->dssim_v_d / count;
    mean->dssim_talk += v->dssim_talk / count;
    mean->dssim_ours += v->dssim_ours / count;
    mean->dssim_ours_held_out += v->dssim_ours_held_out / count;
    mean->rmse_v_d += v->rmse_v_d / count;
    mean->rmse_talk += v->rmse_talk / count;
    mean->rmse_ours += v->rmse_ours / count;
    mean->rmse_ours_held_out += v->rmse_ours_held_out / count;
}

int multibounce_validate(const multibounce_state *st, const char *const *scenes, const float *albedos,
                         multibounce_study_result *out, gt_error *e)
{
    const int count = MULTIBOUNCE_STUDY_SCENES * MULTIBOUNCE_STUDY_ALBEDOS;
    multibounce_validation_row *mean = &out->validation_mean;
    *mean = (multibounce_validation_row){.scene = "mean"};
    out->validation_count = 0;
    for (int k = 0; k < MULTIBOUNCE_STUDY_SCENES; ++k)
        for (int a = 0; a < MULTIBOUNCE_STUDY_ALBEDOS; ++a) {
            multibounce_validation_row *v = &out->validation[out->validation_count];
            if (validate(st, k, a, scenes[k], albedos[a], v, e) != 0)
                return -1;
            ++out->validation_count;
            add_to_mean(mean, v, count);
        }
    return 0;
}
