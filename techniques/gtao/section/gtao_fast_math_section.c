/* The GTAO section's part on the talk's fast arc cosine and square root
 * (issue 25, item 9; gtao_fast_math.h): what they move in the talk's
 * configuration, each arc-cosine variant on fixed horizons, the refits with
 * their jackknife standard errors, and the claims-table row. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report/claim_thresholds.h"
#include "gtao/gtao_shortcuts_section.h"
#include "gtao/gtao_checks_section.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

/* One scene x variant of the replay, flattened for the table. */
typedef struct {
    char scene[64];
    const char *variant;
    double rmse_hf, rmse_3d, shift_mean, shift_max, paired, paired_se;
} variant_row;

static const report_column medium_columns[] = {
    REPORT_TEXT("scene", "scene", gtao_fast_math_scene, scene),
    REPORT_REAL("mean |on - off|", "shift_mean", "%.4f", gtao_fast_math_scene, medium_shift_mean),
    REPORT_REAL("max |on - off|", "shift_max", "%.4f", gtao_fast_math_scene, medium_shift_max),
    REPORT_REAL("MSE(on) - MSE(off) vs height field", "paired_mse", "%+.2e", gtao_fast_math_scene,
                medium_paired_hf.mean),
    REPORT_REAL("s.e. (8x8 blocks)", "paired_mse_se", "%.1e", gtao_fast_math_scene, medium_paired_hf.se),
    REPORT_REAL("held-out gain, slope refit", "heldout_slope_gain", "%+.2e", gtao_fast_math_scene,
                heldout_slope_gain),
    REPORT_REAL("held-out gain, slope and constant", "heldout_both_gain", "%+.2e", gtao_fast_math_scene,
                heldout_both_gain),
};

static const report_column variant_columns[] = {
    REPORT_TEXT("scene", "scene", variant_row, scene),
    REPORT_STRING("arc cosine", "variant", variant_row, variant),
    REPORT_REAL("RMSE vs height field", "rmse_hf", "%.4f", variant_row, rmse_hf),
    REPORT_REAL("RMSE vs 3-D", "rmse_3d", "%.4f", variant_row, rmse_3d),
    REPORT_REAL("mean |AO - AO exact|", "shift_mean", "%.5f", variant_row, shift_mean),
    REPORT_REAL("max |AO - AO exact|", "shift_max", "%.4f", variant_row, shift_max),
    REPORT_REAL("MSE - MSE exact vs height field", "paired_mse", "%+.2e", variant_row, paired),
    REPORT_REAL("s.e.", "paired_mse_se", "%.1e", variant_row, paired_se),
};

static int flatten(const gtao_fast_math_result *r, variant_row *rows)
{
    int n = 0;
    for (int s = 0; s < r->scene_count; ++s)
        for (int v = 0; v < FAST_ACOS_VARIANTS; ++v) {
            const gtao_fast_math_scene *x = &r->scenes[s];
            variant_row *o = &rows[n++];
            snprintf(o->scene, sizeof o->scene, "%s", x->scene);
            o->variant = fast_acos_variant_names[v];
            o->rmse_hf = x->rmse_hf[v];
            o->rmse_3d = x->rmse_3d[v];
            o->shift_mean = x->shift_mean[v];
            o->shift_max = x->shift_max[v];
            o->paired = x->paired_hf[v].mean;
            o->paired_se = x->paired_hf[v].se;
        }
    return n;
}

static void add_polys(cJSON *o, const gtao_fast_math_result *r)
{
    cJSON *list = cJSON_AddArrayToObject(o, "arc_cosines");
    for (int v = 0; v < FAST_ACOS_VARIANTS; ++v) {
        cJSON *p = cJSON_CreateObject();
        cJSON_AddStringToObject(p, "variant", fast_acos_variant_names[v]);
        if (v != FAST_ACOS_EXACT) {
            cJSON_AddNumberToObject(p, "slope", r->poly[v].slope);
            cJSON_AddNumberToObject(p, "constant", r->poly[v].constant);
            cJSON_AddNumberToObject(p, "sqrt_magic", r->poly[v].magic);
        }
        cJSON_AddNumberToObject(p, "max_function_error", r->function_error[v]);
        cJSON_AddItemToArray(list, p);
    }
    cJSON_AddNumberToObject(o, "slope_jackknife_se", r->slope_jackknife_se);
    cJSON_AddNumberToObject(o, "slope_ceres_se", r->slope_ceres_se);
    cJSON_AddItemToObject(o, "both_jackknife_se", cJSON_CreateDoubleArray(r->both_jackknife_se, 2));
    cJSON_AddItemToObject(o, "objective_start", cJSON_CreateDoubleArray(r->objective_start, 3));
    cJSON_AddItemToObject(o, "objective_end", cJSON_CreateDoubleArray(r->objective_end, 3));
    cJSON_AddItemToObject(o, "at_bound", cJSON_CreateIntArray(r->at_bound, 3));
    cJSON_AddNumberToObject(o, "medium_paired_mse", r->medium_paired_hf.mean);
    cJSON_AddNumberToObject(o, "medium_paired_mse_se", r->medium_paired_hf.se);
    cJSON_AddNumberToObject(o, "medium_change", r->medium_change.mean);
    cJSON_AddNumberToObject(o, "medium_change_se", r->medium_change.se);
    cJSON_AddNumberToObject(o, "medium_codes_changed", r->medium_codes.mean);
    cJSON_AddNumberToObject(o, "medium_codes_changed_se", r->medium_codes.se);
}

/* Claim: the fast maths are an optimisation of the same integral. Scored as
 * the shortcut's own change (issue 42): mean |AO(fast) - AO(exact)| of GTAO
 * medium, against one code value of an 8-bit AO target; the old figure
 * (MSE(on) - MSE(off) against the height field) mostly measured the cross
 * term with GTAO medium's own bias and stays in the text. */
static const claim_record fast_math_claim = {
    .talk = "Jimenez et al. 2016 (GTAO)",
    .seed = "001",
    .section = "Cosine Weighting LUT vs Analytical",
    .quote = "3 acos also needed for setting up the integration domain\n- Use fast sqrt [Drobot2014a] and acos "
             "[Eberly2014]",
    .setting = "PS4, 1080p rendered at half resolution, GTAO with 1 direction per pixel and 8 samples per "
               "direction before the spatio-temporal denoiser; the AO is memory bound (\"ALU not a problem\"), "
               "the fast functions replace sqrt and acos in each slice's integral",
    .setting_match = CLAIM_SETTING_TALK,
    .setting_note = "the talk's resolution: GTAO medium (1 direction, 4 samples per side; the talk's radius read "
                    "as a quarter of the camera's distance faded over its last quarter), one frame, on the 960x540 "
                    "half of a 1920x1080 G-buffer from gtlab's ray tracer; not the talk's "
                    "content: gtlab's boxes and Cornell box (production adds menger and corner), not its game "
                    "levels",
    .reading = "the talk adopts the fast sqrt and acos as an optimisation of the same integral, so they should "
               "leave the AO as the exact functions give it",
    .stronger_reading = "that they move the AO by less than one code value of its 8-bit target on average: the talk "
                        "gives no figure for their accuracy",
    .form = CLAIM_RANGE,
    .low = 0.0,
    .high = CLAIM_ONE_CODE_VALUE_8BIT,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "one code value of an 8-bit AO target (CLAIM_ONE_CODE_VALUE_8BIT), the mean change allowed"};

static void add_claim(report_context *ctx, const gtao_fast_math_result *r)
{
    char scenes[256];
    gtao_scene_names_text((const char (*)[64])r->talk_scenes, r->talk_scene_count, scenes, sizeof scenes);
    claims_table_add(ctx->claims, &fast_math_claim, r->talk_change.mean, r->talk_change.se,
                     "mean |AO with the fast maths - AO with exact sqrt and acos| of GTAO medium (1 frame) on the "
                     "%dx%d pass of %s (8x8-block s.e.); %.1f%% of pixels change 8-bit code, the largest change is "
                     "%.4f",
                     r->talk_width, r->talk_height, scenes, 100.0 * r->talk_codes.mean, r->talk_shift_max);
}

static void render_medium(report *doc, const gtao_fast_math_result *r, cJSON *o)
{
    report_paragraph(doc,
                     "The talk's configuration (GTAO medium, one frame, no radius limit) with the fast maths on and "
                     "off: they move the AO by %.5f ± %.5f on average over the scenes' pixels (%.2f ± %.2f code "
                     "values of an 8-bit target) and by %.4f at worst, and change the "
                     "8-bit code of %.1f%% ± %.1f%% of pixels; the squared error against the height-field reference "
                     "changes by %+.2e ± %.1e (pooled, standard error over 8x8-pixel blocks; one 8-bit step squared "
                     "is %.1e), a figure mostly made of the cross term with GTAO medium's own bias, so not the "
                     "shortcut's. Per scene, with each scene's held-out gain of the refits below (MSE refit - MSE "
                     "talk, fitted without the scene):",
                     r->medium_change.mean, r->medium_change.se, r->medium_change.mean / CLAIM_ONE_CODE_VALUE_8BIT,
                     r->medium_change.se / CLAIM_ONE_CODE_VALUE_8BIT, r->medium_shift_max,
                     100.0 * r->medium_codes.mean, 100.0 * r->medium_codes.se, r->medium_paired_hf.mean,
                     r->medium_paired_hf.se, GTAO_SHORTCUT_VISIBLE_MSE);
    report_rows(doc, cJSON_AddArrayToObject(o, "scenes"), medium_columns, COLUMNS(medium_columns), r->scenes,
                sizeof r->scenes[0], r->scene_count);
    if (r->talk_scene_count == 0)
        return;
    char scenes[256];
    gtao_scene_names_text((const char (*)[64])r->talk_scenes, r->talk_scene_count, scenes, sizeof scenes);
    report_paragraph(doc,
                     "In the talk's setting (the claims table's row): on the %dx%d half-resolution pass of 1920x1080 "
                     "G-buffers of %s, the fast maths move GTAO medium's AO by %.2f ± %.2f code values on average "
                     "(%.1f%% of pixels change code, %.4f at worst).",
                     r->talk_width, r->talk_height, scenes, r->talk_change.mean / CLAIM_ONE_CODE_VALUE_8BIT,
                     r->talk_change.se / CLAIM_ONE_CODE_VALUE_8BIT, 100.0 * r->talk_codes.mean, r->talk_shift_max);
    cJSON *x = cJSON_AddObjectToObject(o, "talk_setting");
    cJSON_AddNumberToObject(x, "change", r->talk_change.mean);
    cJSON_AddNumberToObject(x, "change_se", r->talk_change.se);
    cJSON_AddNumberToObject(x, "codes_changed", r->talk_codes.mean);
}

static const char *interior(int at_bound) { return at_bound ? "ON A BOUND of the fit's box" : "interior"; }

static void render_refits(report *doc, const gtao_fast_math_result *r)
{
    const gtao_acos_poly *t = &r->poly[FAST_ACOS_TALK], *s = &r->poly[FAST_ACOS_SLOPE], *b = &r->poly[FAST_ACOS_BOTH],
                         *f = &r->poly[FAST_ACOS_SLOPE_REFERENCE];
    report_paragraph(
        doc,
        "The arc cosine alone, on fixed horizons (%d regular slices x %d samples per side, searched once per pixel "
        "and replayed with each arc cosine; tested equal to GTAO's own output): the talk's polynomial acos(x) ~ "
        "(c1 x + c0) sqrt~(1 - x) has c1 = %.6f, c0 = %.6f and a largest error of %.4f rad with Drobot's sqrt "
        "constant (%.4f rad with the slide's). Refitted with Ceres to minimise the AO error the polynomial "
        "causes (AO minus the AO with exact acosf on the same horizons, every %d-th pixel of every scene; cost "
        "%.4g -> %.4g in %d iterations, %s), the slope alone is c1 = %.6f ± %.6f (jackknife over scenes; Ceres' "
        "%.1e treats pixels as independent); slope and constant together c1 = %.6f ± %.6f, c0 = %.6f ± %.6f "
        "(cost %.4g -> %.4g, %s). Their largest function errors: %.4f and %.4f rad. Held out, against the "
        "height-field reference, the slope refit changes a scene's MSE from the talk's polynomial by %+.2e ± "
        "%.1e (mean and s.e. over scenes), slope and constant by %+.2e ± %.1e. Fitted instead to the height-field "
        "references themselves, the slope goes to c1 = %.6f (cost %.4g -> %.4g, %s): with %d slices the "
        "horizons miss occluders, the AO is biased bright, and that slope darkens to compensate, which is not "
        "the arc cosine's error (see the plane below, where nothing is missed).",
        r->slices, r->steps, t->slope, t->constant, r->function_error[FAST_ACOS_TALK],
        r->function_error[FAST_ACOS_TRANSCRIBED], r->fit_stride, r->objective_start[0], r->objective_end[0],
        r->iterations[0], interior(r->at_bound[0]), s->slope, r->slope_jackknife_se, r->slope_ceres_se, b->slope,
        r->both_jackknife_se[0], b->constant, r->both_jackknife_se[1], r->objective_start[1], r->objective_end[1],
        interior(r->at_bound[1]), r->function_error[FAST_ACOS_SLOPE], r->function_error[FAST_ACOS_BOTH],
        r->heldout_slope_gain_mean, r->heldout_slope_gain_se, r->heldout_both_gain_mean, r->heldout_both_gain_se,
        f->slope, r->objective_start[2], r->objective_end[2], interior(r->at_bound[2]), r->slices);
}

void gtao_fast_math_section(report_context *ctx, const gtao_fast_math_result *r, cJSON *summary)
{
    static variant_row rows[FAST_MATH_MAX_SCENES * FAST_ACOS_VARIANTS];
    cJSON *o = cJSON_AddObjectToObject(summary, "fast_math");
    report_heading(ctx->doc, 3, "Fast arc cosine and square root");
    render_medium(ctx->doc, r, o);
    render_refits(ctx->doc, r);
    int n = flatten(r, rows);
    report_rows(ctx->doc, cJSON_AddArrayToObject(o, "variants"), variant_columns, COLUMNS(variant_columns), rows,
                sizeof rows[0], n);
    add_polys(o, r);
    add_claim(ctx, r);
}
