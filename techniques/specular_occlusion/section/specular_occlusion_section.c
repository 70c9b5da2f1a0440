/* Report section: specular occlusion (specular_occlusion/specular_occlusion_study.h),
 * rendered into the report: the cone/lobe LUT's axis parametrisations
 * compared by interpolation error, every real-time variant scored against
 * the references beside their noise floor (the main ones also on GTAO's
 * inputs: what a renderer ships), the talk's two- and three-split integrals
 * against the ground truth, the gloss-to-aperture fits of u with their
 * curves, the conclusions and the figures. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>

#include "specular_occlusion/specular_occlusion_section.h"
#include "report/claim_thresholds.h"
#include "specular_occlusion/aperture_fit_figures.h"
#include "report/claims_table.h"
#include "specular_occlusion/specular_occlusion_section_parts.h"
#include "report/report_table.h"
#include "report/scene_list_section.h"
#include "specular_occlusion/specular_occlusion_study.h"

/* ---- the LUTs ------------------------------------------------------------------ */

static const report_column lut_columns[] = {
    REPORT_INT("size", "size", so_lut_row, size),
    REPORT_STRING("axes", "axes", so_lut_row, axes_name),
    REPORT_STRING("format", "format", so_lut_row, format),
    REPORT_REAL("generation (s)", "seconds", "%.2f", so_lut_row, seconds),
    REPORT_REAL("quadrature error", "quadrature_error_estimate", "%.1e", so_lut_row, quadrature_error),
    REPORT_REAL("max interp. error", "max_interpolation_error", "%.3e", so_lut_row, max_interpolation_error),
    REPORT_REAL("rms interp. error", "rms_interpolation_error", "%.3e", so_lut_row, rms_interpolation_error),
};

static void report_luts(report_context *ctx, const so_study_result *r, cJSON *json)
{
    report_paragraph(ctx->doc,
                     "The cone/lobe LUT (GGX lobe f_r cos at normal incidence, adaptive Gauss-Kronrod) at each size "
                     "and both axis parametrisations: 'angles' (a_v/(pi/2), beta/pi, r) and 'cosines' (cos a_v, "
                     "0.5 cos beta + 0.5, r: the talk's arguments), in floats, and as the talk ships them: BC4 "
                     "(8-bit endpoints, 3-bit indices per 4x4 block of each roughness slice; libsquish), decoded back "
                     "(its 'generation' is the encoding and decoding). Interpolation error: trilinear lookup against "
                     "direct integration at %d random points of the table's coordinate cube.", r->lut_points);
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "lut"), lut_columns,
                (int)(sizeof lut_columns / sizeof lut_columns[0]), r->luts, sizeof r->luts[0], r->lut_count);
}

/* ---- the variants -------------------------------------------------------------- */

/* A line of the scores table: a variant, or (variant NULL) the references'
 * noise floor, which has DSSIM cells only; mean_dssim ranks the variants
 * (NaN on the floor's line, which ranks nothing). */
typedef struct {
    const so_variant_row *variant;
    const double *noise_floor;
    double mean_dssim;
} score_line;

static void dssim_cell(const score_line *l, int k, char *text, size_t size)
{
    if (l->variant)
        snprintf(text, size, "%.4f", l->variant->dssim[k]);
    else
        snprintf(text, size, "%.2e", l->noise_floor[k]);
}

static void rmse_cell(const score_line *l, int k, char *text, size_t size)
{
    if (l->variant)
        snprintf(text, size, "%.4f", l->variant->rmse[k]);
    else
        text[0] = '\0';
}

#define ROUGHNESS_CELLS(k)                                                                                         \
    static void dssim_cell_##k(const void *row, char *text, size_t size) { dssim_cell(row, k, text, size); }        \
    static void rmse_cell_##k(const void *row, char *text, size_t size) { rmse_cell(row, k, text, size); }
ROUGHNESS_CELLS(0)
ROUGHNESS_CELLS(1)
ROUGHNESS_CELLS(2)

static void label_cell(const void *row, char *text, size_t size)
{
    const score_line *l = row;
    snprintf(text, size, "%s", l->variant ? l->variant->label : "noise floor (reference halves)");
}

static void mean_cell(const void *row, char *text, size_t size)
{
    const score_line *l = row;
    if (l->variant)
        snprintf(text, size, "%.4f", l->variant->mean_dssim);
    else
        text[0] = '\0';
}

static void flip_cell(const void *row, char *text, size_t size)
{
    const score_line *l = row;
    if (l->variant)
        snprintf(text, size, "%.4f", l->variant->mean_flip);
    else
        text[0] = '\0';
}

static const report_column score_columns[] = {
    REPORT_CELL("variant", label_cell),         REPORT_CELL("DSSIM r=0.25", dssim_cell_0),
    REPORT_CELL("DSSIM r=0.5", dssim_cell_1),   REPORT_CELL("DSSIM r=0.8", dssim_cell_2),
    REPORT_CELL("mean DSSIM", mean_cell),       REPORT_CELL("mean FLIP", flip_cell),
    REPORT_CELL("RMSE r=0.25", rmse_cell_0),    REPORT_CELL("RMSE r=0.5", rmse_cell_1),
    REPORT_CELL("RMSE r=0.8", rmse_cell_2),
    REPORT_RANKED(NULL, NULL, NULL, score_line, mean_dssim, REPORT_LOWEST_BEST),
};

/* summary.json's variants: the scalars from columns, the per-roughness means as arrays. */
static const report_column variant_columns[] = {
    REPORT_TEXT(NULL, "variant", so_variant_row, label),
    REPORT_REAL(NULL, "mean_dssim", NULL, so_variant_row, mean_dssim),
    REPORT_REAL(NULL, "mean_flip", NULL, so_variant_row, mean_flip),
};

static void add_array(cJSON *o, const char *key, const double *values, int count)
{
    cJSON *list = cJSON_AddArrayToObject(o, key);
    for (int i = 0; i < count; ++i)
        cJSON_AddItemToArray(list, cJSON_CreateNumber(values[i]));
}

static void variants_json(const so_study_result *r, cJSON *json)
{
    cJSON *list = cJSON_AddArrayToObject(json, "variants");
    report_rows(NULL, list, variant_columns, (int)(sizeof variant_columns / sizeof variant_columns[0]), r->variants,
                sizeof r->variants[0], r->variant_count);
    for (int v = 0; v < r->variant_count; ++v) {
        cJSON *o = cJSON_GetArrayItem(list, v);
        add_array(o, "mean_dssim_by_roughness", r->variants[v].dssim, SO_STUDY_ROUGHNESSES);
        add_array(o, "mean_rmse_by_roughness", r->variants[v].rmse, SO_STUDY_ROUGHNESSES);
        add_array(o, "mean_flip_by_roughness", r->variants[v].flip, SO_STUDY_ROUGHNESSES);
    }
}

static void report_scores(report_context *ctx, const so_study_result *r, cJSON *json)
{
    char sampling[256];
    if (r->noise_budget > 0)
        snprintf(sampling, sizeof sampling,
                 "each pixel stopping at its noise budget, a standard error of %g in the integral of V f_r cos (in "
                 "AO for the AO reference), at most %d samples per pixel",
                 r->noise_budget, r->spp);
    else
        snprintf(sampling, sizeof sampling, "%d samples per pixel", r->spp);
    report_paragraph(ctx->doc,
                     "References: V_s = integral of V f_r cos / integral of f_r cos (GGX, no Fresnel, white dome, view "
                     "from the camera), VNDF-sampled, %s, %dx%d pixels, at perceptual roughness "
                     "0.25, 0.5 and 0.8 on every built-in scene. Variants run on the AO reference's cosine AO and bent "
                     "normal, so their error is their own; the rows 'on GTAO' run the main variants on GTAO's AO and "
                     "bent normal instead (high preset, one frame, no radius limit, on the same G-buffer), which is "
                     "what a renderer ships. Columns average DSSIM, mean FLIP (LDR-FLIP at 67 pixels per degree, V_s "
                     "the reference; metrics/flip.h) and RMSE over the scenes; the last row is the "
                     "references' own noise floor.", sampling, r->size, r->size);
    score_line lines[SO_STUDY_MAX_VARIANTS + 1];
    for (int v = 0; v < r->variant_count; ++v)
        lines[v] = (score_line){&r->variants[v], NULL, r->variants[v].mean_dssim};
    lines[r->variant_count] = (score_line){NULL, r->noise_floor_dssim, NAN};
    report_rows(ctx->doc, NULL, score_columns, (int)(sizeof score_columns / sizeof score_columns[0]), lines,
                sizeof lines[0], r->variant_count + 1);
    variants_json(r, json);
}

/* ---- the split integrals ------------------------------------------------------- */

static const report_column split_columns[] = {
    REPORT_REAL("roughness", "roughness", "%.2f", so_split_row, roughness),
    REPORT_REAL("DSSIM two-split", "dssim_two_split", "%.4f", so_split_row, dssim_two),
    REPORT_REAL("DSSIM three-split", "dssim_three_split", "%.4f", so_split_row, dssim_three),
    REPORT_REAL("RMSE two-split", "rmse_two_split", "%.4f", so_split_row, rmse_two),
    REPORT_REAL("RMSE three-split", "rmse_three_split", "%.4f", so_split_row, rmse_three),
    REPORT_REAL("noise floor (DSSIM)", "noise_floor_dssim", "%.2e", so_split_row, noise_floor),
};

/* The summary table's row: two-split against three-split (mean[0], mean[1]),
 * their gap against the truth's half-sample noise floor. */
static void split_headline(report *doc, const double mean[2], double floor)
{
    static const char *const labels[2] = {"two-split", "three-split"};
    report_headline h = {.topic = "Split integrals", .measure = "mean DSSIM vs the ground truth, analytic sky",
                         .margin = CLAIM_DSSIM_JUST_NOTICEABLE};
    headline_rank(&h, 2, labels, mean);
    headline_from_noise_floor(&h, floor);
    report_add_headline(doc, &h);
}

/* The conclusion of the split table and its finding. */
static void conclude_splits(report_context *ctx, const so_study_result *r)
{
    double mean[2] = {0, 0}, floor = 0.0;
    for (int k = 0; k < SO_STUDY_ROUGHNESSES; ++k) {
        mean[0] += r->splits[k].dssim_two / SO_STUDY_ROUGHNESSES;
        mean[1] += r->splits[k].dssim_three / SO_STUDY_ROUGHNESSES;
        floor += r->splits[k].noise_floor / SO_STUDY_ROUGHNESSES;
    }
    /* Statistical and practical significance are different: a gap a viewer cannot
     * see is not against the talk's "doesn't introduce more error". */
    char verdict[256];
    double gap = mean[1] - mean[0];
    if (gap <= 0.0)
        snprintf(verdict, sizeof verdict, "no more error than the two-split, as the talk says");
    else if (gap < CLAIM_DSSIM_JUST_NOTICEABLE)
        snprintf(verdict, sizeof verdict,
                 "more error than the two-split, but less than a viewer sees (a gap of %.4f against a just-noticeable "
                 "DSSIM of %.3f): to the eye it introduces no more error, as the talk says",
                 gap, CLAIM_DSSIM_JUST_NOTICEABLE);
    else
        snprintf(verdict, sizeof verdict, "visibly more error than the two-split, against the talk's claim");
    /* Truth and approximations share their samples, so their difference is
     * far less noisy than two independent halves; still, a gap below the
     * halves' floor is stated as indicative only. */
    const char *weight = fabs(mean[1] - mean[0]) < floor ? " The gap is smaller than the truth's own half-sample noise "
                                                           "floor, so at this sample count it is indicative only."
                                                         : "";
    report_paragraph(ctx->doc, "Mean DSSIM against the ground truth: two-split %.4f, three-split %.4f (noise floor %.4f): "
                     "the third split adds %s.%s", mean[0], mean[1], floor, verdict, weight);
    split_headline(ctx->doc, mean, floor);
    report_finding(ctx->doc, "Split integrals",
                   "Under an analytic sky the three-split approximation scores mean DSSIM %.4f against the ground "
                   "truth, the two-split %.4f (noise floor %.4f): the third split adds %s.%s", mean[1], mean[0], floor,
                   verdict, weight);
}

static void report_splits(report_context *ctx, const so_study_result *r, cJSON *json)
{
    report_paragraph(ctx->doc,
                     "Split integrals (the talk's 'Two Split' and 'Three Split' slides), from the same references "
                     "rendered under an analytic sky (techniques/specular_occlusion/README.md: horizon 0.2, zenith 1, a sun lobe of peak "
                     "5 at 30 degrees): ground truth = integral of V L f_r cos; two-split = [integral* V L D cos] "
                     "integral f_r cos; three-split = [integral* V D cos][integral* L D cos] integral f_r cos "
                     "(integral* normalised by the integral of D cos). All three come from the same samples, so "
                     "only the splitting is measured. Means over the scenes; the noise floor is the truth's own.");
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "split_integrals"), split_columns,
                (int)(sizeof split_columns / sizeof split_columns[0]), r->splits, sizeof r->splits[0],
                SO_STUDY_ROUGHNESSES);
    conclude_splits(ctx, r);
}

/* ---- the aperture fits --------------------------------------------------------- */

static int report_fits(report_context *ctx, const so_study_result *r, cJSON *json, gt_error *e)
{
    for (int d = 0; d < SO_STUDY_DEFINITIONS; ++d) {
        const so_aperture_row *f = &r->fits[d];
        char path[4096], title[128], key[64];
        snprintf(path, sizeof path, "%s/figures/aperture_fit_%s.png", ctx->study.output_dir, f->name);
        snprintf(title, sizeof title, "cone/cone (exact) vs %s: mean DSSIM against u", f->channel);
        const aperture_fit both[2] = {f->fit, f->reflected};
        if (aperture_fit_plot(both, 2, path, title, e) != 0)
            return -1;
        snprintf(path, sizeof path, "%s/figures/aperture_regions_%s.png", ctx->study.output_dir, f->name);
        snprintf(title, sizeof title, "cone/cone (exact, the talk's cone) vs %s: RMSE per region against u", f->channel);
        if (aperture_fit_region_plot(&f->fit, path, title, e) != 0)
            return -1;
        snprintf(key, sizeof key, "aperture_fit_%s", f->name);
        cJSON_AddItemToObject(json, key, aperture_fit_json(&f->fit, f->channel, 1));
        snprintf(key, sizeof key, "aperture_fit_%s_reflected", f->name);
        cJSON_AddItemToObject(json, key, aperture_fit_json(&f->reflected, f->channel, 1));
    }
    return 0;
}

/* ---- conclusions --------------------------------------------------------------- */

/* The rows the conclusions name, selected by their fields. */
typedef struct {
    const so_variant_row *best, *runner_up, *ao, *lagarde, *exp2_alpha, *exp2_perceptual, *lut32;
    const so_variant_row *ao_on_gtao, *lagarde_on_gtao, *lut32_on_gtao;
} so_named_rows;

static const so_variant_row *row_of(const so_study_result *r, so_variant_kind kind, so_aperture_mapping mapping,
                                    int lut_size, int on_gtao)
{
    return &r->variants[so_study_find(r, kind, mapping, lut_size, SO_AXES_ANGLES, on_gtao)];
}

/* The closest and the next closest on the reference's inputs. */
static void rank(const so_study_result *r, so_named_rows *n)
{
    int best, runner_up;
    so_study_best_variants(r, &best, &runner_up);
    n->best = &r->variants[best], n->runner_up = &r->variants[runner_up];
}

static void name_rows(const so_study_result *r, so_named_rows *n)
{
    rank(r, n);
    n->ao = row_of(r, SO_VARIANT_AO, 0, 0, 0), n->lagarde = row_of(r, SO_VARIANT_LAGARDE, 0, 0, 0);
    n->exp2_alpha = row_of(r, SO_VARIANT_CONE_EXACT, SO_APERTURE_EXP2_ALPHA, 0, 0);
    n->exp2_perceptual = row_of(r, SO_VARIANT_CONE_EXACT, SO_APERTURE_EXP2_PERCEPTUAL, 0, 0);
    n->lut32 = row_of(r, SO_VARIANT_LUT, 0, 32, 0);
    n->ao_on_gtao = row_of(r, SO_VARIANT_AO, 0, 0, 1), n->lagarde_on_gtao = row_of(r, SO_VARIANT_LAGARDE, 0, 0, 1);
    n->lut32_on_gtao = row_of(r, SO_VARIANT_LUT, 0, 32, 1);
}

/* Where a fit landed, in words. */
static const char *landing(const aperture_fit *f) { return f->at_range_edge ? "at the edge of the range" : "inside the range"; }

/* ", %.1f to %.1f decades from the talk's u = 0.01. (An earlier ...)": how
 * far the reflected cone's fits lie from the talk's u. */
static const char *decades_from_talk(const so_study_result *r)
{
    static char text[256];
    double lo = INFINITY, hi = 0.0;
    for (int d = 0; d < SO_STUDY_DEFINITIONS; ++d) {
        double decades = fabs(r->fits[d].reflected.log10_u + 2.0);
        lo = fmin(lo, decades), hi = fmax(hi, decades);
    }
    snprintf(text, sizeof text,
             ", %.1f to %.1f decades from the talk's u = 0.01. (An earlier version of this report read u at the edge "
             "as 'the narrowest cone': it is the widest.)",
             lo, hi);
    return text;
}

/* Where each kind of pixel would put u (the talk's cone, GTSO's V_s). */
static void conclude_regions(report_context *ctx, const aperture_fit *f)
{
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < APERTURE_REGIONS; ++k)
        lo = fmin(lo, log10(f->region_best_u[k])), hi = fmax(hi, log10(f->region_best_u[k]));
    char spread[160];
    snprintf(spread, sizeof spread,
             hi - lo > 1.0 ? "The regions' optima span %.1f decades: no single u of this parametrisation serves them all."
                           : "The regions' optima agree within %.1f decades.",
             hi - lo);
    report_paragraph(ctx->doc,
                     "Per region (RMSE of V_s along the same scan, the talk's cone against GTSO's V_s, figures "
                     "below): the lowest RMSE is at u = %.3g on grazing pixels (n.v < %.2g, %ld pixels), u = %.3g on "
                     "occluded ones (cosine AO < %.2g, %ld) and u = %.3g on open ones (%ld). %s",
                     f->region_best_u[APERTURE_GRAZING], APERTURE_GRAZING_NV, f->region_pixels[APERTURE_GRAZING],
                     f->region_best_u[APERTURE_OCCLUDED], APERTURE_OCCLUDED_AO, f->region_pixels[APERTURE_OCCLUDED],
                     f->region_best_u[APERTURE_OPEN], f->region_pixels[APERTURE_OPEN], spread);
}

/* The gloss-to-aperture fits: the talk's cone against the cone of reflected
 * directions (specular_occlusion/specular_occlusion.h), every word chosen by the data. */
static void conclude_fits(report_context *ctx, const so_study_result *r)
{
    const so_aperture_row *g = &r->fits[0], *d = &r->fits[1], *p = &r->fits[2];
    int talk_edge = g->fit.at_range_edge + d->fit.at_range_edge + p->fit.at_range_edge;
    int reflected_edge = g->reflected.at_range_edge + d->reflected.at_range_edge + p->reflected.at_range_edge;
    report_paragraph(ctx->doc,
                     "Gloss to aperture (scanned range of u [1e-12, 0.9]). With the talk's cone, a_s = theta_m = "
                     "arccos(u^(1/(p+2))), the search gives u = %.3g against GTSO's V_s (%s; DSSIM %.4f, %.4f at the "
                     "talk's u = 0.01), u = %.3g against the D-only V_s (%s) and u = %.3g against the Phong V_s (%s; "
                     "DSSIM %.4f, %.4f at u = 0.01). A smaller u widens that cone, towards 90 degrees as u goes to 0. "
                     "theta_m is the angle of the sampled microfacet normal (Walter et al.'s eq. 31); the light "
                     "direction, its mirror, turns about 2 theta_m away from the reflection vector, so the cone of "
                     "reflected directions holding the same share 1 - u of the lobe is 2 theta_m wide (as Drobot's "
                     "2 alpha). With that cone the search gives u = %.3g against GTSO's V_s (%s; DSSIM %.4f), "
                     "u = %.3g against the D-only V_s (%s) and u = %.3g against the Phong V_s (%s; DSSIM %.4f). "
                     "%s%s",
                     g->fit.u, landing(&g->fit), g->fit.dssim, g->fit.dssim_at_published, d->fit.u, landing(&d->fit),
                     p->fit.u, landing(&p->fit), p->fit.dssim, p->fit.dssim_at_published, g->reflected.u,
                     landing(&g->reflected), g->reflected.dssim, d->reflected.u, landing(&d->reflected),
                     p->reflected.u, landing(&p->reflected), p->reflected.dssim,
                     talk_edge > 0 && reflected_edge == 0
                         ? "So the talk's parametrisation runs off its range because its cone is about half as wide "
                           "as the lobe it stands for: the data ask for wider cones than theta_m can give, and with "
                           "the factor 2 the optimum is an interior u"
                         : reflected_edge > 0
                               ? "The cone of reflected directions runs to the edge too: the width of the cone is "
                                 "not what the data disagree with; see techniques/specular_occlusion/README.md."
                               : "Neither search runs off its range here.",
                     talk_edge > 0 && reflected_edge == 0 ? decades_from_talk(r) : "");
    conclude_regions(ctx, &g->fit);
}

/* The talk's "16x16x16 BC4 still acceptable", against the float 32^3 table,
 * and its claim record: acceptable read as "no worse than the float table by
 * a just-noticeable DSSIM" (the float table, not the shipped 32^3 BC4: a
 * stronger reading). */
static const claim_record kBc4Sixteen = {
    .talk = SO_TALK, .seed = "001", .section = "Final Specular Visibility Calculation",
    .quote = "16x16x16 BC4 still acceptable, quality-wise",
    .setting = SO_SETTING, .setting_match = CLAIM_SETTING_GTLAB, .setting_note = SO_SETTING_NOTE,
    .reading = "V_s from a 16^3 BC4 table is as close (DSSIM) to the reference as from the 32^3 table, to within a "
               "just-noticeable difference.",
    .stronger_reading = "against the float 32^3 table rather than the shipped 32^3 BC4 one.",
    .form = CLAIM_AS_GOOD, .margin = CLAIM_DSSIM_JUST_NOTICEABLE, .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "the DSSIM of a just noticeable difference (CLAIM_DSSIM_JUST_NOTICEABLE, SSIM 0.95)"};

static void conclude_bc4(report_context *ctx, const so_study_result *r, const so_named_rows *n)
{
    int i16 = so_study_find_bc4(r, 16), i32 = so_study_find_bc4(r, 32);
    if (i16 < 0 || i32 < 0)
        return;
    const so_variant_row *b16 = &r->variants[i16], *b32 = &r->variants[i32];
    const so_paired_difference *cost = &r->bc4_16_cost;
    double floor = r->noise_floor_mean;
    report_paragraph(ctx->doc,
                     "The table as shipped (the talk: 32^3 BC4, and \"16^3 BC4 still acceptable\"): mean DSSIM "
                     "%.4f with 32^3 BC4 and %.4f with 16^3 BC4, against %.4f with the float 32^3 table; 16^3 BC4 "
                     "costs %+.4f +- %.4f (paired over %d scenes: %s at 95%%), against a "
                     "just-noticeable DSSIM of %.3f; %s than the references' own noise floor (DSSIM %.4f between "
                     "their two halves, mean over the roughnesses).",
                     b32->mean_dssim, b16->mean_dssim, n->lut32->mean_dssim, cost->mean, cost->standard_error,
                     cost->cases, fabs(cost->mean) > CLAIM_Z * cost->standard_error ? "significant" : "not significant",
                     CLAIM_DSSIM_JUST_NOTICEABLE, fabs(cost->mean) < floor ? "smaller" : "larger", floor);
    claims_table_add(ctx->claims, &kBc4Sixteen, cost->mean, cost->standard_error,
                     "DSSIM of the 16^3 BC4 table minus the float 32^3 table's, paired over %d scenes (each "
                     "scene's mean over the roughnesses)",
                     cost->cases);
}

/* The cone/cone ratio normalised above the horizon (not the talk's) against
 * the talk's, both with exp2(-3.32 alpha^2) and exact caps. */
static void conclude_horizon(report_context *ctx, const so_study_result *r, const so_named_rows *n)
{
    int h = so_study_find(r, SO_VARIANT_CONE_HORIZON, SO_APERTURE_EXP2_ALPHA, 0, 0, 0);
    if (h < 0)
        return;
    const so_variant_row *horizon = &r->variants[h], *talk = n->exp2_alpha;
    const int last = SO_STUDY_ROUGHNESSES - 1;
    report_paragraph(ctx->doc,
                     "Normalised by the part of the reflection cone above the surface (cone-horizon, not the talk's: "
                     "the reference never counts directions below the surface as occluded, the talk's ratio divides "
                     "by the whole cone), cone/cone with exp2(-3.32193 alpha^2) moves from mean DSSIM %.4f to %.4f, "
                     "and its RMSE at r = %.2f from %.3f to %.3f.",
                     talk->mean_dssim, horizon->mean_dssim, r->roughness[last], talk->rmse[last], horizon->rmse[last]);
}

static void conclude_variants(report_context *ctx, const so_study_result *r, const so_named_rows *n)
{
    report_paragraph(ctx->doc,
                     "Conclusion (from the numbers above, not typed in): the variant closest to the reference overall "
                     "is %s (mean DSSIM %.4f; AO as specular occlusion %.4f, Lagarde %.4f, cone/lobe LUT 32^3 %.4f). "
                     "For the engines' reflection cone cos a_s = 2^(-3.32193 r^2) the data favour r = %s "
                     "(cone/cone exact: %.4f with r = alpha, %.4f with r perceptual); the talk's own derivation "
                     "(r = sqrt(2/(p+2)), Walter's Beckmann-Phong alpha) also means alpha.",
                     n->best->label, n->best->mean_dssim, n->ao->mean_dssim, n->lagarde->mean_dssim, n->lut32->mean_dssim,
                     n->exp2_alpha->mean_dssim <= n->exp2_perceptual->mean_dssim ? "alpha (= perceptual roughness squared)"
                                                                                 : "perceptual roughness",
                     n->exp2_alpha->mean_dssim, n->exp2_perceptual->mean_dssim);
    conclude_horizon(ctx, r, n);
    conclude_bc4(ctx, r, n);
    conclude_fits(ctx, r);
}

static void conclude_inputs(report_context *ctx, const so_named_rows *n, double input_cost, double lut_gain)
{
    report_paragraph(ctx->doc,
                     "Fed by GTAO instead of the reference's AO and bent normal, the LUT 32^3 goes from mean DSSIM "
                     "%.4f to %.4f, Lagarde from %.4f to %.4f and AO as specular occlusion from %.4f to %.4f: GTAO's "
                     "inputs cost the LUT %+.4f, against the %+.4f the LUT gains over AO as specular occlusion on "
                     "exact inputs.",
                     n->lut32->mean_dssim, n->lut32_on_gtao->mean_dssim, n->lagarde->mean_dssim,
                     n->lagarde_on_gtao->mean_dssim, n->ao->mean_dssim, n->ao_on_gtao->mean_dssim, input_cost, lut_gain);
}

/* The talk's bent-normal estimators downstream (issue 25, item 10): the
 * LUT on GTAO's inputs with each, against gtlab's arc mean. */
static void conclude_bent_estimators(report_context *ctx, const so_study_result *r, cJSON *json)
{
    const so_paired_difference *h = &r->bent_halfway_cost, *v = &r->bent_vectors_cost;
    report_paragraph(ctx->doc,
                     "The bent normal as the visibility cone's axis (GTAO issue 25, item 10, downstream): with the "
                     "talk's halfway angles instead of gtlab's exact arc mean the LUT 32^3 on GTAO's inputs changes "
                     "its DSSIM by %+.4f +- %.4f, with the average of the two horizon vectors by %+.4f +- %.4f "
                     "(paired over %d scenes; the same AO in all three).",
                     h->mean, h->standard_error, v->mean, v->standard_error, h->cases);
    cJSON *o = cJSON_AddObjectToObject(json, "bent_estimators_downstream");
    cJSON_AddNumberToObject(o, "halfway_minus_arc_mean_dssim", h->mean);
    cJSON_AddNumberToObject(o, "halfway_minus_arc_mean_dssim_stderr", h->standard_error);
    cJSON_AddNumberToObject(o, "horizon_vectors_minus_arc_mean_dssim", v->mean);
    cJSON_AddNumberToObject(o, "horizon_vectors_minus_arc_mean_dssim_stderr", v->standard_error);
}

static void conclude(report_context *ctx, const so_study_result *r, cJSON *json)
{
    so_named_rows n;
    name_rows(r, &n);
    int alpha = n.exp2_alpha->mean_dssim <= n.exp2_perceptual->mean_dssim;
    double input_cost = n.lut32_on_gtao->mean_dssim - n.lut32->mean_dssim, lut_gain = n.ao->mean_dssim - n.lut32->mean_dssim;
    conclude_variants(ctx, r, &n);
    conclude_inputs(ctx, &n, input_cost, lut_gain);
    conclude_bent_estimators(ctx, r, json);
    report_headline h = {.topic = "Specular occlusion", .measure = "mean DSSIM vs the Monte Carlo reference",
                         .best_error = n.best->mean_dssim, .runner_up_error = n.runner_up->mean_dssim,
                         .margin = CLAIM_DSSIM_JUST_NOTICEABLE};
    snprintf(h.best, sizeof h.best, "%s", n.best->label);
    snprintf(h.runner_up, sizeof h.runner_up, "%s", n.runner_up->label);
    headline_from_noise_floor(&h, r->noise_floor_mean);
    int ahead = h.significance == HEADLINE_SIGNIFICANT || h.significance == HEADLINE_ABOVE_NOISE_FLOOR;
    int equal = h.significance == HEADLINE_NO_VISIBLE_DIFFERENCE;
    report_finding(ctx->doc, "Specular occlusion",
                   "%s %s (mean DSSIM %.4f; next %s %.4f%s; AO used as specular "
                   "occlusion %.4f; the references' noise floor %.3f at r = 0.25 to %.3f at r = 0.8). "
                   "In 2^(-3.32 r^2) the data support r = %s. On GTAO's inputs the LUT 32^3 scores %.4f (%s its "
                   "gain over AO-as-SO on exact inputs is %.4f).",
                   ahead   ? "Closest to the Monte Carlo reference:"
                   : equal ? "Lowest mean DSSIM, but not visibly (a gap below a just-noticeable DSSIM):"
                           : "Lowest mean DSSIM, but not significantly:",
                   n.best->label, n.best->mean_dssim, n.runner_up->label, n.runner_up->mean_dssim,
                   ahead || equal ? "" : ", a gap below the references' noise floor at this quality", n.ao->mean_dssim,
                   r->noise_floor_dssim[0], r->noise_floor_dssim[SO_STUDY_ROUGHNESSES - 1],
                   alpha ? "alpha" : "perceptual roughness", n.lut32_on_gtao->mean_dssim,
                   input_cost > lut_gain ? "GTAO's error outweighs the choice of variant:" : "the choice of variant still matters:",
                   lut_gain);
    report_add_headline(ctx->doc, &h);
    cJSON_AddStringToObject(json, "best_variant", n.best->label);
    cJSON_AddNumberToObject(json, "lut32_input_cost_of_gtao", input_cost);
    cJSON_AddStringToObject(json, "exp2_r_meaning_supported", alpha ? "alpha" : "perceptual");
}

/* ---- figures ------------------------------------------------------------------- */

/* The captions of the maps ("<metric> of <variant><scale>"), in the order
 * of so_study_heatmap_rows, then the closest variant's when it has maps of
 * its own (so_study_result.best_maps); the closest variant's marked.
 * Returns how many maps a scene has. */
static int map_captions(const so_study_result *r, const char *metric, const char *scale,
                        char captions[SO_STUDY_HEATMAPS + 1][192])
{
    static const char *const shown[SO_STUDY_HEATMAPS] = {"AO as V_s", "Lagarde 2014", "cone/cone exact, exp2(-3.32 alpha^2)",
                                                         "cone/lobe LUT 32^3"};
    int rows[SO_STUDY_HEATMAPS], best, runner_up;
    so_study_heatmap_rows(r, rows);
    so_study_best_variants(r, &best, &runner_up);
    for (int k = 0; k < SO_STUDY_HEATMAPS; ++k)
        snprintf(captions[k], 192, "%s of %s%s%s", metric, shown[k], rows[k] == best ? ", the closest variant" : "",
                 scale);
    if (r->best_maps)
        snprintf(captions[SO_STUDY_HEATMAPS], 192, "%s of %s, the closest variant%s", metric, r->variants[best].label,
                 scale);
    return SO_STUDY_HEATMAPS + (r->best_maps ? 1 : 0);
}

/* The map file of map k of a scene: figures/specocc_<kind>_<scene>_<k>.png,
 * "best" for the closest variant's own. */
static void map_path(const so_study_result *r, const char *kind, int scene, int k, char path[256])
{
    if (k < SO_STUDY_HEATMAPS)
        snprintf(path, 256, "figures/specocc_%s_%s_%d.png", kind, r->scenes[scene], k);
    else
        snprintf(path, 256, "figures/specocc_%s_%s_best.png", kind, r->scenes[scene]);
}

/* Per scene: the reference V_s at r = 0.5 beside the |error| maps (0 to
 * 0.5), then the FLIP maps (magma, 0 to 1). */
static void add_maps(report_context *ctx, const so_study_result *r)
{
    enum { MAPS = SO_STUDY_HEATMAPS + 1 };
    char err_captions[MAPS][192], flip_captions[MAPS][192], ref_caption[128], paths[MAPS + 1][256];
    int maps = map_captions(r, "|error|", " (0 to 0.5)", err_captions);
    map_captions(r, "FLIP", " (magma, 0 to 1)", flip_captions);
    for (int i = 0; i < r->scene_count; ++i) {
        const char *p[MAPS + 1], *err[MAPS + 1], *flip[MAPS];
        snprintf(paths[0], 256, "figures/specocc_ref_%s.png", r->scenes[i]);
        snprintf(ref_caption, sizeof ref_caption, "%s: reference V_s, r = 0.5", r->scenes[i]);
        p[0] = paths[0], err[0] = ref_caption;
        for (int k = 0; k < maps; ++k) {
            map_path(r, "err", i, k, paths[k + 1]);
            p[k + 1] = paths[k + 1], err[k + 1] = err_captions[k];
        }
        report_figures(ctx->doc, maps + 1, p, err);
        for (int k = 0; k < maps; ++k) {
            map_path(r, "flip", i, k, paths[k + 1]);
            flip[k] = flip_captions[k];
        }
        report_figures(ctx->doc, maps, p + 1, flip);
    }
}

static void add_figures(report_context *ctx, const so_study_result *r)
{
    add_maps(ctx, r);
    const char *p[3] = {"figures/aperture_fit_gtso.png", "figures/aperture_fit_d_only.png", "figures/aperture_fit_phong.png"};
    const char *c[3] = {"gloss-to-aperture fits against GTSO's V_s (GGX f_r): the talk's cone and the cone of "
                        "reflected directions",
                        "against the D-only V_s (GGX D)", "against the Phong V_s (the talk's fit)"};
    report_figures(ctx->doc, 3, p, c);
    const char *rp[3] = {"figures/aperture_regions_gtso.png", "figures/aperture_regions_d_only.png",
                         "figures/aperture_regions_phong.png"};
    const char *rc[3] = {"the talk's cone against GTSO's V_s, RMSE per region (dashed: each region's lowest)",
                         "against the D-only V_s", "against the Phong V_s"};
    report_figures(ctx->doc, 3, rp, rc);
}

int specular_occlusion_section(report_context *ctx, const so_study_result *r, gt_error *e)
{
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "specular_occlusion");
    scene_names_json(json, (const char(*)[64])r->scenes, r->scene_count);
    report_heading(ctx->doc, 2, "Specular occlusion (GTSO)");
    report_luts(ctx, r, json);
    report_scores(ctx, r, json);
    cJSON_AddNumberToObject(json, "reference_samples_per_second", r->reference_samples_per_second);
    report_splits(ctx, r, json);
    if (report_fits(ctx, r, json, e) != 0)
        return -1;
    conclude(ctx, r, json);
    so_rankings_section(ctx, r, json);
    so_cone_view_section(ctx, r, json);
    add_figures(ctx, r);
    return 0;
}
