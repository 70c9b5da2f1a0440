/* The GTAO section's subsection on the denoisers (issue 25, item 8;
 * gtao_denoisers_study.c): the spatial filter's depth tests at edges and
 * on flat pixels, the alternating window's shift, the neighbourhood clamp's
 * window size, and the claims-table rows. */
#include <math.h>
#include <stdio.h>

#include "gtao/gtao_shortcuts_section.h"
#include "report/claim_thresholds.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static const report_column depth_columns[] = {
    REPORT_TEXT("scene", "scene", gtao_denoisers_scene, scene),
    REPORT_REAL("edge pixels", "edge_fraction", "%.3f", gtao_denoisers_scene, edge_fraction),
    REPORT_REAL("edges: linear + 1st", "rmse_edge_linear_d1", "%.4f", gtao_denoisers_scene, rmse_edge[0]),
    REPORT_REAL("edges: linear + 1st + 2nd (talk's)", "rmse_edge_linear_d2", "%.4f", gtao_denoisers_scene,
                rmse_edge[1]),
    REPORT_REAL("edges: log + 1st", "rmse_edge_log_d1", "%.4f", gtao_denoisers_scene, rmse_edge[2]),
    REPORT_REAL("flat: linear + 1st", "rmse_flat_linear_d1", "%.4f", gtao_denoisers_scene, rmse_flat[0]),
    REPORT_REAL("flat: linear + 1st + 2nd (talk's)", "rmse_flat_linear_d2", "%.4f", gtao_denoisers_scene,
                rmse_flat[1]),
    REPORT_REAL("flat: log + 1st", "rmse_flat_log_d1", "%.4f", gtao_denoisers_scene, rmse_flat[2]),
};

static const report_column temporal_columns[] = {
    REPORT_TEXT("scene", "scene", gtao_denoisers_scene, scene),
    REPORT_REAL("shift x, alternating", "shift_x_alternating", "%+.3f", gtao_denoisers_scene, shift_with[0]),
    REPORT_REAL("shift y, alternating", "shift_y_alternating", "%+.3f", gtao_denoisers_scene, shift_with[1]),
    REPORT_REAL("shift x, fixed", "shift_x_fixed", "%+.3f", gtao_denoisers_scene, shift_without[0]),
    REPORT_REAL("shift y, fixed", "shift_y_fixed", "%+.3f", gtao_denoisers_scene, shift_without[1]),
    REPORT_REAL("RMSE alternating", "rmse_alternating", "%.4f", gtao_denoisers_scene, rmse_with),
    REPORT_REAL("RMSE fixed", "rmse_fixed", "%.4f", gtao_denoisers_scene, rmse_without),
    REPORT_REAL("RMSE clamp 0", "rmse_clamp_0", "%.4f", gtao_denoisers_scene, rmse_clamped[0]),
    REPORT_REAL("RMSE clamp 0.25", "rmse_clamp_0_25", "%.4f", gtao_denoisers_scene, rmse_clamped[1]),
    REPORT_REAL("RMSE clamp 0.5 (talk's)", "rmse_clamp_0_5", "%.4f", gtao_denoisers_scene, rmse_clamped[2]),
    REPORT_REAL("RMSE clamp 1", "rmse_clamp_1", "%.4f", gtao_denoisers_scene, rmse_clamped[3]),
    REPORT_REAL("RMSE clamp 2", "rmse_clamp_2", "%.4f", gtao_denoisers_scene, rmse_clamped[4]),
};

static void add_block(cJSON *o, const char *key, const block_mean *m)
{
    cJSON *x = cJSON_AddObjectToObject(o, key);
    cJSON_AddNumberToObject(x, "mean", block_mean_value(m));
    cJSON_AddNumberToObject(x, "se", block_mean_se(m));
    cJSON_AddNumberToObject(x, "blocks", (double)m->blocks);
}

static void add_summary(const gtao_denoisers_result *r, cJSON *summary)
{
    cJSON *o = cJSON_AddObjectToObject(summary, "denoisers");
    report_rows(NULL, cJSON_AddArrayToObject(o, "depth_tests"), depth_columns, COLUMNS(depth_columns), r->scenes,
                sizeof r->scenes[0], r->scene_count);
    report_rows(NULL, cJSON_AddArrayToObject(o, "temporal"), temporal_columns, COLUMNS(temporal_columns),
                r->scenes, sizeof r->scenes[0], r->scene_count);
    add_block(o, "d2_minus_log_edge", &r->d2_minus_log_edge);
    add_block(o, "d2_minus_log_flat", &r->d2_minus_log_flat);
    add_block(o, "d2_minus_d1_edge", &r->d2_minus_d1_edge);
    add_block(o, "d2_minus_d1_flat", &r->d2_minus_d1_flat);
    add_block(o, "bias_alternating", &r->bias_with);
    add_block(o, "bias_fixed", &r->bias_without);
    cJSON_AddItemToObject(o, "shift_alternating", cJSON_CreateDoubleArray(r->shift_with, 2));
    cJSON_AddItemToObject(o, "shift_alternating_se", cJSON_CreateDoubleArray(r->shift_with_se, 2));
    cJSON_AddItemToObject(o, "shift_fixed", cJSON_CreateDoubleArray(r->shift_without, 2));
    cJSON_AddItemToObject(o, "shift_fixed_se", cJSON_CreateDoubleArray(r->shift_without_se, 2));
    cJSON_AddNumberToObject(o, "diagonal_rms_gradient", r->diagonal_rms_gradient);
    cJSON *clamp = cJSON_AddArrayToObject(o, "clamp_minus_none");
    for (int k = 0; k < GTAO_CLAMP_WINDOWS; ++k) {
        cJSON *x = cJSON_CreateObject();
        cJSON_AddNumberToObject(x, "clamp_window", gtao_clamp_windows[k]);
        cJSON_AddNumberToObject(x, "mean", block_mean_value(&r->clamp_minus_none[k]));
        cJSON_AddNumberToObject(x, "se", block_mean_se(&r->clamp_minus_none[k]));
        cJSON_AddItemToArray(clamp, x);
    }
}

/* The talk's depth test (linear depth + 1st + 2nd derivatives) against the
 * log depth + 1st derivatives it also tried: "sharper details" at edges,
 * "smoother flat surfaces" elsewhere, each "better" past one 8-bit code
 * value squared of MSE. */
#define DEPTH_TEST_QUOTE                                                                                             \
    "Also tried log-space depth + first derivatives - Linear depth + 1<sup>st</sup> + 2<sup>nd</sup> order "         \
    "derivatives yield sharper details yet smoother flat surfaces"
#define DEPTH_TEST_SETTING                                                                                           \
    "the 4x4 bilateral spatial filter of GTAO's 1-direction frame at 1080p half resolution, its depth threshold "    \
    "(10% relative, linear ramp) with a gradient test"
#define DEPTH_TEST_NOTE                                                                                      \
    "the depth test is gtlab's reconstruction (the talk names its terms, not its thresholds or weights), so a " \
    "difference judges gtlab's reading, not the talk's filter (techniques/gtao/gtao_spatial_filter.h); the talk's "   \
    "resolution: frame 0 of GTAO medium filtered on the 960x540 half of a 1920x1080 G-buffer from gtlab's ray " \
    "tracer, against the 96-direction brute force of the same pass, the talk's radius read as a quarter of the " \
    "camera's distance faded over its last quarter; not the talk's content: gtlab's boxes and Cornell box "     \
    "(production adds menger and corner), not its game levels"
static const claim_record depth_claims[2] = {
    {.talk = "Jimenez et al. 2016 (GTAO)",
     .seed = "001",
     .section = "Spatial Denoiser Details",
     .quote = DEPTH_TEST_QUOTE,
     .setting = DEPTH_TEST_SETTING,
     .setting_match = CLAIM_SETTING_GTLAB,
     .setting_note = DEPTH_TEST_NOTE,
     .reading = "on flat pixels the talk's test leaves the filtered frame closer to the 96-direction AO than log "
                "depth + 1st derivatives (\"smoother flat surfaces\")",
     .form = CLAIM_BETTER,
     .margin = CLAIM_ONE_CODE_VALUE_8BIT_MSE,
     .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
     .tolerance = "better by more than one 8-bit code value squared of MSE (CLAIM_ONE_CODE_VALUE_8BIT_MSE)"},
    {.talk = "Jimenez et al. 2016 (GTAO)",
     .seed = "001",
     .section = "Spatial Denoiser Details",
     .quote = DEPTH_TEST_QUOTE,
     .setting = DEPTH_TEST_SETTING,
     .setting_match = CLAIM_SETTING_GTLAB,
     .setting_note = DEPTH_TEST_NOTE,
     .reading = "at edges (within 2 pixels of a silhouette or crease) the talk's test leaves the filtered frame "
                "closer to the 96-direction AO than log depth + 1st derivatives (\"sharper details\")",
     .form = CLAIM_BETTER,
     .margin = CLAIM_ONE_CODE_VALUE_8BIT_MSE,
     .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
     .tolerance = "better by more than one 8-bit code value squared of MSE (CLAIM_ONE_CODE_VALUE_8BIT_MSE)"}};

static void depth_claim(report_context *ctx, const gtao_talk_result *t, const block_mean *m, int edges)
{
    char scenes[256];
    gtao_talk_scenes_text(t, scenes, sizeof scenes);
    claims_table_add(ctx->claims, &depth_claims[edges], block_mean_value(m), block_mean_se(m),
                     "squared error against the 96-direction brute force of GTAO medium, frame 0 filtered, linear + "
                     "1st + 2nd minus log + 1st, %s pixels of the %dx%d pass, mean over %ld 8x8 blocks of %s (s.e. "
                     "over blocks); below 0: the talk's test better",
                     edges ? "edge" : "flat", t->half_width, t->half_height, m->blocks, scenes);
}

/* The alternating window: the 24-frame accumulation's residual shift along
 * the diagonal the talk moves the window on (t, the mean of x and y), as
 * the AO change it makes: t times the brute force's RMS change per pixel of
 * diagonal shift, within one 8-bit code value. */
static const claim_record shift_record = {
    .talk = "Jimenez et al. 2016 (GTAO)",
    .seed = "001",
    .section = "Temporal Denoiser Details",
    .quote = "4x4 bilateral filter offsets the image (not symmetric) - Temporal filtering will accumulate offsets "
             "and show trailing - Offset the 4x4 bilateral filter by 1 pixel each frame to compensate - Odd "
             "frames: move top/left - Even frames: move bottom/right",
    .setting = "the half-resolution exponential accumulation buffer after the 4x4 bilateral filter, 1080p at half "
               "resolution, the window moved by 1 pixel each frame",
    .setting_match = CLAIM_SETTING_TALK,
    .setting_note = "the talk's resolution: GTAO medium over the 24-frame cycle with a static camera on the 960x540 "
                    "half of a 1920x1080 G-buffer from gtlab's ray tracer, the talk's radius read as a quarter of "
                    "the camera's distance faded over its last quarter, the AO change per pixel of shift that of "
                    "the same pass; not the talk's content: gtlab's boxes and Cornell box (production adds "
                    "menger and corner), not its game levels",
    .reading = "moving the window by one pixel on alternate frames cancels the shift a fixed 4x4 window "
               "accumulates, leaving along the diagonal the talk moves it on a shift too small to change the AO "
               "by one 8-bit code value (RMS)",
    .form = CLAIM_RANGE,
    .low = -CLAIM_ONE_CODE_VALUE_8BIT,
    .high = CLAIM_ONE_CODE_VALUE_8BIT,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "one code value of an 8-bit AO target (CLAIM_ONE_CODE_VALUE_8BIT) of RMS change made by the "
                 "residual shift"};

static void shift_claim(report_context *ctx, const gtao_talk_result *t)
{
    const gtao_denoisers_result *r = &t->denoisers;
    char scenes[256];
    gtao_talk_scenes_text(t, scenes, sizeof scenes);
    double mean = 0.5 * (r->shift_with[0] + r->shift_with[1]);
    double se = 0.5 * sqrt(r->shift_with_se[0] * r->shift_with_se[0] + r->shift_with_se[1] * r->shift_with_se[1]);
    double g = r->diagonal_rms_gradient, fixed = 0.5 * (r->shift_without[0] + r->shift_without[1]);
    claims_table_add(ctx->claims, &shift_record, mean * g, se * g,
                     "AO change made by the 24-frame accumulation's shift against the brute force along the "
                     "diagonal (t = %+.3f px, the mean of x and y, by least squares on the brute force's gradient; "
                     "s.e. clustered by 8x8 blocks) times the brute force's RMS change per pixel of diagonal shift "
                     "(%.4f), alternating window, the %dx%d pass of %s; the fixed window's shift (%+.3f, %+.3f) px "
                     "gives %+.4f",
                     mean, g, t->half_width, t->half_height, scenes, r->shift_without[0], r->shift_without[1],
                     fixed * g);
}

/* The talk-setting figures in words, beside gtlab's 256x256 ones. */
static void talk_paragraph(report *doc, const gtao_talk_result *t)
{
    if (t->scene_count == 0)
        return;
    const gtao_denoisers_result *r = &t->denoisers;
    char scenes[256];
    gtao_talk_scenes_text(t, scenes, sizeof scenes);
    report_paragraph(doc,
                     "In the talk's setting (the claims table's rows): on the %dx%d pass of %dx%d G-buffers of %s, "
                     "linear + 1st + 2nd minus log + 1st in squared error is %+.2e ± %.1e at edges and %+.2e ± "
                     "%.1e on flat pixels; the 24-frame shift is (%+.3f ± %.3f, %+.3f ± %.3f) px with the window "
                     "alternating, (%+.3f ± %.3f, %+.3f ± %.3f) px fixed, on an RMS change of the brute force of "
                     "%.4f per pixel of diagonal shift.",
                     t->half_width, t->half_height, t->full_width, t->full_height, scenes,
                     block_mean_value(&r->d2_minus_log_edge), block_mean_se(&r->d2_minus_log_edge),
                     block_mean_value(&r->d2_minus_log_flat), block_mean_se(&r->d2_minus_log_flat), r->shift_with[0],
                     r->shift_with_se[0], r->shift_with[1], r->shift_with_se[1], r->shift_without[0],
                     r->shift_without_se[0], r->shift_without[1], r->shift_without_se[1], r->diagonal_rms_gradient);
}

void gtao_denoisers_section(report_context *ctx, const gtao_denoisers_result *r, const gtao_talk_result *t,
                            cJSON *summary)
{
    report_heading(ctx->doc, 3, "The denoisers");
    report_paragraph(
        ctx->doc,
        "The spatial filter's depth test (techniques/gtao/gtao_spatial_filter.h): frame 0 of GTAO medium filtered with "
        "each test, RMSE against the 96-direction brute force, on edge pixels (within 2 pixels of a silhouette "
        "or of a second depth difference above 2%% of the depth) and on the other, flat, pixels:");
    report_rows(ctx->doc, NULL, depth_columns, COLUMNS(depth_columns), r->scenes, sizeof r->scenes[0],
                r->scene_count);
    report_paragraph(ctx->doc,
                     "Paired over 8x8 blocks, squared error of linear + 1st + 2nd minus log + 1st: %+.2e ± %.1e at "
                     "edges, %+.2e ± %.1e on flat pixels; minus linear + 1st (gtlab's default filter): %+.2e ± "
                     "%.1e at edges, %+.2e ± %.1e on flat pixels (negative: the second derivatives help).",
                     block_mean_value(&r->d2_minus_log_edge), block_mean_se(&r->d2_minus_log_edge),
                     block_mean_value(&r->d2_minus_log_flat), block_mean_se(&r->d2_minus_log_flat),
                     block_mean_value(&r->d2_minus_d1_edge), block_mean_se(&r->d2_minus_d1_edge),
                     block_mean_value(&r->d2_minus_d1_flat), block_mean_se(&r->d2_minus_d1_flat));
    report_paragraph(
        ctx->doc,
        "The temporal filter: 24 frames accumulated with the filter's asymmetric window alternating (the talk's) "
        "or fixed at [-1, 2]^2, and with the history clamped to the current frame's 3x3 range widened by "
        "clampWindowSize (a static camera: the velocity weight is 1). Shift: least squares of the accumulation "
        "minus the brute force on the brute force's gradient (pixels, +x right, +y down):");
    report_rows(ctx->doc, NULL, temporal_columns, COLUMNS(temporal_columns), r->scenes, sizeof r->scenes[0],
                r->scene_count);
    report_paragraph(
        ctx->doc,
        "Pooled: shift (%+.3f ± %.3f, %+.3f ± %.3f) px alternating, (%+.3f ± %.3f, %+.3f ± %.3f) px fixed; mean "
        "signed error %+.2e ± %.1e alternating, %+.2e ± %.1e fixed. Clamping the history (squared error minus "
        "no clamp): %+.2e ± %.1e at clampWindowSize 0, %+.2e ± %.1e at 0.5, %+.2e ± %.1e at 2. With a static "
        "camera nothing ghosts, so the clamp can only cost convergence and a fit of clampWindowSize to these "
        "references would run to its upper bound; fitting it needs references with motion.",
        r->shift_with[0], r->shift_with_se[0], r->shift_with[1], r->shift_with_se[1], r->shift_without[0],
        r->shift_without_se[0], r->shift_without[1], r->shift_without_se[1], block_mean_value(&r->bias_with),
        block_mean_se(&r->bias_with), block_mean_value(&r->bias_without), block_mean_se(&r->bias_without),
        block_mean_value(&r->clamp_minus_none[0]), block_mean_se(&r->clamp_minus_none[0]),
        block_mean_value(&r->clamp_minus_none[2]), block_mean_se(&r->clamp_minus_none[2]),
        block_mean_value(&r->clamp_minus_none[4]), block_mean_se(&r->clamp_minus_none[4]));
    talk_paragraph(ctx->doc, t);
    add_summary(r, summary);
    cJSON *x = cJSON_AddObjectToObject(cJSON_GetObjectItem(summary, "denoisers"), "talk_setting");
    add_block(x, "d2_minus_log_edge", &t->denoisers.d2_minus_log_edge);
    add_block(x, "d2_minus_log_flat", &t->denoisers.d2_minus_log_flat);
    cJSON_AddItemToObject(x, "shift_alternating", cJSON_CreateDoubleArray(t->denoisers.shift_with, 2));
    cJSON_AddItemToObject(x, "shift_fixed", cJSON_CreateDoubleArray(t->denoisers.shift_without, 2));
    cJSON_AddNumberToObject(x, "diagonal_rms_gradient", t->denoisers.diagonal_rms_gradient);
    depth_claim(ctx, t, &t->denoisers.d2_minus_log_edge, 1);
    depth_claim(ctx, t, &t->denoisers.d2_minus_log_flat, 0);
    shift_claim(ctx, t);
}
