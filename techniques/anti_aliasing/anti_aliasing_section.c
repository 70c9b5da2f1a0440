/* The anti-aliasing section (anti_aliasing_section.h). */
#include "anti_aliasing/anti_aliasing_section.h"
#include "report/claim_thresholds.h"

#include <math.h>
#include <string.h>

#include "anti_aliasing/aa_temporal_section.h"
#include "report/report_table.h"

static const report_column truth_columns[] = {
    REPORT_STRING("scene", "scene", aa_truth_row, scene),
    REPORT_STRING("filter", "filter", aa_truth_row, filter),
    REPORT_REAL("RMSE 16 vs 64 spp", "truth16_rmse", "%.2e", aa_truth_row, truth16_rmse),
};

static const report_column columns[] = {
    REPORT_STRING("scene", "scene", aa_row, scene),     REPORT_STRING("technique", "technique", aa_row, technique),
    REPORT_STRING("truth filter", "filter", aa_row, filter), REPORT_REAL("RMSE", "rmse", "%.4f", aa_row, rmse),
    REPORT_REAL("DSSIM", "dssim", "%.4f", aa_row, dssim),
};

/* Mean over scenes of a technique's DSSIM against one filter's truth. */
static double mean_dssim(const aa_result *r, const char *technique, const char *filter)
{
    double sum = 0.0;
    int n = 0;
    for (int i = 0; i < r->row_count; ++i)
        if (!strcmp(r->rows[i].technique, technique) && !strcmp(r->rows[i].filter, filter))
            sum += r->rows[i].dssim, ++n;
    return n ? sum / n : 0.0;
}

/* A technique's DSSIM against one filter's truth on one scene (NaN if not run). */
static double scene_dssim(const aa_result *r, const char *scene, const char *technique, const char *filter)
{
    for (int i = 0; i < r->row_count; ++i)
        if (!strcmp(r->rows[i].scene, scene) && !strcmp(r->rows[i].technique, technique) &&
            !strcmp(r->rows[i].filter, filter))
            return r->rows[i].dssim;
    return NAN;
}

static double worst_truth(const aa_result *r)
{
    double w = 0.0;
    for (int i = 0; i < r->truth_count; ++i)
        w = r->truth[i].truth16_rmse > w ? r->truth[i].truth16_rmse : w;
    return w;
}

/* The summary table's row: the three single-frame techniques by mean DSSIM
 * against the Blackman-Harris truth, the gap's interval from the per-scene
 * differences. */
static void add_headline(report *doc, const aa_result *r)
{
    const char *labels[3] = {"no AA (1 sample)", "FXAA 3.11", "SSAA 2x2 (box)"};
    double errors[3 * AA_MAX_SCENES];
    int scenes = r->request.scene_count;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < scenes; ++k)
            errors[i * scenes + k] = scene_dssim(r, r->request.scenes[k], labels[i], "blackman-harris");
    report_headline h = {.topic = "anti-aliasing", .measure = "mean DSSIM vs the Blackman-Harris truth",
                         .significance = HEADLINE_NOT_COMPUTED, .margin = CLAIM_DSSIM_JUST_NOTICEABLE};
    char over[64];
    snprintf(over, sizeof over, "paired over %d scenes", scenes);
    if (headline_rank_paired(&h, 3, labels, errors, scenes, over) == 0)
        report_add_headline(doc, &h);
}

int aa_section(report_context *ctx, const aa_result *r, gt_error *e)
{
    (void)e;
    report_heading(ctx->doc, 2, "Anti-aliasing against supersampled truth (Decima 2017, first part)");
    report_paragraph(ctx->doc,
                     "Shaded frames of built-in scenes (%dx%d; albedo x (sun with shadow rays + sky), Embree primary "
                     "rays, raytracer/shaded_frame.h), their truth at 64 stratified samples per pixel resolved with "
                     "a box and a Blackman-Harris filter (radius 1.5 px), and what a renderer does with one sample "
                     "per pixel: nothing, FXAA 3.11 (quality preset 12, anti_aliasing/fxaa.h), or 2x2 supersampling for "
                     "comparison. Scores on display values sRGB(L/(1+L)): RMSE over RGB, DSSIM of the luma. The "
                     "truth's own error, 16 against 64 samples per pixel:",
                     r->request.width, r->request.height);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "anti_aliasing");
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "truth"), truth_columns, 3, r->truth, sizeof r->truth[0],
                r->truth_count);
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "techniques"), columns, 5, r->rows, sizeof r->rows[0],
                r->row_count);
    const char *p[4] = {AA_DIR "/truth_blackman_harris.png", AA_DIR "/no_aa.png", AA_DIR "/fxaa.png", AA_DIR "/ssaa4.png"};
    const char *c[4] = {"truth, 64 spp, Blackman-Harris", "no AA", "FXAA 3.11", "SSAA 2x2"};
    report_figures(ctx->doc, 4, p, c);
    add_headline(ctx->doc, r);
    report_finding(ctx->doc, "anti-aliasing",
                   "Against the Blackman-Harris truth, FXAA 3.11 brings the mean DSSIM from %.4f (no AA) to %.4f, "
                   "2x2 supersampling to %.4f; the truth itself is within RMSE %.1e of its 64-sample value at 16 "
                   "samples.",
                   mean_dssim(r, "no AA (1 sample)", "blackman-harris"), mean_dssim(r, "FXAA 3.11", "blackman-harris"),
                   mean_dssim(r, "SSAA 2x2 (box)", "blackman-harris"), worst_truth(r));
    aa_temporal_section(ctx, json, &r->temporal);
    return 0;
}
