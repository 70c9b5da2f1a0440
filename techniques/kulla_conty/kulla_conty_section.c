/* The Kulla-Conty section; see kulla_conty_section.h. */
#include "kulla_conty/kulla_conty_section.h"

#include "report/claim_thresholds.h"
#include "report/report_table.h"

#define ROW kulla_conty_size_row
static const report_column size_columns[] = {
    REPORT_INT("entries N", "size", ROW, size),
    REPORT_REAL("max E_avg error", "max_error", "%.2e", ROW, max_error),
    REPORT_REAL("RMS E_avg error", "rms_error", "%.2e", ROW, rms_error),
    REPORT_REAL("max white-furnace error", "max_furnace_error", "%.2e", ROW, max_furnace_error),
};
#undef ROW
#define ROW kulla_conty_loss_row
static const report_column loss_columns[] = {
    REPORT_REAL("roughness r", "roughness", "%.2f", ROW, roughness),
    REPORT_REAL("E_avg", "average_albedo", "%.4f", ROW, average_albedo),
    REPORT_REAL("energy lost 1 - E_avg", "energy_lost", "%.4f", ROW, energy_lost),
};
#undef ROW
static const report_column result_columns[] = {
    REPORT_INT(NULL, "size", kulla_conty_result, request.size),
    REPORT_REAL(NULL, "max_quadrature_error_estimate", NULL, kulla_conty_result, max_error_estimate),
    REPORT_REAL(NULL, "seconds", NULL, kulla_conty_result, seconds),
};

int kulla_conty_smallest_invisible_size(const kulla_conty_result *r)
{
    for (int i = 0; i < r->request.size_count; ++i)
        if (r->by_size[i].max_furnace_error < CLAIM_WEBER_FRACTION)
            return r->by_size[i].size;
    return 0;
}

static void render_findings(report_context *ctx, const kulla_conty_result *r)
{
    int smallest = kulla_conty_smallest_invisible_size(r);
    const kulla_conty_loss_row *rough = &r->loss[KULLA_CONTY_LOSS_ROWS - 1];
    if (smallest > 0)
        report_finding(ctx->doc, "Kulla-Conty",
                       "Single-scattering GGX loses %.0f%% of a white surface's energy on average at roughness %.1f; "
                       "the compensation lobe restores it, and a %d-entry E_avg table already keeps the white furnace "
                       "within the %.0f%% a viewer can see.",
                       100.0 * rough->energy_lost, rough->roughness, smallest, 100.0 * CLAIM_WEBER_FRACTION);
    else
        report_finding(ctx->doc, "Kulla-Conty",
                       "Single-scattering GGX loses %.0f%% of a white surface's energy on average at roughness %.1f; "
                       "no scored E_avg table size keeps the compensated white furnace within %.0f%%.",
                       100.0 * rough->energy_lost, rough->roughness, 100.0 * CLAIM_WEBER_FRACTION);
}

int kulla_conty_section(report_context *ctx, const kulla_conty_result *r, gt_error *e)
{
    (void)e;
    const kulla_conty_request *rq = &r->request;
    report_heading(ctx->doc, 2, "Multiple-scattering energy compensation (Kulla-Conty 2017)");
    report_paragraph(ctx->doc,
                     "Kulla & Conty 2017 restore the energy a single-scattering microfacet BRDF loses with a lobe "
                     "f_ms = (1 - E(mu_o))(1 - E(mu_i)) / (pi (1 - E_avg)), E the directional albedo of the DFG "
                     "table above and E_avg = 2 int E(mu) mu dmu its cosine-weighted average, tabulated against "
                     "roughness (luts/kulla_conty_eavg_%d.exr, .png, .h; quadrature bound %.1e). The lobe's "
                     "cosine-weighted integral is 1 - E(mu_o) exactly when E_avg is exact (tested), so the white "
                     "furnace is 1; the second table scores the E_avg table's linear lookup at %d roughnesses between texel centres, "
                     "and its white-furnace error over %d viewing angles: the relative energy a white surface gains "
                     "or loses, against the %.0f%% Weber fraction a viewer can see. %.1f s.",
                     rq->size, r->max_error_estimate, rq->roughness_points, rq->mu_points,
                     100.0 * CLAIM_WEBER_FRACTION, r->seconds);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "kulla_conty");
    report_object(json, "table", result_columns, (int)(sizeof result_columns / sizeof result_columns[0]), r);
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "energy_lost"), loss_columns,
                (int)(sizeof loss_columns / sizeof loss_columns[0]), r->loss, sizeof r->loss[0],
                KULLA_CONTY_LOSS_ROWS);
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "sizes"), size_columns,
                (int)(sizeof size_columns / sizeof size_columns[0]), r->by_size, sizeof r->by_size[0],
                rq->size_count);
    render_findings(ctx, r);
    return 0;
}
