/* The GTAO sections' claims rows (issue 42) from made-up results (no study
 * runs): every row is a record the builder accepts, its figure is the one
 * the struct holds (a shortcut's own change where the row says so, never
 * the technique's total error), and its verdict is the one the record's
 * tolerance and setting give those figures: reproduced, refuted, "fails a
 * stronger reading", not significant and no visible difference all occur.
 * The shortcut rows measured in the talk's setting (issue 42, item 4: a
 * 1080p frame at half resolution) take their figures from the talk-setting
 * results, not from gtlab's 256x256 runs, which are given figures that
 * would give another verdict; with the talk's setting reproduced a failing
 * figure is "refuted", no longer "fails under gtlab's setting". */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "gtao/gtao_checks_section.h"
#include "gtao/gtao_shortcuts_section.h"
#include "report/claim_thresholds.h"
#include "tests/check.h"

enum { SIDE = 32 };

/* A block mean of an image holding v everywhere (standard error 0). */
static block_mean constant_blocks(float v)
{
    static float x[SIDE * SIDE];
    for (int i = 0; i < SIDE * SIDE; ++i)
        x[i] = v;
    block_mean m = {0, 0.0, 0.0};
    block_mean_add(&m, x, NULL, SIDE, SIDE, BLOCK_MEAN_SIZE);
    return m;
}

typedef struct {
    const char *what;
    double figure;
    claim_verdict verdict;
} expected_row;

/* The rows added since `first` against the expected ones. */
static void check_rows(const claims_table *t, int first, const expected_row *want, int count)
{
    CHECK_MSG(t->count - first == count, "%s: %d rows", want[0].what, t->count - first);
    CHECK_MSG(t->refused == 0, "refused: %s", t->first_refusal);
    for (int i = 0; i < count && first + i < t->count; ++i) {
        const claim *c = &t->rows[first + i];
        CHECK_MSG(fabs(c->figure - want[i].figure) <= 1e-9 * fmax(1.0, fabs(want[i].figure)), "%s: figure %g",
                  want[i].what, c->figure);
        CHECK_MSG(c->verdict == want[i].verdict, "%s: %s", want[i].what, c->verdict_name);
        CHECK_MSG(c->record.quote && strcmp(c->record.seed, "001") == 0, "%s: no quote", want[i].what);
    }
}

/* Fast maths 1.2 code values in the talk's setting (fails the stronger
 * reading the row names; gtlab's 256x256 figure, 0.2, is not the row's);
 * baselines: GTAO better by 1e-3 of MSE (reproduced), the pitfall better
 * than the talk's integrand by 1e-3 (refuted); bent normals 0.1 deg worse
 * (as good: reproduced); thickness 0.2 +- 0.5 code values (not
 * significant); the fade's own change 3 code values off the truth's (fails
 * the stronger reading it names). */
static void test_checks(report_context *ctx)
{
    static gtao_fast_math_result fm;
    static gtao_baselines_result bl;
    static gtao_bent_normals_result bn;
    static gtao_thickness_result th;
    static gtao_distance_fade_result fd;
    const double code = CLAIM_ONE_CODE_VALUE_8BIT;
    fm.scene_count = 1;
    fm.medium_change = (cluster_mean){0.2 * code, 0.01 * code, 1000, 16}; /* gtlab's 256x256: not the row's */
    fm.talk_scene_count = 1, fm.talk_width = 960, fm.talk_height = 540;
    fm.talk_change = (cluster_mean){1.2 * code, 0.01 * code, 1000, 16}; /* past the stronger reading */
    fm.medium_paired_hf = (cluster_mean){1.0, 0.001, 1000, 16}; /* the old figure: not the row's */
    bl.pooled_rmse_3d[BASELINE_ALCHEMY] = 0.05, bl.pooled_rmse_3d[BASELINE_CRYTEK] = 0.1;
    bl.pooled_vs_gtao_3d[BASELINE_ALCHEMY] = (cluster_mean){1e-3, 1e-4, 1000, 16};
    bl.pooled_vs_gtao_3d[BASELINE_PITFALL] = (cluster_mean){-1e-3, 1e-4, 1000, 16}; /* the pitfall better */
    bn.pooled_halfway_vs_horizons = (cluster_mean){0.1, 0.05, 1000, 16};
    th.scene_count = 1, th.corner_scene = 0, th.best = 0;
    th.rows[0][0].change = (cluster_mean){0.2 * code, 0.5 * code, 1000, 16};
    fd.scene_count = 1;
    fd.pooled_change_vs_truth = (cluster_mean){3.0 * code, 0.2 * code, 1000, 16};
    fd.pooled_signed_vs_faded = (cluster_mean){0.0, 0.0001, 1000, 16}; /* the old figure: not the row's */
    int first = ctx->claims->count;
    gtao_fast_math_section(ctx, &fm, ctx->summary);
    gtao_baselines_section(ctx, &bl, ctx->summary);
    gtao_bent_normals_section(ctx, &bn, ctx->summary);
    gtao_thickness_section(ctx, &th, ctx->summary);
    gtao_distance_fade_section(ctx, &fd, ctx->summary);
    const expected_row want[] = {
        {"fast maths", 1.2 * code, CLAIM_FAILS_STRONGER_READING},
        {"baselines", -1e-3, CLAIM_REPRODUCED},
        {"pitfall", 1e-3, CLAIM_REFUTED},
        {"bent normals", 0.1, CLAIM_REPRODUCED},
        {"thickness", 0.2 * code, CLAIM_NOT_SIGNIFICANT},
        {"distance fade", 3.0 * code, CLAIM_FAILS_STRONGER_READING},
    };
    check_rows(ctx->claims, first, want, (int)(sizeof want / sizeof want[0]));
}

/* In the talk's setting: half resolution, MIN minus point-sampled MIP worse
 * by 1e-3 of MSE (refuted), the talk's variant changing the AO by half a
 * code value (reproduced); the cycle 5 code values of RMSE from the 96
 * directions (fails the stronger reading it names), rows better than Morton by 1e-3 (reproduced); the
 * depth test better at edges (reproduced), 1e-6 on flat pixels (no visible
 * difference); the alternating window leaving half a pixel on a gradient of
 * 0.05 per pixel, 6 code values (refuted). gtlab's 256x256 results hold
 * figures that would give other verdicts. */
static void test_shortcuts(report_context *ctx)
{
    static gtao_shortcuts_result s;
    const double code = CLAIM_ONE_CODE_VALUE_8BIT;
    gtao_half_res_result *own = &s.half_res; /* gtlab's 256x256: not the rows' */
    own->scene_count = 1, own->radius_count = 1;
    own->radii[0].radius_fraction = GTAO_HALF_RES_4X_RADIUS;
    own->radii[0].change[GTAO_HALF_RES_HALF_MIP_MIN] = constant_blocks((float)(11.0 * code));
    own->min_vs_mip_mean = -1e-3, own->min_vs_mip_se = 1e-4;
    s.pattern.scene_count = 1, s.pattern.cycle_rmse = 0.0, s.pattern.cycle_rmse_se = 0.0;
    s.denoisers.scene_count = 1;
    gtao_talk_result *t = &s.talk;
    t->scene_count = 1, t->full_width = 1920, t->full_height = 1080, t->half_width = 960, t->half_height = 540;
    snprintf(t->scenes[0], sizeof t->scenes[0], "boxes");
    gtao_half_res_result *h = &t->half_res;
    h->scene_count = 1, h->radius_count = 1;
    h->radii[0].radius_fraction = GTAO_HALF_RES_4X_RADIUS;
    h->radii[0].change[GTAO_HALF_RES_HALF_MIP_MIN] = constant_blocks((float)(0.5 * code));
    h->radii[0].se2[GTAO_HALF_RES_HALF_MIP_MIN] = constant_blocks(1.0f); /* RMSE 1: not the row's figure */
    t->half_pass.scene_count = 1;
    t->half_pass.min_vs_mip_mean = 1e-3, t->half_pass.min_vs_mip_se = 1e-4;
    gtao_pattern_result *p = &t->pattern;
    p->scene_count = 1;
    p->cycle_rmse = 5.0 * code, p->cycle_rmse_se = 0.1 * code;
    p->hf_noise_rmse = 1.0; /* a noise floor that would have passed it */
    p->order_difference[0] = constant_blocks(-1e-3f);
    gtao_denoisers_result *d = &t->denoisers;
    d->scene_count = 1;
    d->d2_minus_log_edge = constant_blocks(-1e-3f);
    d->d2_minus_log_flat = constant_blocks(1e-6f);
    d->shift_with[0] = d->shift_with[1] = 0.5;
    d->shift_with_se[0] = d->shift_with_se[1] = 0.02;
    d->diagonal_rms_gradient = 0.05; /* 0.025 of AO change: 6 code values */
    int first = ctx->claims->count;
    gtao_shortcuts_section(ctx, &s);
    const expected_row want[] = {
        {"MIN filter", 1e-3, CLAIM_REFUTED},
        {"half resolution", (float)(0.5 * code), CLAIM_REPRODUCED},
        {"cycle", 5.0 * code, CLAIM_FAILS_STRONGER_READING},
        {"row order", -1e-3f, CLAIM_REPRODUCED},
        {"depth test, edges", -1e-3f, CLAIM_REPRODUCED},
        {"depth test, flat", 1e-6f, CLAIM_NO_VISIBLE_DIFFERENCE},
        {"alternating window", 0.5 * 0.05, CLAIM_REFUTED},
    };
    check_rows(ctx->claims, first, want, (int)(sizeof want / sizeof want[0]));
    /* Every row at the talk's 960x540; the depth test's two rows judge
     * gtlab's reconstruction of the filter, so under gtlab's setting. */
    for (int i = first; i < ctx->claims->count; ++i) {
        int depth = i - first == 4 || i - first == 5;
        CHECK_MSG(ctx->claims->rows[i].record.setting_match == (depth ? CLAIM_SETTING_GTLAB : CLAIM_SETTING_TALK) &&
                      strstr(ctx->claims->rows[i].quantity, "960x540"),
                  "row %d: not in the setting expected", i - first);
    }
}

int main(void)
{
    char dir[2048];
    snprintf(dir, sizeof dir, "%s/gtao_claims_output", check_tmp_dir());
    mkdir(dir, 0755);
    static claims_table claims;
    report doc;
    report_init(&doc, "test");
    report_context ctx = {{dir, QUALITY_PREVIEW, 1, NULL, NULL, 0}, &doc, cJSON_CreateObject(), &claims};
    test_checks(&ctx);
    test_shortcuts(&ctx);
    report_free(&doc);
    cJSON_Delete(ctx.summary);
    return check_report("test_gtao_claims");
}
