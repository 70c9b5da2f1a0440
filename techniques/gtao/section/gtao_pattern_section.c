/* The GTAO section's subsection on the spatio-temporal pattern (issue 25,
 * item 7; gtao_pattern_study.c): the talk's configuration after 1 and
 * 24 frames in row and Morton order against its 96-direction brute force,
 * and the claims-table rows. */
#include <math.h>
#include <stdio.h>

#include "gtao/gtao_shortcuts_section.h"
#include "report/claim_thresholds.h"
#include "report/report_table.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

static const report_column scene_columns[] = {
    REPORT_TEXT("scene", "scene", gtao_pattern_scene, scene),
    REPORT_REAL("brute force vs height field (noise out)", "brute_rmse_heightfield", "%.4f", gtao_pattern_scene,
                brute_rmse_hf),
    REPORT_REAL("rows, 1 frame", "rmse_rows_1", "%.4f", gtao_pattern_scene, rmse_rows[0]),
    REPORT_REAL("Morton, 1 frame", "rmse_morton_1", "%.4f", gtao_pattern_scene, rmse_morton[0]),
    REPORT_REAL("rows, 24 frames", "rmse_rows_24", "%.4f", gtao_pattern_scene, rmse_rows[1]),
    REPORT_REAL("Morton, 24 frames", "rmse_morton_24", "%.4f", gtao_pattern_scene, rmse_morton[1]),
    REPORT_REAL("rows, 24 frames, no spatial filter", "rmse_raw_cycle", "%.4f", gtao_pattern_scene,
                rmse_raw_cycle),
};

static void add_summary(const gtao_pattern_result *r, cJSON *summary)
{
    cJSON *o = cJSON_AddObjectToObject(summary, "pattern");
    report_rows(NULL, cJSON_AddArrayToObject(o, "scenes"), scene_columns, COLUMNS(scene_columns), r->scenes,
                sizeof r->scenes[0], r->scene_count);
    cJSON_AddNumberToObject(o, "cycle_rmse", r->cycle_rmse);
    cJSON_AddNumberToObject(o, "cycle_rmse_se", r->cycle_rmse_se);
    cJSON_AddNumberToObject(o, "heightfield_noise_rmse", r->hf_noise_rmse);
    cJSON *d = cJSON_AddArrayToObject(o, "rows_minus_morton_mse");
    for (int k = 0; k < GTAO_PATTERN_RUNS; ++k) {
        cJSON *x = cJSON_CreateObject();
        cJSON_AddNumberToObject(x, "frames", gtao_pattern_frames[k]);
        cJSON_AddNumberToObject(x, "mean", block_mean_value(&r->order_difference[k]));
        cJSON_AddNumberToObject(x, "se", block_mean_se(&r->order_difference[k]));
        cJSON_AddNumberToObject(x, "blocks", (double)r->order_difference[k].blocks);
        cJSON_AddItemToArray(d, x);
    }
}

/* The 24-frame cycle denoised against the 96 directions it stands for,
 * within one 8-bit code value of RMSE; the talk's row order against Morton
 * order, "better" past one code value squared of MSE. */
static const claim_record cycle_claim = {
    .talk = "Jimenez et al. 2016 (GTAO)",
    .seed = "001",
    .section = "Achieving the Performance Target",
    .quote = "Spatial + Temporal Denoiser 96 Directions per pixel ... So, we had to heavily rely on temporal "
             "filtering to stabilize the image, and to increase the directions to 96 per pixel.",
    .setting = "PS4, 1080p at half resolution, 1 direction per pixel in 16 spatial rotations (4x4 tiles) times 6 "
               "temporal rotations, the 4x4 bilateral filter and the temporal accumulation",
    .setting_match = CLAIM_SETTING_TALK,
    .setting_note = "the talk's resolution: GTAO medium's 24-frame cycle, its 4x4 bilateral filter and temporal "
                    "accumulation on the 960x540 half of a 1920x1080 G-buffer from gtlab's ray tracer, against the "
                    "96 directions in one frame of the same pass; a static camera, the talk's radius read as a "
                    "quarter of the camera's distance faded over its last quarter (150 to 200 inches); not the "
                    "talk's content: gtlab's boxes and Cornell box (production "
                    "adds menger and corner), not its game levels",
    .reading = "the 4x4 tile's 16 rotations times the cycle's 6 temporal ones, gathered by the bilateral filter "
               "and the temporal accumulation, give each pixel's AO from 96 directions",
    .stronger_reading = "that after the 24-frame cycle the denoised accumulation is each pixel's AO of 96 directions "
                        "in one frame within one 8-bit code value of RMSE: the talk counts the directions and gives "
                        "no figure for how close its filtered result comes to a 96-direction search per pixel",
    .form = CLAIM_RANGE,
    .low = 0.0,
    .high = CLAIM_ONE_CODE_VALUE_8BIT,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "one code value of an 8-bit AO target of RMSE (CLAIM_ONE_CODE_VALUE_8BIT)"};

static const claim_record order_claim = {
    .talk = "Jimenez et al. 2016 (GTAO)",
    .seed = "001",
    .section = "Noise Distribution",
    .quote = "Sorted in such a way that each row contains a full rotation - Horizontal/vertical features prominent "
             "in architecture ... Worked better than Morton order",
    .setting = "architectural game levels, where horizontal and vertical features make the bilateral filter "
               "average along rows and columns; 1080p at half resolution",
    .setting_match = CLAIM_SETTING_TALK,
    .setting_note = "the talk's resolution: GTAO medium after one frame of the 4x4 bilateral filter on the 960x540 "
                    "half of a 1920x1080 G-buffer from gtlab's ray tracer, against the 96 directions in one frame, "
                    "the talk's radius read as a quarter of the camera's distance faded over its last quarter; "
                    "the content architecture-like but not the talk's levels: gtlab's boxes (a grid of boxes on a "
                    "floor) and Cornell box (a room with two blocks), production adding menger and corner",
    .reading = "with the directions sorted so that each row of the 4x4 tile holds a full rotation, the filtered "
               "frame is closer to the 96-direction AO than with the directions in Morton order",
    .form = CLAIM_BETTER,
    .margin = CLAIM_ONE_CODE_VALUE_8BIT_MSE,
    .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = "better by more than one 8-bit code value squared of MSE (CLAIM_ONE_CODE_VALUE_8BIT_MSE)"};

/* The rows, from the run in the talk's setting. */
static void add_claims(report_context *ctx, const gtao_talk_result *t)
{
    const gtao_pattern_result *r = &t->pattern;
    char scenes[256];
    gtao_talk_scenes_text(t, scenes, sizeof scenes);
    claims_table_add(ctx->claims, &cycle_claim, r->cycle_rmse, r->cycle_rmse_se,
                     "RMSE of GTAO medium after the 24-frame cycle (denoised) against the same configuration with "
                     "its 96 directions in one frame, on the %dx%d pass of %s (s.e. over 8x8 blocks)",
                     t->half_width, t->half_height, scenes);
    claims_table_add(ctx->claims, &order_claim, block_mean_value(&r->order_difference[0]),
                     block_mean_se(&r->order_difference[0]),
                     "squared error against the 96-direction brute force, rows minus Morton, GTAO medium denoised, "
                     "one frame, on the %dx%d pass, mean over %ld 8x8 blocks of %s (s.e. over blocks); below 0: "
                     "rows better",
                     t->half_width, t->half_height, r->order_difference[0].blocks, scenes);
}

/* The talk-setting figures in words, beside gtlab's 256x256 ones. */
static void talk_paragraph(report *doc, const gtao_talk_result *t)
{
    if (t->scene_count == 0)
        return;
    const gtao_pattern_result *r = &t->pattern;
    char scenes[256];
    gtao_talk_scenes_text(t, scenes, sizeof scenes);
    report_paragraph(doc,
                     "In the talk's setting (the claims table's rows): on the %dx%d pass of %dx%d G-buffers of %s, "
                     "the 24-frame cycle is RMSE %.4f ± %.4f from its 96 directions (%.2f code values); rows minus "
                     "Morton in squared error %+.2e ± %.1e after 1 frame, %+.2e ± %.1e after 24.",
                     t->half_width, t->half_height, t->full_width, t->full_height, scenes, r->cycle_rmse,
                     r->cycle_rmse_se, r->cycle_rmse / CLAIM_ONE_CODE_VALUE_8BIT,
                     block_mean_value(&r->order_difference[0]), block_mean_se(&r->order_difference[0]),
                     block_mean_value(&r->order_difference[1]), block_mean_se(&r->order_difference[1]));
}

void gtao_pattern_section(report_context *ctx, const gtao_pattern_result *r, const gtao_talk_result *t,
                          cJSON *summary)
{
    report_heading(ctx->doc, 3, "The spatio-temporal pattern");
    report_paragraph(
        ctx->doc,
        "The talk's configuration (GTAO medium: one direction per pixel, 4 samples per side, the 4x4 bilateral "
        "filter, temporal accumulation with a static camera) against its brute force: the same configuration "
        "with all %d directions of the pattern in one frame (regular slices, no filter). Over a 4x4 tile and the "
        "24-frame cycle the pattern visits each of the 96 directions exactly 4 times, so before any filter the "
        "tile's accumulation equals the brute force to float rounding (techniques/gtao/tests/test_gtao_pattern.c); "
        "what remains here is the bilateral filter's weights and the step offsets. RMSE against the brute "
        "force, in the talk's row order and with the directions in Morton order:",
        GTAO_PATTERN_DIRECTIONS);
    report_rows(ctx->doc, NULL, scene_columns, COLUMNS(scene_columns), r->scenes, sizeof r->scenes[0],
                r->scene_count);
    const block_mean *d = r->order_difference;
    report_paragraph(
        ctx->doc,
        "Pooled over the scenes (8x8-pixel blocks, standard errors over blocks): after the 24-frame cycle the "
        "RMSE to the brute force is %.4f ± %.4f (one 8-bit code value is %.4f; the height-field reference's own "
        "noise RMSE, %.4f, only says how well a reference could tell). "
        "Rows minus Morton in squared error (negative: rows better): %+.2e ± %.1e after 1 frame, %+.2e ± %.1e "
        "after 24.",
        r->cycle_rmse, r->cycle_rmse_se, CLAIM_ONE_CODE_VALUE_8BIT, r->hf_noise_rmse, block_mean_value(&d[0]),
        block_mean_se(&d[0]),
        block_mean_value(&d[1]), block_mean_se(&d[1]));
    talk_paragraph(ctx->doc, t);
    add_summary(r, summary);
    cJSON *x = cJSON_AddObjectToObject(cJSON_GetObjectItem(summary, "pattern"), "talk_setting");
    cJSON_AddNumberToObject(x, "cycle_rmse", t->pattern.cycle_rmse);
    cJSON_AddNumberToObject(x, "cycle_rmse_se", t->pattern.cycle_rmse_se);
    cJSON_AddNumberToObject(x, "rows_minus_morton_mse", block_mean_value(&t->pattern.order_difference[0]));
    cJSON_AddNumberToObject(x, "rows_minus_morton_mse_se", block_mean_se(&t->pattern.order_difference[0]));
    add_claims(ctx, t);
}
