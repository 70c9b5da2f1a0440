/* The parts of multibounce/multibounce_study.c kept in their own files: what they
 * share (the study's working state), the validation and the plot data.
 * Internal to the technique's study. */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_PARTS_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_PARTS_H

#include "multibounce/multibounce_study.h"
#include "multibounce/multibounce_quantity.h"
#include "raytracer/reference_render.h"

typedef struct {
    image refs[MULTIBOUNCE_STUDY_SCENES];
    image halves[MULTIBOUNCE_STUDY_SCENES][2]; /* means of the even- and odd-index samples */
    int rendered[MULTIBOUNCE_STUDY_SCENES], split[MULTIBOUNCE_STUDY_SCENES];
    multibounce_plan plan; /* the channel names */
    multibounce_data data;
    multibounce_analysis *analysis;
} multibounce_state;

/* DSSIM and RMSE of `approx` against `target` over the mask, images of
 * img's size (multibounce_validation.c; also the user's functions,
 * multibounce_score.c). `what` names them in errors. */
int multibounce_score_images(const float *approx, const float *target, const float *mask, const image *img,
                             const char *what, double *dssim, double *rmse, gt_error *e);

/* The validation rows of every scene and albedo and their mean
 * (multibounce_validation.c); scene k is scenes[k], albedo a albedos[a]. */
int multibounce_validate(const multibounce_state *st, const char *const *scenes, const float *albedos,
                         multibounce_study_result *out, gt_error *e);

/* MULTIBOUNCE_SCATTER_DATA, MULTIBOUNCE_CURVES_DATA and
 * MULTIBOUNCE_COEFFICIENTS_DATA into the folder `figures`
 * (multibounce_plot_data.c). */
int multibounce_write_plot_data(const multibounce_data *d, const multibounce_analysis *a, const char *figures,
                                gt_error *e);

/* out->clamp from the data and their analysis (multibounce_clamp.c). */
int multibounce_study_clamp(const multibounce_data *d, const multibounce_analysis *a, multibounce_clamp *out,
                            gt_error *e);

/* out->bounce_counts: renders scenes[0..MULTIBOUNCE_STUDY_SCENES) as `req`
 * but for the bounce count, reuses st->data for 4 (multibounce_bounces.c). */
int multibounce_study_bounces(const study_context *ctx, const reference_request *req, const multibounce_state *st,
                              const char *const *scenes, multibounce_bounce_study *out, gt_error *e);

/* out->gtao_input: GTAO run on the G-buffer of each reference written to
 * <output>/MULTIBOUNCE_STUDY_DIR/<scene>.exr, and the height-field
 * multi-bounce reference rendered at its camera as req (written to
 * <output>/MULTIBOUNCE_HEIGHTFIELD_DIR/<scene>.exr; multibounce_gtao.c). */
int multibounce_study_gtao(const study_context *ctx, const reference_request *req, const multibounce_state *st,
                           const char *const *scenes, multibounce_gtao_study *out, gt_error *e);

/* out->contrast (multibounce_contrast.c); the uniform references are
 * st's scenes `scenes` at albedos `albedos` (their count MULTIBOUNCE_STUDY_ALBEDOS). */
int multibounce_study_contrast(const study_context *ctx, const reference_request *req, const multibounce_state *st,
                               const char *const *scenes, const float *albedos, multibounce_contrast_study *out,
                               gt_error *e);

/* `spec` loaded with its floor (mesh 0) of base colour floor_rgb and every
 * other mesh of objects_rgb: two new materials copied from the floor's
 * (multibounce_two_albedos.c; the contrast and colour scenes). */
int multibounce_load_two_albedo_scene(const char *spec, const float floor_rgb[3], const float objects_rgb[3],
                                      scene *s, gt_error *e);

/* out->colour (multibounce_colour.c). */
int multibounce_study_colour(const study_context *ctx, const reference_request *req, multibounce_colour_study *out,
                             gt_error *e);

#endif
