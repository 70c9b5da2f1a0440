/* The environment section: tables from one column description each, the
 * images, the claims rows and a finding (see the header). */
#include "environment/environment_section.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report/claim_thresholds.h"
#include "report/claims_table.h"
#include "report/report_table.h"
#include "report/scene_list_section.h"

typedef struct {
    char environment[64];
    const char *kind;
    double lighting_map, lighting_sh, occlusion, total_map, total_sh, dssim_map;
} diffuse_row;

typedef struct {
    char environment[64];
    const char *variant;
    double lighting, occlusion, total, dssim;
} specular_row;

typedef struct {
    char environment[64];
    char order[160];
    double kendall_tau;
    int flipped, significant;
} ranking_row;

static const report_column diffuse_columns[] = {
    REPORT_TEXT("environment", "environment", diffuse_row, environment),
    REPORT_STRING("combination", "combination", diffuse_row, kind),
    REPORT_REAL("lighting (map)", "lighting_map", "%.3f", diffuse_row, lighting_map),
    REPORT_REAL("lighting (SH9)", "lighting_sh9", "%.3f", diffuse_row, lighting_sh),
    REPORT_REAL("occlusion", "occlusion", "%.3f", diffuse_row, occlusion),
    REPORT_REAL("total (map)", "total_map", "%.3f", diffuse_row, total_map),
    REPORT_REAL("total (SH9)", "total_sh9", "%.3f", diffuse_row, total_sh),
    REPORT_REAL("DSSIM total (map)", "dssim_total_map", "%.4f", diffuse_row, dssim_map),
};
static const report_column specular_columns[] = {
    REPORT_TEXT("environment", "environment", specular_row, environment),
    REPORT_STRING("specular occlusion", "variant", specular_row, variant),
    REPORT_REAL("lighting", "lighting", "%.3f", specular_row, lighting),
    REPORT_REAL("occlusion", "occlusion", "%.3f", specular_row, occlusion),
    REPORT_REAL("total", "total", "%.3f", specular_row, total),
    REPORT_REAL("DSSIM total", "dssim_total", "%.4f", specular_row, dssim),
};
static const report_column ranking_columns[] = {
    REPORT_TEXT("environment", "environment", ranking_row, environment),
    REPORT_TEXT("order (best first)", "order", ranking_row, order),
    REPORT_REAL("Kendall tau vs white", "kendall_tau", "%.2f", ranking_row, kendall_tau),
    REPORT_INT("pairs flipped", "pairs_flipped", ranking_row, flipped),
    REPORT_INT("flips significant", "significant_flips", ranking_row, significant),
};
#define COLUMNS(c) (int)(sizeof c / sizeof c[0])

static void diffuse_table(report_context *ctx, const environment_study_result *r, cJSON *json)
{
    diffuse_row rows[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS * ENVIRONMENT_STUDY_OCCLUDED_KINDS];
    int n = 0;
    for (int env = 0; env < r->environment_count; ++env)
        for (int k = 0; k < ENVIRONMENT_STUDY_OCCLUDED_KINDS; ++k) {
            const environment_study_environment *x = &r->environments[env];
            const environment_score *map = x->diffuse[ENVIRONMENT_IRRADIANCE_MAP][k], *sh = x->diffuse[ENVIRONMENT_IRRADIANCE_SH9][k];
            diffuse_row *row = &rows[n++];
            snprintf(row->environment, sizeof row->environment, "%s", x->name);
            row->kind = environment_diffuse_kind_name((environment_diffuse_kind)(k + 1));
            row->lighting_map = map[ENVIRONMENT_PART_LIGHTING].rmse, row->lighting_sh = sh[ENVIRONMENT_PART_LIGHTING].rmse;
            row->occlusion = map[ENVIRONMENT_PART_OCCLUSION].rmse, row->total_map = map[ENVIRONMENT_PART_TOTAL].rmse;
            row->total_sh = sh[ENVIRONMENT_PART_TOTAL].rmse, row->dssim_map = map[ENVIRONMENT_PART_TOTAL].dssim;
        }
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "diffuse"), diffuse_columns, COLUMNS(diffuse_columns), rows,
                sizeof rows[0], n);
}

static void specular_table(report_context *ctx, const environment_study_result *r, cJSON *json)
{
    specular_row rows[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS * ENVIRONMENT_STUDY_SO_VARIANTS];
    int n = 0;
    for (int env = 0; env < r->environment_count; ++env)
        for (int v = 0; v < ENVIRONMENT_STUDY_SO_VARIANTS; ++v) {
            const environment_score *s = r->environments[env].specular[v];
            specular_row *row = &rows[n++];
            snprintf(row->environment, sizeof row->environment, "%s", r->environments[env].name);
            row->variant = environment_study_so_label(v);
            row->lighting = s[ENVIRONMENT_PART_LIGHTING].rmse, row->occlusion = s[ENVIRONMENT_PART_OCCLUSION].rmse;
            row->total = s[ENVIRONMENT_PART_TOTAL].rmse, row->dssim = s[ENVIRONMENT_PART_TOTAL].dssim;
        }
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "specular"), specular_columns, COLUMNS(specular_columns), rows,
                sizeof rows[0], n);
}

static void ranking_table(report_context *ctx, const environment_study_result *r, cJSON *json)
{
    ranking_row rows[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS];
    for (int env = 0; env < r->environment_count; ++env) {
        const environment_so_ranking *k = &r->rankings[env];
        ranking_row *row = &rows[env];
        snprintf(row->environment, sizeof row->environment, "%s", r->environments[env].name);
        row->order[0] = '\0';
        for (int i = 0; i < ENVIRONMENT_STUDY_SO_VARIANTS; ++i) {
            strncat(row->order, environment_study_so_label(k->order[i]), sizeof row->order - strlen(row->order) - 1);
            if (i + 1 < ENVIRONMENT_STUDY_SO_VARIANTS)
                strncat(row->order, " < ", sizeof row->order - strlen(row->order) - 1);
        }
        row->kendall_tau = k->kendall_tau, row->flipped = k->flipped_pairs, row->significant = k->significant_flips;
    }
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "rankings"), ranking_columns, COLUMNS(ranking_columns), rows,
                sizeof rows[0], r->environment_count);
}

static void images(report_context *ctx, const environment_study_result *r)
{
    static char paths[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS * 3][160], captions[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS * 3][160];
    const char *p[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS * 3], *c[ENVIRONMENT_STUDY_MAX_ENVIRONMENTS * 3];
    static const char *const parts[3] = {"ref", "approx", "dssim"};
    static const char *const what[3] = {"reference (direct diffuse)", "AO x E(n), irradiance map", "DSSIM map (0-0.5)"};
    int n = 0;
    for (int env = 0; env < r->environment_count; ++env)
        for (int k = 0; k < 3; ++k, ++n) {
            snprintf(paths[n], sizeof paths[n], "environment/%s_%s_%s.png", r->environments[env].name,
                     r->image_scene, parts[k]);
            snprintf(captions[n], sizeof captions[n], "%s: %s", r->environments[env].name, what[k]);
            p[n] = paths[n], c[n] = captions[n];
        }
    report_figures(ctx->doc, n, p, c);
}

/* The talk's words (seed 001, "How We Use Ambient Occlusion"): AO times the
 * pre-convolved probe is exact under a white dome and not otherwise. The
 * figure is the occlusion's part of the error (exact AO, exact unoccluded
 * lighting) of the one-bounce combination against the direct diffuse
 * reference: the talk's Lambertian, single-bounce setting. */
#define ENVIRONMENT_TALK "Jimenez et al. 2016 (GTAO)"
#define ENVIRONMENT_SECTION "How We Use Ambient Occlusion"
#define ENVIRONMENT_QUOTE                                                                                                     \
    "The typical approach to account for this is to just multiply the ambient occlusion by the pre-convolved "      \
    "probe, which will still be accurate for the case of a white dome, but not for any other scenario."
#define ENVIRONMENT_SETTING                                                                                                   \
    "L_o = rho_d V_d times the pre-convolved probe, for real scenes whose lighting is not uniform white; AO is "   \
    "the ground truth for a Lambertian surface, a white dome and a single bounce of light"
#define ENVIRONMENT_SETTING_NOTE                                                                                              \
    "gtlab's built-in scenes at the quality table's image size (the section states it), exact AO and exact "     \
    "unoccluded irradiance, "                                                                                      \
    "scored against the direct (one-bounce) diffuse reference; the error is per pixel, so it does not depend on " \
    "the image size"

static const claim_record kWhiteDome = {
    .talk = ENVIRONMENT_TALK, .seed = "001", .section = ENVIRONMENT_SECTION, .quote = ENVIRONMENT_QUOTE, .setting = ENVIRONMENT_SETTING,
    .setting_match = CLAIM_SETTING_INDEPENDENT, .setting_note = ENVIRONMENT_SETTING_NOTE,
    .reading = "Under a white dome, exact AO times the exact irradiance E(n) reproduces the one-bounce diffuse "
               "reference to within a just-visible luminance change.",
    .form = CLAIM_RANGE, .low = -INFINITY, .high = CLAIM_WEBER_FRACTION,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "accurate: relative RMSE at most the Weber fraction of luminance discrimination (1%, "
                 "CLAIM_WEBER_FRACTION)"};

static const claim_record kOtherScenario = {
    .talk = ENVIRONMENT_TALK, .seed = "001", .section = ENVIRONMENT_SECTION, .quote = ENVIRONMENT_QUOTE, .setting = ENVIRONMENT_SETTING,
    .setting_match = CLAIM_SETTING_INDEPENDENT, .setting_note = ENVIRONMENT_SETTING_NOTE,
    .reading = "Under any non-uniform environment, even the one where it does best, exact AO times E(n) misses the "
               "one-bounce diffuse reference by more than a just-visible luminance change.",
    .form = CLAIM_RANGE, .low = CLAIM_WEBER_FRACTION, .high = INFINITY,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "not accurate: relative RMSE above the Weber fraction of luminance discrimination (1%, "
                 "CLAIM_WEBER_FRACTION)"};

static void claims(report_context *ctx, const environment_study_result *r)
{
    claims_table_add(ctx->claims, &kWhiteDome, r->white_occlusion.mean, r->white_occlusion.standard_error,
                     "relative RMSE of exact AO x E(n) against the direct diffuse reference, exact unoccluded "
                     "lighting (the occlusion's part), reference noise taken out, white dome, mean over %d scenes "
                     "(s.e. over scenes)",
                     r->scene_count);
    if (r->claim_environment < 0)
        return;
    claims_table_add(ctx->claims, &kOtherScenario, r->other_occlusion.mean, r->other_occlusion.standard_error,
                     "the same under the environment where it is smallest (%s), mean over %d scenes (s.e. over "
                     "scenes)",
                     r->environments[r->claim_environment].name, r->scene_count);
}

static void findings(report_context *ctx, const environment_study_result *r)
{
    if (r->claim_environment < 0)
        return;
    int worst = 1;
    for (int env = 1; env < r->environment_count; ++env)
        if (r->environments[env].diffuse[ENVIRONMENT_IRRADIANCE_MAP][0][ENVIRONMENT_PART_OCCLUSION].rmse >
            r->environments[worst].diffuse[ENVIRONMENT_IRRADIANCE_MAP][0][ENVIRONMENT_PART_OCCLUSION].rmse)
            worst = env;
    report_finding(ctx->doc, "Environment lighting",
                   "AO x E(n) with exact AO: the occlusion's part of the error is %.3f (relative RMSE) under the "
                   "white dome and from %.3f (%s) to %.3f (%s) under the other environments; the irradiance "
                   "itself (map) contributes %.3f under %s.",
                   r->white_occlusion.mean, r->other_occlusion.mean, r->environments[r->claim_environment].name,
                   r->environments[worst].diffuse[ENVIRONMENT_IRRADIANCE_MAP][0][ENVIRONMENT_PART_OCCLUSION].rmse,
                   r->environments[worst].name,
                   r->environments[worst].diffuse[ENVIRONMENT_IRRADIANCE_MAP][0][ENVIRONMENT_PART_LIGHTING].rmse,
                   r->environments[worst].name);
}

int environment_section(report_context *ctx, const environment_study_result *r, gt_error *e)
{
    (void)e;
    report_heading(ctx->doc, 2, "Beyond the white dome: ambient terms under real environments");
    report_paragraph(ctx->doc,
                     "Engines light with AO x an irradiance probe and a split-sum specular times a specular "
                     "occlusion. Here each combination is computed on the G-buffer with the AO reference's exact "
                     "AO and bent normal, under the white dome (the control), the analytic sky, a synthetic small "
                     "bright sun and Blender's studio-light HDRs, and compared (luminance, %d scenes, %dx%d, %d "
                     "spp, %d bounces) with the environment-lit references. The error is split: 'lighting' is the "
                     "unoccluded approximation against the unoccluded reference (SH9 or the exact irradiance map; "
                     "the split sum); 'occlusion' applies the approximation's occlusion factor (AO, AO E(b)/E(n), "
                     "the multi-bounce G(AO), V_s) to the exact unoccluded reference; 'total' is the combination "
                     "itself. Figures are relative RMSE (RMSE / the reference's mean), noise included; the "
                     "reference's own RMS noise is %.3f of its mean under the white dome (the claims rows take it "
                     "out). The study took %.0f s.",
                     r->scene_count, r->size, r->size, r->spp, r->bounces, r->environments[0].reference_noise,
                     r->seconds);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "environment");
    scene_names_json(json, (const char(*)[64])r->scenes, r->scene_count);
    report_heading(ctx->doc, 3, "Diffuse: AO x irradiance and the multi-bounce function");
    diffuse_table(ctx, r, json);
    report_heading(ctx->doc, 3, "Specular: split sum x specular occlusion");
    specular_table(ctx, r, json);
    report_heading(ctx->doc, 3, "Does the white dome's specular-occlusion ranking transfer?");
    report_paragraph(ctx->doc,
                     "Variants ordered by mean total relative RMSE over the scenes; Kendall's tau against the "
                     "white dome's order; a flip counts as significant when the pair's paired difference over the "
                     "scenes exceeds 2 standard errors under both lights.");
    ranking_table(ctx, r, json);
    images(ctx, r);
    claims(ctx, r);
    findings(ctx, r);
    return 0;
}
