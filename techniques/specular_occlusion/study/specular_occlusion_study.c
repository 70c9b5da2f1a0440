#include "specular_occlusion/specular_occlusion_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "project/gbuffer_input.h"
#include "core/files/image_io.h"
#include "core/statistics/mc_film.h"
#include "core/progress.h"
#include "core/reference_schema.h"
#include "core/optics/spherical_caps.h"
#include "metrics/flip.h"
#include "metrics/image_error.h"
#include "metrics/ssim.h"
#include "raytracer/reference_render.h"
#include "specular_occlusion/specular_occlusion_integrator.h"
#include "specular_occlusion/specular_occlusion_quality.h"
#include "specular_occlusion/specular_occlusion_quantity.h"
#include "gtao/gtao.h"
#include "gtao/gtao_bent_horizons.h"
#include "project/scene_list.h"
#include "specular_occlusion/specular_occlusion_inputs.h"
#include "specular_occlusion/specular_occlusion_rankings.h"

enum { LUT_SIZES = 3, BC4_SIZES = 2, CASES_MAX = SO_STUDY_MAX_SCENES * SO_STUDY_ROUGHNESSES };
static const char *const definition_channels[SO_STUDY_DEFINITIONS] = {CH_SPECOCC, CH_SPECOCC_D, CH_SPECOCC_PHONG};
static const char *const definition_names[SO_STUDY_DEFINITIONS] = {"gtso", "d_only", "phong"};
enum { DEFINITION_GTSO, DEFINITION_D_ONLY, DEFINITION_PHONG }; /* indices of the two arrays above */
const float so_study_roughness_values[SO_STUDY_ROUGHNESSES] = {0.25f, 0.5f, 0.8f};
static const int lut_sizes[LUT_SIZES] = {16, 32, 64};

/* What the study holds while it runs: the tables the LUT variants read, the
 * variants themselves, sums over the scenes, and the fit cases (with their
 * own copy of the reference channel: the reference image is freed). */
typedef struct {
    const study_context *ctx;
    so_study_result *out;
    char figures[2048];
    so_lut luts[LUT_SIZES], lut_cosines, bc4[BC4_SIZES]; /* bc4[s]: luts[s] as shipped */
    so_variant variants[SO_STUDY_MAX_VARIANTS];
    int heatmaps[SO_STUDY_HEATMAPS];
    double dssim[SO_STUDY_MAX_VARIANTS][SO_STUDY_ROUGHNESSES], rmse[SO_STUDY_MAX_VARIANTS][SO_STUDY_ROUGHNESSES];
    double flip[SO_STUDY_MAX_VARIANTS][SO_STUDY_ROUGHNESSES];
    double case_dssim[SO_STUDY_MAX_VARIANTS][CASES_MAX]; /* per scored case, for paired differences */
    so_lut lut_phong;                              /* the talk's setting's cone/lobe table, 32^3 angles */
    so_ranking_scores ranking[SO_SETTINGS];        /* the rankings' variants in each setting */
    so_cone_view_scores cone_view;
    double silhouette_fraction_sum;
    int scored;
    double floor_dssim[SO_STUDY_ROUGHNESSES];
    double split_dssim[2][SO_STUDY_ROUGHNESSES], split_rmse[2][SO_STUDY_ROUGHNESSES], split_floor[SO_STUDY_ROUGHNESSES];
    aperture_case cases[SO_STUDY_DEFINITIONS][CASES_MAX];
    float *owned[SO_STUDY_DEFINITIONS][CASES_MAX];
    int case_count;
    double samples_per_second_sum;
    int renders;
} so_state;

/* ---- the rows ------------------------------------------------------------------ */

int so_study_find(const so_study_result *r, so_variant_kind kind, so_aperture_mapping mapping, int lut_size,
                  so_lut_axes lut_axes, int on_gtao)
{
    for (int i = 0; i < r->variant_count; ++i) {
        const so_variant_row *v = &r->variants[i];
        int cone = kind == SO_VARIANT_CONE_EXACT || kind == SO_VARIANT_CONE_OAT || kind == SO_VARIANT_CONE_HORIZON;
        int lut = kind == SO_VARIANT_LUT;
        if (v->kind == kind && v->on_gtao == on_gtao && (!cone || v->mapping == mapping) &&
            (!lut || (v->lut_size == lut_size && v->lut_axes == lut_axes && !v->lut_bc4)))
            return i;
    }
    return -1;
}

int so_study_find_bc4(const so_study_result *r, int lut_size)
{
    for (int i = 0; i < r->variant_count; ++i)
        if (r->variants[i].lut_bc4 && r->variants[i].lut_size == lut_size && !r->variants[i].on_gtao)
            return i;
    return -1;
}

void so_study_heatmap_rows(const so_study_result *r, int rows[SO_STUDY_HEATMAPS])
{
    rows[0] = so_study_find(r, SO_VARIANT_AO, 0, 0, 0, 0);
    rows[1] = so_study_find(r, SO_VARIANT_LAGARDE, 0, 0, 0, 0);
    rows[2] = so_study_find(r, SO_VARIANT_CONE_EXACT, SO_APERTURE_EXP2_ALPHA, 0, 0, 0);
    rows[3] = so_study_find(r, SO_VARIANT_LUT, 0, 32, SO_AXES_ANGLES, 0);
}

void so_study_best_variants(const so_study_result *r, int *best, int *runner_up)
{
    *best = 0;
    for (int v = 0; v < r->variant_count; ++v)
        if (!r->variants[v].on_gtao && r->variants[v].mean_dssim < r->variants[*best].mean_dssim)
            *best = v;
    *runner_up = *best == 0 ? 1 : 0;
    for (int v = 0; v < r->variant_count; ++v)
        if (!r->variants[v].on_gtao && v != *best && r->variants[v].mean_dssim < r->variants[*runner_up].mean_dssim)
            *runner_up = v;
}

/* A variant from its text (so_variant_parse), with its table and input. */
static void add_variant(so_state *st, const char *text, const so_lut *lut, int on_gtao)
{
    so_variant_row *row = &st->out->variants[st->out->variant_count];
    so_variant *v = &st->variants[st->out->variant_count++];
    so_variant_parse(text, v);
    v->lut = lut;
    row->kind = v->kind, row->mapping = v->mapping, row->weighting = v->weighting, row->on_gtao = on_gtao;
    row->lut_size = lut ? lut->size : 0, row->lut_axes = lut ? lut->axes : SO_AXES_ANGLES;
    row->lut_bc4 = lut ? lut->bc4 : 0;
    so_variant_label(v, row->label, sizeof row->label);
    if (lut && lut->axes == SO_AXES_COSINES)
        strcat(row->label, "-cosines");
    if (lut && lut->bc4)
        strcat(row->label, "-bc4");
    static const char *const gtao_labels[SO_GTAO_INPUTS + 1] = {"", " on GTAO", " on GTAO (bent: halfway angles)",
                                                                " on GTAO (bent: horizon vectors)"};
    strcat(row->label, gtao_labels[on_gtao]);
}

/* ao, lagarde, 4 cone-exact, 4 cone-oat, the LUTs (16, 32, [64], 32
 * cosines), 2 cone-horizon (not the talk's), the LUTs 16 and 32 in BC4, sg (Unity HDRP's spherical Gaussians), then
 * ao, lagarde, cone-exact:exp2-alpha, lut 32 and sg on GTAO, and lut 32 on GTAO with the talk's two bent normals. */
static void setup_variants(so_state *st)
{
    static const char *const cones[] = {"drobot", "uludag", "exp2-alpha", "exp2-perceptual"};
    add_variant(st, "ao", NULL, 0);
    add_variant(st, "lagarde", NULL, 0);
    char text[64];
    for (int kind = 0; kind < 2; ++kind)
        for (int m = 0; m < 4; ++m) {
            snprintf(text, sizeof text, "%s:%s", kind ? "cone-oat" : "cone-exact", cones[m]);
            add_variant(st, text, NULL, 0);
        }
    for (int s = 0; s < LUT_SIZES; ++s)
        if (st->luts[s].data)
            add_variant(st, "lut", &st->luts[s], 0);
    add_variant(st, "lut", &st->lut_cosines, 0);
    add_variant(st, "cone-horizon:exp2-alpha", NULL, 0);
    add_variant(st, "cone-horizon:exp2-perceptual", NULL, 0);
    for (int s = 0; s < BC4_SIZES; ++s)
        add_variant(st, "lut", &st->bc4[s], 0);
    add_variant(st, "sg", NULL, 0);
    add_variant(st, "ao", NULL, 1);
    add_variant(st, "lagarde", NULL, 1);
    add_variant(st, "cone-exact:exp2-alpha", NULL, 1);
    add_variant(st, "lut", &st->luts[1], 1);
    add_variant(st, "sg", NULL, 1);
    add_variant(st, "lut", &st->luts[1], SO_GTAO_HALFWAY);
    add_variant(st, "lut", &st->luts[1], SO_GTAO_HORIZON_VECTORS);
    so_study_heatmap_rows(st->out, st->heatmaps);
}

/* ---- the LUTs ------------------------------------------------------------------ */

/* Builds one table into lut and measures it into row. */
static int build_lut(so_state *st, so_lut *lut, int size, so_lut_axes axes, so_lut_row *row, gt_error *e)
{
    double t0 = seconds_now();
    if (so_lut_build(lut, size, SO_LOBE_GGX, axes, st->ctx->threads) != 0)
        return gt_error_set(e, "specular-occlusion LUT", "out of memory");
    row->seconds = seconds_now() - t0;
    so_lut_interpolation_error(lut, st->out->lut_points, 1u, st->ctx->threads, &row->max_interpolation_error,
                               &row->rms_interpolation_error);
    row->size = size, row->axes = axes, row->axes_name = so_lut_axes_name(axes), row->format = "float";
    row->quadrature_error = lut->max_error_estimate;
    return 0;
}

/* The table `src` as shipped in BC4 into lut, measured into row. */
static int ship_lut_bc4(so_state *st, const so_lut *src, so_lut *lut, so_lut_row *row, gt_error *e)
{
    double t0 = seconds_now();
    if (so_lut_bc4(src, lut) != 0)
        return gt_error_set(e, "specular-occlusion LUT", "out of memory");
    row->seconds = seconds_now() - t0;
    so_lut_interpolation_error(lut, st->out->lut_points, 1u, st->ctx->threads, &row->max_interpolation_error,
                               &row->rms_interpolation_error);
    row->size = lut->size, row->axes = lut->axes, row->axes_name = so_lut_axes_name(lut->axes), row->format = "BC4";
    row->quadrature_error = lut->max_error_estimate;
    return 0;
}

/* Whether the sweep builds the table of that size in that parametrisation:
 * the cosines at the sizes below 64^3 (which takes ~10 s on 2 cores), the
 * angles at the first angles_lut_sizes of 16, 32, 64 (the quality table). */
static int lut_is_built(const so_state *st, int size_index, so_lut_axes axes)
{
    if (axes == SO_AXES_COSINES)
        return lut_sizes[size_index] < 64;
    return size_index < specular_occlusion_quality_of(st->ctx->quality)->angles_lut_sizes;
}

/* Every size in both parametrisations; the angles tables and the 32^3
 * cosines one are kept for the variants. */
static int build_luts(so_state *st, gt_error *e)
{
    st->out->lut_points = specular_occlusion_quality_of(st->ctx->quality)->lut_error_points;
    for (int s = 0; s < LUT_SIZES; ++s)
        for (int axes = 0; axes < SO_AXES_COUNT; ++axes) {
            if (!lut_is_built(st, s, (so_lut_axes)axes))
                continue;
            so_lut scratch, *lut = axes == SO_AXES_ANGLES ? &st->luts[s] : lut_sizes[s] == 32 ? &st->lut_cosines : &scratch;
            if (build_lut(st, lut, lut_sizes[s], (so_lut_axes)axes, &st->out->luts[st->out->lut_count++], e) != 0)
                return -1;
            if (lut == &scratch)
                so_lut_free(&scratch);
        }
    for (int s = 0; s < BC4_SIZES; ++s) /* 16 and 32, as the talk ships them */
        if (ship_lut_bc4(st, &st->luts[s], &st->bc4[s], &st->out->luts[st->out->lut_count++], e) != 0)
            return -1;
    /* the talk's setting: its comparisons used Phong lobes */
    if (so_lut_build(&st->lut_phong, 32, SO_LOBE_PHONG, SO_AXES_ANGLES, st->ctx->threads) != 0)
        return gt_error_set(e, "specular-occlusion LUT", "out of memory");
    so_ranking_scores_init(&st->ranking[SO_SETTING_TALK], &st->lut_phong);
    so_ranking_scores_init(&st->ranking[SO_SETTING_GTSO], &st->luts[1]);
    st->cone_view.lut = &st->luts[1], st->cone_view.strata = 24;
    return 0;
}

/* ---- scoring ------------------------------------------------------------------- */

/* The noise floor of a ratio channel: DSSIM between the ratios of the even
 * and of the odd samples' means. */
int so_study_ratio_noise_floor(const image *ref, const char *what, const char *channel, double *dssim, double *rmse,
                               gt_error *e)
{
    mc_film film;
    if (mc_film_read_channels(ref, what, &film, e) != 0)
        return -1;
    image half[2];
    int rc = 0;
    for (int h = 0; h < 2; ++h) {
        if (image_init(&half[h], ref->width, ref->height) != 0 || mc_film_write_half_means(&film, h, &half[h]) != 0 ||
            specular_occlusion_write_ratios(&half[h]) != 0)
            rc = gt_error_set(e, what, "out of memory");
    }
    const float *mask = image_channel_data(ref, CH_MASK);
    if (rc == 0) {
        float *a = image_channel_data(&half[0], channel), *b = image_channel_data(&half[1], channel);
        for (size_t i = 0; i < image_pixel_count(ref); ++i)
            if (mask[i] == 0.0f)
                a[i] = b[i] = 0.0f;
        ssim_result r;
        image_error_stats err;
        rc = ssim_compute(a, b, mask, ref->width, ref->height, what, NULL, &r, e);
        *dssim = r.dssim;
        if (rc == 0 && rmse && (rc = image_error_compute(a, b, mask, ref->width, ref->height, what, &err, e)) == 0)
            *rmse = err.rmse;
    }
    image_free(&half[0]);
    image_free(&half[1]);
    mc_film_free(&film);
    return rc;
}

/* The |error| heatmap (inferno, 0 to 0.5) and FLIP map (magma, 0 to 1, with
 * a colour bar) of one variant against the reference V_s (vs),
 * figures/specocc_{err,flip}_<name>_<suffix>.png. */
static int write_variant_maps(const so_state *st, const float *vs, const so_pixel_inputs *in, const char *name,
                              int variant, const char *suffix, gt_error *e)
{
    char path[4096];
    size_t n = (size_t)in->width * (size_t)in->height;
    float *approx = malloc(sizeof(float) * n), *err = malloc(sizeof(float) * n);
    int rc = approx && err ? 0 : gt_error_set(e, name, "out of memory");
    if (rc == 0) {
        so_approx_evaluate(in, &st->variants[variant], approx);
        for (size_t i = 0; i < n; ++i)
            err[i] = fabsf(approx[i] - vs[i]);
        snprintf(path, sizeof path, "%s/specocc_err_%s_%s.png", st->figures, name, suffix);
        rc = image_write_heatmap(path, err, in->mask, in->width, in->height, 0.5f, "inferno", e);
    }
    flip_result f;
    rc = rc == 0 ? flip_grey(vs, approx, in->mask, in->width, in->height, name, err, &f, e) : rc;
    snprintf(path, sizeof path, "%s/specocc_flip_%s_%s.png", st->figures, name, suffix);
    rc = rc == 0 ? image_write_heatmap(path, err, in->mask, in->width, in->height, 1.0f, "magma", e) : rc;
    free(approx);
    free(err);
    return rc;
}

/* The reference V_s, and the maps of the heatmap rows (write_variant_maps). */
static int write_heatmaps(const so_state *st, const image *ref, const so_pixel_inputs *in, const char *name, gt_error *e)
{
    char path[4096];
    const float *vs = image_channel_data(ref, CH_SPECOCC);
    snprintf(path, sizeof path, "%s/specocc_ref_%s.png", st->figures, name);
    int rc = image_write_preview(path, &vs, 1, ref->width, ref->height, 1.0f, e);
    for (int k = 0; k < SO_STUDY_HEATMAPS && rc == 0; ++k) {
        char suffix[16];
        snprintf(suffix, sizeof suffix, "%d", k);
        rc = write_variant_maps(st, vs, in, name, st->heatmaps[k], suffix, e);
    }
    return rc;
}

/* The maps of the closest variant, when it is not a heatmap row: known only
 * once every scene is scored, they are drawn from the kept cases of the
 * maps' roughness (one case per reference, scene by scene). */
static int write_best_maps(so_state *st, gt_error *e)
{
    int best, runner_up;
    so_study_best_variants(st->out, &best, &runner_up);
    for (int k = 0; k < SO_STUDY_HEATMAPS; ++k)
        if (st->heatmaps[k] == best)
            return 0;
    int rc = 0;
    for (int i = 0; i < st->out->scene_count && rc == 0; ++i) {
        const aperture_case *c = &st->cases[DEFINITION_GTSO][i * SO_STUDY_ROUGHNESSES + SO_STUDY_MAP_ROUGHNESS];
        rc = write_variant_maps(st, c->reference, &c->inputs, st->out->scenes[i], best, "best", e);
    }
    st->out->best_maps = rc == 0;
    return rc;
}

int so_study_add_scores(const float *truth, const float *approx, const float *mask, int width, int height,
                      const char *what, double *dssim_sum, double *rmse_sum, double *flip_sum, gt_error *e)
{
    ssim_result s;
    image_error_stats err;
    flip_result f = {0};
    if (ssim_compute(truth, approx, mask, width, height, what, NULL, &s, e) != 0 ||
        image_error_compute(truth, approx, mask, width, height, what, &err, e) != 0 ||
        (flip_sum && flip_grey(truth, approx, mask, width, height, what, NULL, &f, e) != 0))
        return -1;
    *dssim_sum += s.dssim, *rmse_sum += err.rmse;
    if (flip_sum)
        *flip_sum += f.mean;
    return 0;
}

/* The talk's two- and three-split approximations against the ground truth
 * under the sky (channels of the same reference), and the truth's noise floor. */
static int score_splits(so_state *st, const image *ref, const char *what, int ri, gt_error *e)
{
    static const char *const approximations[2] = {CH_SPLIT_TWO, CH_SPLIT_THREE};
    const float *truth = image_channel_data(ref, CH_SPLIT_TRUTH), *mask = image_channel_data(ref, CH_MASK);
    for (int k = 0; k < 2; ++k)
        if (so_study_add_scores(truth, image_channel_data(ref, approximations[k]), mask, ref->width, ref->height, what,
                       &st->split_dssim[k][ri], &st->split_rmse[k][ri], NULL, e) != 0)
            return -1;
    ssim_result floor;
    if (ssim_noise_floor(ref, what, CH_SPLIT_TRUTH, mask, &floor, e) != 0)
        return -1;
    st->split_floor[ri] += floor.dssim;
    return 0;
}

/* The fit cases of one reference, one per definition, each keeping a copy
 * of its reference channel. */
static int keep_cases(so_state *st, const image *ref, const image *ao, const char *what, gt_error *e)
{
    size_t n = image_pixel_count(ref);
    for (int d = 0; d < SO_STUDY_DEFINITIONS; ++d) {
        aperture_case *c = &st->cases[d][st->case_count];
        if (aperture_case_from_images(c, ref, what, ao, what, definition_channels[d], e) != 0)
            return -1;
        if (!(st->owned[d][st->case_count] = malloc(sizeof(float) * n)))
            return gt_error_set(e, what, "out of memory");
        memcpy(st->owned[d][st->case_count], c->reference, sizeof(float) * n);
        c->reference = st->owned[d][st->case_count];
    }
    st->case_count++;
    return 0;
}

/* Every variant on the reference's inputs or GTAO's, against V_s. */
static int score_variants(so_state *st, const aperture_case *c, const so_pixel_inputs on_gtao[SO_GTAO_INPUTS],
                          const char *what, int ri, gt_error *e)
{
    const so_pixel_inputs *in = &c->inputs;
    float *approx = malloc(sizeof(float) * (size_t)in->width * in->height);
    int rc = approx ? 0 : gt_error_set(e, what, "out of memory");
    for (int v = 0; v < st->out->variant_count && rc == 0; ++v) {
        int g = st->out->variants[v].on_gtao;
        so_approx_evaluate(g ? &on_gtao[g - 1] : in, &st->variants[v], approx);
        double before = st->dssim[v][ri];
        rc = so_study_add_scores(c->reference, approx, in->mask, in->width, in->height, what, &st->dssim[v][ri],
                        &st->rmse[v][ri], &st->flip[v][ri], e);
        st->case_dssim[v][st->scored] = st->dssim[v][ri] - before;
    }
    st->scored++;
    free(approx);
    return rc;
}

/* The rankings' variants in both settings on the latest case, by region. */
static int score_rankings(so_state *st, const image *ref, const char *what, int ri, gt_error *e)
{
    static const int definition[SO_SETTINGS] = {DEFINITION_PHONG, DEFINITION_GTSO};
    so_regions regions;
    if (so_regions_from_reference(ref, what, &regions, e) != 0)
        return -1;
    long surface = regions.pixels[SO_REGION_SILHOUETTE] + regions.pixels[SO_REGION_INTERIOR];
    st->silhouette_fraction_sum += surface ? (double)regions.pixels[SO_REGION_SILHOUETTE] / surface : 0.0;
    int rc = 0, i = st->case_count - 1;
    for (int k = 0; k < SO_SETTINGS && rc == 0; ++k) {
        const aperture_case *c = &st->cases[definition[k]][i];
        double floor = 0.0;
        rc = so_ranking_scores_add(&st->ranking[k], &c->inputs, c->reference, &regions, what, e);
        if (rc == 0)
            rc = so_study_ratio_noise_floor(ref, what, definition_channels[definition[k]], &floor, NULL, e);
        st->ranking[k].floor_sum[ri] += floor;
    }
    so_regions_free(&regions);
    return rc;
}

/* The visibility cone and the dropped dimension on the latest case. */
static int score_cone_view(so_state *st, const image *ref, const image *ao, const char *what, int ri, gt_error *e)
{
    const aperture_case *c = &st->cases[DEFINITION_GTSO][st->case_count - 1];
    so_screen_buffers b;
    vec3 eye;
    if (so_buffers_from_images(ref, what, ao, what, &b, &eye, e) != 0)
        return -1;
    return so_cone_view_add(&st->cone_view, &b, eye, &c->inputs, c->reference,
                            schema_stderr_data(ref, CH_SPECOCC), ri, what, e);
}

/* Scores every variant on one reference, with the AO reference's or GTAO's
 * AO and bent normal, its noise floor and split integrals; keeps its fit
 * cases; at r = 0.5 writes the heatmaps. */
static int score(so_state *st, const image *ref, const image *ao, const image gtao[SO_GTAO_INPUTS], const char *what,
                 int ri, const char *name, gt_error *e)
{
    if (keep_cases(st, ref, ao, what, e) != 0)
        return -1;
    const aperture_case *c = &st->cases[0][st->case_count - 1];
    so_pixel_inputs on_gtao[SO_GTAO_INPUTS] = {{0}};
    int rc = 0;
    for (int g = 0; g < SO_GTAO_INPUTS && rc == 0; ++g)
        rc = so_inputs_from_images(ref, what, &gtao[g], "GTAO", so_reference_roughness(ref), &on_gtao[g], e);
    if (rc == 0)
        rc = score_variants(st, c, on_gtao, what, ri, e);
    for (int g = 0; g < SO_GTAO_INPUTS; ++g)
        so_inputs_free(&on_gtao[g]);
    if (rc == 0)
        rc = score_rankings(st, ref, what, ri, e);
    if (rc == 0)
        rc = score_cone_view(st, ref, ao, what, ri, e);
    double floor = 0.0;
    if (rc == 0)
        rc = so_study_ratio_noise_floor(ref, what, CH_SPECOCC, &floor, NULL, e);
    st->floor_dssim[ri] += floor;
    if (rc == 0)
        rc = score_splits(st, ref, what, ri, e);
    if (rc == 0 && ri == SO_STUDY_MAP_ROUGHNESS)
        rc = write_heatmaps(st, ref, &c->inputs, name, e);
    return rc;
}

/* ---- the references ------------------------------------------------------------ */

void so_study_resolution(const study_context *ctx, int *size, int *spp)
{
    const specular_occlusion_quality *q = specular_occlusion_quality_of(ctx->quality);
    *size = q->image_size, *spp = q->reference_spp;
}

int so_study_render(const study_context *ctx, const scene *s, const char *spec, const camera *cam, reference_quantity q,
                    float roughness, image *out, render_stats *stats, gt_error *e)
{
    int size, spp;
    so_study_resolution(ctx, &size, &spp);
    specular_occlusion_render_settings so = specular_occlusion_render_settings_make(roughness, ENVIRONMENT_SKY);
    reference_request req = {.quantity = q,
                             .sampling = {.spp = spp, .seed = 1,
                                          .target_stderr = specular_occlusion_quality_of(ctx->quality)->noise_budget,
                                          .threads = ctx->threads},
                             .normals = NORMAL_SHADING,
                             .settings = q == QUANTITY_SPECULAR_OCCLUSION ? &so.header : NULL};
    return reference_render(s, spec, cam, &req, out, stats, e);
}

static int render(so_state *st, const scene *s, const char *spec, const camera *cam, reference_quantity q,
                  float roughness, image *out, gt_error *e)
{
    render_stats stats;
    if (so_study_render(st->ctx, s, spec, cam, q, roughness, out, &stats, e) != 0)
        return -1;
    if (q == QUANTITY_SPECULAR_OCCLUSION && stats.seconds > 0.0) {
        st->samples_per_second_sum += (double)stats.samples / stats.seconds;
        st->renders++;
    }
    return 0;
}

/* GTAO's AO of both weightings and a bent normal on the AO reference's
 * G-buffer, as the channels so_inputs_from_images reads. */
static int gtao_channels(image *out, int width, int height, float **cosine, float **uniform, float *bent[3])
{
    if (image_init(out, width, height) != 0)
        return -1;
    *cosine = image_add_channel(out, CH_AO), *uniform = image_add_channel(out, CH_AO_UNIFORM);
    bent[0] = image_add_channel(out, CH_BENT_X), bent[1] = image_add_channel(out, CH_BENT_Y);
    bent[2] = image_add_channel(out, CH_BENT_Z);
    return *cosine && *uniform && bent[0] && bent[1] && bent[2] ? 0 : -1;
}

/* GTAO's inputs with each bent-normal estimator (so_gtao_bent, out[k - 1]):
 * high preset, one frame, and like the AO reference no radius limit; the
 * same AO in all three. */
static int gtao_inputs(const image *ao, const camera *cam, const char *what, image out[SO_GTAO_INPUTS], gt_error *e)
{
    ss_gbuffer g;
    if (ss_gbuffer_from_image(ao, what, approx_ss_camera(cam), &g, e) != 0)
        return -1;
    float *cosine[SO_GTAO_INPUTS], *uniform[SO_GTAO_INPUTS], *bent[SO_GTAO_INPUTS][3];
    for (int k = 0; k < SO_GTAO_INPUTS; ++k)
        if (gtao_channels(&out[k], ao->width, ao->height, &cosine[k], &uniform[k], bent[k]) != 0)
            return gt_error_set(e, what, "out of memory");
    gtao_params p;
    gtao_preset("high", &p);
    p.radius = 1e6f, p.falloff = 0.0f, p.max_radius_px = (float)ao->width;
    gtao_params halfway = p, uniform_p = p;
    halfway.bent_halfway = 1, uniform_p.weighting = GTAO_UNIFORM;
    if (gtao_render(&g, &p, cosine[0], bent[0]) != 0 || gtao_render(&g, &halfway, cosine[1], bent[1]) != 0 ||
        gtao_render(&g, &uniform_p, uniform[0], NULL) != 0)
        return gt_error_set(e, what, "out of memory");
    gtao_bent_horizons_frame(&g, &p, 0, bent[2]);
    size_t n = image_pixel_count(ao);
    for (int k = 1; k < SO_GTAO_INPUTS; ++k) { /* the same AO: only the bent normal differs */
        memcpy(cosine[k], cosine[0], sizeof(float) * n);
        memcpy(uniform[k], uniform[0], sizeof(float) * n);
    }
    return 0;
}

/* The specular-occlusion references of one scene at every roughness, scored. */
static int score_roughnesses(so_state *st, const scene *s, const char *spec, const camera *cam, const image *ao,
                             const image gtao[SO_GTAO_INPUTS], const char *name, gt_error *e)
{
    int rc = 0;
    for (int r = 0; r < SO_STUDY_ROUGHNESSES && rc == 0; ++r) {
        image ref;
        char what[256];
        snprintf(what, sizeof what, "%s (roughness %.2f)", name, so_study_roughness_values[r]);
        if ((rc = render(st, s, spec, cam, QUANTITY_SPECULAR_OCCLUSION, so_study_roughness_values[r], &ref, e)) != 0)
            break;
        rc = score(st, &ref, ao, gtao, what, r, name, e);
        image_free(&ref);
    }
    return rc;
}

/* One scene: its AO reference, GTAO on it, then the roughnesses. */
static int run_scene(so_state *st, const study_scene_entry *b, gt_error *e)
{
    const char *spec = b->spec;
    scene s;
    camera cam;
    if (study_scene_view(b, st->out->size, 0, &s, &cam, e) != 0)
        return -1;
    image ao = {0}, gtao[SO_GTAO_INPUTS] = {{0}};
    int rc = render(st, &s, spec, &cam, QUANTITY_AO, -1.0f, &ao, e);
    if (rc == 0)
        rc = gtao_inputs(&ao, &cam, b->label, gtao, e);
    if (rc == 0)
        rc = score_roughnesses(st, &s, spec, &cam, &ao, gtao, b->label, e);
    image_free(&ao);
    for (int k = 0; k < SO_GTAO_INPUTS; ++k)
        image_free(&gtao[k]);
    scene_free(&s);
    return rc;
}

/* ---- the results --------------------------------------------------------------- */

/* The sums over the scenes as means. */
/* Variant a's DSSIM minus variant b's, paired over the scenes. */
static so_paired_difference paired_difference(const so_state *st, int a, int b)
{
    so_paired_difference none = {NAN, NAN, 0};
    return a < 0 || b < 0 ? none
                          : so_paired_over_scenes(st->case_dssim[a], st->case_dssim[b], 1, st->out->scene_count, -1);
}

/* The talk's rankings (items 2 and 3) in both settings. */
static void rank(const so_state *st, so_rankings *k)
{
    static const char *const names[SO_SETTINGS] = {"talk", "gtso"};
    static const int definition[SO_SETTINGS] = {DEFINITION_PHONG, DEFINITION_GTSO};
    static const so_lobe lobes[SO_SETTINGS] = {SO_LOBE_PHONG, SO_LOBE_GGX};
    k->silhouette_fraction = st->scored ? st->silhouette_fraction_sum / st->scored : NAN;
    so_cone_view_compute(&st->cone_view, st->out->scene_count, &st->out->cone_view);
    for (int i = 0; i < SO_SETTINGS; ++i) {
        so_ranking_setting *s = &k->settings[i];
        so_ranking_setting_compute(&st->ranking[i], st->out->scene_count, s);
        s->name = names[i], s->reference = definition_channels[definition[i]], s->lobe = so_lobe_name(lobes[i]);
    }
}

static void average(const so_state *st, so_study_result *out)
{
    int n = out->scene_count;
    for (int v = 0; v < out->variant_count; ++v) {
        so_variant_row *row = &out->variants[v];
        row->mean_dssim = row->mean_flip = 0.0;
        for (int k = 0; k < SO_STUDY_ROUGHNESSES; ++k) {
            row->dssim[k] = st->dssim[v][k] / n, row->rmse[k] = st->rmse[v][k] / n, row->flip[k] = st->flip[v][k] / n;
            row->mean_dssim += row->dssim[k] / SO_STUDY_ROUGHNESSES;
            row->mean_flip += row->flip[k] / SO_STUDY_ROUGHNESSES;
        }
    }
    for (int k = 0; k < SO_STUDY_ROUGHNESSES; ++k) {
        so_split_row *s = &out->splits[k];
        out->noise_floor_dssim[k] = st->floor_dssim[k] / n;
        s->roughness = so_study_roughness_values[k];
        s->dssim_two = st->split_dssim[0][k] / n, s->dssim_three = st->split_dssim[1][k] / n;
        s->rmse_two = st->split_rmse[0][k] / n, s->rmse_three = st->split_rmse[1][k] / n;
        s->noise_floor = st->split_floor[k] / n;
    }
    out->reference_samples_per_second = st->renders ? st->samples_per_second_sum / st->renders : 0.0;
    out->noise_floor_mean = 0.0;
    for (int k = 0; k < SO_STUDY_ROUGHNESSES; ++k)
        out->noise_floor_mean += out->noise_floor_dssim[k] / SO_STUDY_ROUGHNESSES;
    out->bc4_16_cost = paired_difference(st, so_study_find_bc4(out, 16),
                                         so_study_find(out, SO_VARIANT_LUT, 0, 32, SO_AXES_ANGLES, 0));
    rank(st, &out->rankings);
    int arc = so_study_find(out, SO_VARIANT_LUT, 0, 32, SO_AXES_ANGLES, SO_GTAO_ARC_MEAN);
    out->bent_halfway_cost =
        paired_difference(st, so_study_find(out, SO_VARIANT_LUT, 0, 32, SO_AXES_ANGLES, SO_GTAO_HALFWAY), arc);
    out->bent_vectors_cost =
        paired_difference(st, so_study_find(out, SO_VARIANT_LUT, 0, 32, SO_AXES_ANGLES, SO_GTAO_HORIZON_VECTORS), arc);
}

/* The gloss-to-aperture fits (exact intersection) against each definition. */
static int fit_apertures(so_state *st, gt_error *e)
{
    for (int d = 0; d < SO_STUDY_DEFINITIONS; ++d) {
        so_aperture_row *row = &st->out->fits[d];
        row->name = definition_names[d], row->channel = definition_channels[d];
        if (aperture_fit_run(st->cases[d], st->case_count, SO_APERTURE_PHONG_U, 1, &row->fit, e) != 0 ||
            aperture_fit_run(st->cases[d], st->case_count, SO_APERTURE_PHONG_U_REFLECTED, 1, &row->reflected, e) != 0)
            return -1;
    }
    return 0;
}

static void free_state(so_state *st)
{
    for (int s = 0; s < LUT_SIZES; ++s)
        so_lut_free(&st->luts[s]);
    for (int s = 0; s < BC4_SIZES; ++s)
        so_lut_free(&st->bc4[s]);
    so_lut_free(&st->lut_cosines);
    so_lut_free(&st->lut_phong);
    for (int d = 0; d < SO_STUDY_DEFINITIONS; ++d)
        for (int i = 0; i < st->case_count; ++i) {
            aperture_case_free(&st->cases[d][i]);
            free(st->owned[d][i]);
        }
}

static void init_result(const study_context *ctx, so_study_result *out)
{
    memset(out, 0, sizeof *out);
    so_study_resolution(ctx, &out->size, &out->spp);
    out->noise_budget = specular_occlusion_quality_of(ctx->quality)->noise_budget;
    for (int k = 0; k < SO_STUDY_ROUGHNESSES; ++k)
        out->roughness[k] = so_study_roughness_values[k];
}

/* The LUTs, the variants, every scene, the means and the fits. */
static int run(so_state *st, gt_error *e)
{
    int rc = build_luts(st, e);
    setup_variants(st);
    for (int i = 0; i < study_scene_count(st->ctx) && i < SO_STUDY_MAX_SCENES && rc == 0; ++i) {
        const study_scene_entry *b = study_scene_at(st->ctx, i);
        rc = run_scene(st, b, e);
        if (rc == 0)
            snprintf(st->out->scenes[st->out->scene_count++], sizeof st->out->scenes[0], "%s", b->label);
    }
    if (rc == 0) {
        average(st, st->out);
        rc = write_best_maps(st, e);
        if (rc == 0)
            rc = fit_apertures(st, e);
    }
    st->out->caps_max_difference = spherical_caps_compare_derivations(97, &st->out->caps_configurations);
    return rc;
}

int specular_occlusion_study(const study_context *ctx, so_study_result *out, gt_error *e)
{
    init_result(ctx, out);
    so_state *st = calloc(1, sizeof *st);
    if (!st)
        return gt_error_set(e, "specular occlusion", "out of memory");
    st->ctx = ctx, st->out = out;
    int rc = study_make_dir(ctx, "figures", st->figures, sizeof st->figures, e);
    if (rc == 0)
        rc = run(st, e);
    free_state(st);
    free(st);
    return rc;
}
