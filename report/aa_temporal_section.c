/* The temporal anti-aliasing part of the report (aa_temporal_section.h). */
#include "report/aa_temporal_section.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report/report_table.h"

static const char *const source = "Kojima et al. 2017, Decima / Horizon Zero Dawn, AA in 1080p and 2160p checkerboard";

static const report_column truth_columns[] = {
    REPORT_STRING("scene", "scene", aa_temporal_truth, scene),
    REPORT_STRING("path", "path", aa_temporal_truth, path),
    REPORT_REAL("RMSE 16 vs 64 spp", "truth16_rmse", "%.2e", aa_temporal_truth, truth16_rmse),
    REPORT_REAL("truth's own change (RMS)", "truth_change", "%.4f", aa_temporal_truth, truth_change),
    REPORT_REAL("disoccluded fraction", "disoccluded", "%.4f", aa_temporal_truth, disoccluded),
};

static const report_column columns[] = {
    REPORT_STRING("scene", "scene", aa_temporal_row, scene),
    REPORT_STRING("path", "path", aa_temporal_row, path),
    REPORT_STRING("technique", "technique", aa_temporal_row, technique),
    REPORT_REAL("RMSE (64 spp)", "rmse", "%.4f", aa_temporal_row, rmse),
    REPORT_REAL("DSSIM (64 spp)", "dssim", "%.4f", aa_temporal_row, dssim),
    REPORT_REAL("RMSE (16 spp)", "rmse16", "%.4f", aa_temporal_row, rmse16),
    REPORT_REAL("DSSIM (16 spp)", "dssim16", "%.4f", aa_temporal_row, dssim16),
    REPORT_REAL("flicker (RMS)", "flicker", "%.4f", aa_temporal_row, flicker),
    REPORT_REAL("ghosting (RMSE, disoccluded)", "ghost_rmse", "%.4f", aa_temporal_row, ghost_rmse),
};

static const aa_temporal_row *find(const aa_temporal_result *r, const char *path, int technique)
{
    for (int i = 0; i < r->row_count; ++i)
        if (!strcmp(r->rows[i].path, path) && r->rows[i].technique == aa_temporal_technique_names[technique] &&
            r->rows[i].scene == r->request.scenes[0])
            return &r->rows[i];
    return NULL;
}

static double ratio(double a, double b) { return b > 0.0 ? a / b : NAN; }

/* The edge TAA's largest relative change of RMSE between frames 1 .. N-1
 * on the static path: 0 when it is final after two frames. */
static double settle_after_two(const aa_temporal_row *row, int frames)
{
    double worst = 0.0;
    for (int k = 2; k < frames; ++k)
        worst = fmax(worst, fabs(row->rmse_frame[k] - row->rmse_frame[1]) / row->rmse_frame[1]);
    return worst;
}

enum { T_NONE, T_FXAA, T_TAA, T_EDGE, T_CHECKER };

static void add_claims(report_context *ctx, const aa_temporal_result *r)
{
    const aa_temporal_row *s_edge = find(r, "static", T_EDGE), *p_none = find(r, "pan", T_NONE),
                          *p_fxaa = find(r, "pan", T_FXAA), *p_taa = find(r, "pan", T_TAA),
                          *p_edge = find(r, "pan", T_EDGE), *p_checker = find(r, "pan", T_CHECKER);
    if (!s_edge || !p_none || !p_fxaa || !p_taa || !p_edge || !p_checker)
        return;
    claims_table_add_unreviewed_figure(ctx->claims, source, "the TAA reaches a stable and final result in only two frames",
                            "static camera: largest relative change of the edge TAA's RMSE after frame 1", 
                            settle_after_two(s_edge, r->request.frames), 0.0, 0.0, 0.01);
    claims_table_add_unreviewed_figure(ctx->claims, source, "TAA: much calmer than no AA (temporal stability)",
                            "pan over thin geometry: edge TAA flicker / no-AA flicker", ratio(p_edge->flicker, p_none->flicker),
                            0.0, 0.0, 1.0);
    claims_table_add_unreviewed_figure(ctx->claims, source, "post-processing AA alone (FXAA) is not enough for thin, alpha-tested content",
                            "pan: FXAA DSSIM / edge TAA DSSIM against the 64-spp truth (> 1: FXAA worse)",
                            ratio(p_fxaa->dssim, p_edge->dssim), 0.0, 1.0, INFINITY);
    claims_table_add_unreviewed_figure(ctx->claims, source, "no accumulated history: no long ghosting trails",
                            "pan: edge TAA / accumulating TAA RMSE over disoccluded pixels",
                            ratio(p_edge->ghost_rmse, p_taa->ghost_rmse), 0.0, 0.0, 1.0);
    claims_table_add_unreviewed_figure(ctx->claims, source, "checkerboard: AA stability similar to our 1080p TAA",
                            "pan: checkerboard flicker / edge TAA flicker (similar: within a factor 1.25, our bound)",
                            ratio(p_checker->flicker, p_edge->flicker), 0.0, 0.8, 1.25);
}

static void figures(report_context *ctx, const char *path)
{
    static const char *const names[] = {"truth", "none", "fxaa", "taa", "edge_taa", "checkerboard"};
    static const char *const captions[] = {"truth (64 spp, Blackman-Harris)", "no AA", "FXAA 3.11",
                                           "TAA (accumulating)", "edge TAA (talk)", "checkerboard (talk)"};
    char strips[6][96], errors[5][96];
    const char *sp[6], *ep[5];
    for (int k = 0; k < 6; ++k) {
        snprintf(strips[k], sizeof strips[k], "aa/temporal_%s_%s_strip.png", path, names[k]);
        sp[k] = strips[k];
        if (k > 0)
            snprintf(errors[k - 1], sizeof errors[k - 1], "aa/temporal_%s_%s_error.png", path, names[k]), ep[k - 1] = errors[k - 1];
    }
    report_figures(ctx->doc, 6, sp, captions);
    report_figures(ctx->doc, 5, ep, captions + 1);
}

/* The summary table's row: the four techniques of the pan (rows[4], the
 * techniques ids[4]) by DSSIM against the truth, the gap's interval from
 * the per-pixel DSSIM difference over 8x8-pixel blocks (frames averaged
 * per pixel first, so the blocks are the independent cases). */
static void add_headline(report *doc, const aa_temporal_row *const rows[4], const int ids[4])
{
    const char *labels[4];
    double errors[4];
    for (int i = 0; i < 4; ++i)
        labels[i] = rows[i]->technique, errors[i] = rows[i]->dssim;
    report_headline h = {.topic = "temporal anti-aliasing", .measure = "DSSIM vs the truth, pan over thin geometry",
                         .significance = HEADLINE_NOT_COMPUTED};
    if (headline_rank(&h, 4, labels, errors) != 0)
        return;
    int best = 0, second = 0;
    for (int i = 0; i < 4; ++i)
        best = !strcmp(labels[i], h.best) ? i : best, second = !strcmp(labels[i], h.runner_up) ? i : second;
    const cluster_mean *d = &rows[second]->dssim_minus[ids[best]];
    char over[96];
    snprintf(over, sizeof over, "per-pixel DSSIM over %d 8x8 blocks, %d frames", d->blocks, rows[second]->frames);
    headline_from_paired_cases(&h, d->mean, d->se, d->blocks, over);
    report_add_headline(doc, &h);
}

void aa_temporal_section(report_context *ctx, cJSON *json, const aa_temporal_result *r)
{
    if (r->row_count == 0)
        return;
    report_heading(ctx->doc, 3, "Temporal anti-aliasing: TAA, the talk's edge-sample TAA and checkerboard");
    report_paragraph(ctx->doc,
                     "%d frames of %dx%d along a static and a panning camera (4 cm and 0.25 deg a frame) over "
                     "builtin:aa-thin (a wire fence of 1 cm wires, grass blades, alpha-tested foliage cards, a "
                     "5 cm checker texture), exact motion vectors and disocclusion from the rays "
                     "(raytracer/frames_render.h). Scores are means over frames %d on; flicker is the RMS of each "
                     "frame-to-frame change minus the truth's own; ghosting the RMSE over pixels disoccluded since "
                     "the previous frame. The checkerboard renders half the samples a frame.",
                     r->request.frames, r->request.width, r->request.height, AA_T_WARMUP);
    cJSON *t = cJSON_AddObjectToObject(json, "temporal");
    report_rows(ctx->doc, cJSON_AddArrayToObject(t, "truth"), truth_columns, 5, r->truth, sizeof r->truth[0],
                r->truth_count);
    report_rows(ctx->doc, cJSON_AddArrayToObject(t, "techniques"), columns, 9, r->rows, sizeof r->rows[0],
                r->row_count);
    report_paragraph(ctx->doc, "The last 4 frames of the pan, then each technique's error on the last frame "
                               "(|error| summed over RGB x 4/3):");
    figures(ctx, "pan");
    add_claims(ctx, r);
    const aa_temporal_row *none = find(r, "pan", T_NONE), *edge = find(r, "pan", T_EDGE), *taa = find(r, "pan", T_TAA),
                          *checker = find(r, "pan", T_CHECKER);
    if (none && edge && taa && checker)
        add_headline(ctx->doc, (const aa_temporal_row *[]){none, taa, edge, checker},
                     (const int[]){T_NONE, T_TAA, T_EDGE, T_CHECKER});
    if (none && edge && taa && checker)
        report_finding(ctx->doc, "temporal anti-aliasing",
                       "On the pan over thin geometry, DSSIM against the truth: no AA %.4f, accumulating TAA %.4f, "
                       "the talk's edge TAA %.4f, checkerboard %.4f; flicker %.4f / %.4f / %.4f / %.4f; ghosting "
                       "RMSE %.4f / %.4f / %.4f / %.4f.",
                       none->dssim, taa->dssim, edge->dssim, checker->dssim, none->flicker, taa->flicker,
                       edge->flicker, checker->flicker, none->ghost_rmse, taa->ghost_rmse, edge->ghost_rmse,
                       checker->ghost_rmse);
}
