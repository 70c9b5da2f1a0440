/* A stage's part of the report (report/report_part.h): sections written
 * directly into one report, and the same sections recorded as parts, written,
 * read back and replayed, give the same report.md, report.html, summary and
 * claims, byte for byte; every call of report_writer.h is among them, with
 * the doubles a JSON number cannot hold (NaN, infinities, -0). A part that
 * is malformed, of another stage or of another quality is refused. */
#include "report/report_part.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "report/report_frame.h"
#include "tests/check.h"
#include "tests/test_files.h"

static const claim_record kClaim = {
    .talk = "A 2020", .seed = "000", .section = "Slide 1", .quote = "at most one percent", .setting = "1080p",
    .reading = "the error is at most 0.01", .form = CLAIM_RANGE, .low = -INFINITY, .high = 0.01,
    .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER, .tolerance = "the claim's 1%"};

/* The first made-up stage: headings, prose, a table, figures, findings, a headline. */
static void first_stage(report_context *ctx)
{
    report_heading(ctx->doc, 2, "First technique");
    report_paragraph(ctx->doc, "A paragraph with <markup> & a figure %.3f.", 0.125);
    report_finding(ctx->doc, "First", "it wins by %d", 3);
    const char *headers[] = {"variant", "RMSE"}, *row[] = {"a | b", "0.1"};
    report_table_begin(ctx->doc, 2, headers);
    report_table_row(ctx->doc, row);
    report_table_best_row(ctx->doc, (const char *const[]){"c", "0.05"});
    report_table_end(ctx->doc);
    const char *paths[] = {"figures/a.png", "figures/b.png"}, *captions[] = {"a", "b"};
    report_figures(ctx->doc, 2, paths, captions);
    report_headline h = {.topic = "First", .measure = "RMSE", .best = "a", .runner_up = "b", .best_error = 1.0 / 3.0,
                         .runner_up_error = NAN, .margin = -0.0, .samples_factor_to_decide = INFINITY};
    headline_from_difference(&h, 0.02, 0.001, "paired over 6 scenes");
    report_add_headline(ctx->doc, &h);
    cJSON_AddNumberToObject(cJSON_AddObjectToObject(ctx->summary, "first"), "rmse", 0.1);
    /* 0.1 + 0.2 needs 17 digits: a part must keep its bits */
    claims_table_add(ctx->claims, &kClaim, 0.1 + 0.2, 0.001 / 3.0, "the error (%s)", "made up");
}

/* The second: a level-3 heading repeating a first-stage anchor, a comparison. */
static void second_stage(report_context *ctx)
{
    report_heading(ctx->doc, 2, "Second technique");
    report_heading(ctx->doc, 3, "First technique");
    const char *paths[] = {"figures/r.png", "figures/e.png"}, *labels[] = {"radiance", "error"};
    report_comparison(ctx->doc, 2, paths, labels, 1, "One view two ways");
    report_finding(ctx->doc, "Second", "%s", "equal to a viewer");
    cJSON_AddStringToObject(ctx->summary, "second", "text");
}

typedef void (*stage_fn)(report_context *);
static const stage_fn kStages[2] = {first_stage, second_stage};
static const char *const kKeys[2] = {"first", "second"};

static char *read_all(const char *path)
{
    char *text = NULL;
    FILE *f = fopen(path, "rb");
    if (f && fseek(f, 0, SEEK_END) == 0) {
        long n = ftell(f);
        rewind(f);
        if (n >= 0 && (text = calloc(1, (size_t)n + 1)) && fread(text, 1, (size_t)n, f) != (size_t)n)
            free(text), text = NULL;
    }
    if (f)
        fclose(f);
    return text;
}

static void make_dir(char *dir, size_t size, const char *name)
{
    snprintf(dir, size, "%s/report_part_%s", check_tmp_dir(), name);
    mkdir(dir, 0777);
}

/* A context writing a fresh report into dir. */
static void context_begin(report_context *ctx, report *doc, claims_table *claims, const char *dir)
{
    memset(ctx, 0, sizeof *ctx);
    memset(claims, 0, sizeof *claims);
    ctx->study.output_dir = dir;
    ctx->study.quality = QUALITY_PREVIEW;
    report_init(doc, "t");
    ctx->doc = doc;
    ctx->summary = cJSON_CreateObject();
    ctx->claims = claims;
    report_introduce(ctx, NULL, NULL, NULL);
}

static void context_end(report_context *ctx)
{
    gt_error e;
    claims_table_render(ctx->claims, ctx->doc, ctx->summary);
    CHECK(report_write(ctx->doc, ctx->study.output_dir, &e) == 0);
    CHECK(report_write_summary(ctx, &e) == 0);
    report_free(ctx->doc);
    cJSON_Delete(ctx->summary);
}

/* Stage k recorded, written as a part and read back (NULL on failure). */
static cJSON *part_of_stage(const report_context *ctx, int k)
{
    report_part_recorder rec;
    report_context stage;
    gt_error e;
    cJSON *part = NULL;
    CHECK(report_part_begin(&rec, ctx, &stage, &e) == 0);
    kStages[k](&stage);
    cJSON *made = report_part_end(&rec, ctx, kKeys[k], NULL, 1.5, &e);
    CHECK(made && report_part_write(ctx->study.output_dir, made, &e) == 0);
    cJSON_Delete(made);
    CHECK(report_part_read(ctx->study.output_dir, kKeys[k], &part, &e) == 1);
    return part;
}

static void check_same_file(const char *a_dir, const char *b_dir, const char *name)
{
    char a_path[4096], b_path[4096];
    snprintf(a_path, sizeof a_path, "%s/%s", a_dir, name);
    snprintf(b_path, sizeof b_path, "%s/%s", b_dir, name);
    char *a = read_all(a_path), *b = read_all(b_path);
    CHECK_MSG(a && b && strcmp(a, b) == 0, "%s differs between the direct and the replayed report", name);
    free(a), free(b);
}

static void test_replay_is_the_direct_report(void)
{
    static claims_table direct_claims, replayed_claims;
    char direct_dir[2048], replayed_dir[2048];
    report direct_doc, replayed_doc;
    report_context direct, replayed;
    make_dir(direct_dir, sizeof direct_dir, "direct");
    make_dir(replayed_dir, sizeof replayed_dir, "replayed");
    context_begin(&direct, &direct_doc, &direct_claims, direct_dir);
    context_begin(&replayed, &replayed_doc, &replayed_claims, replayed_dir);
    cJSON *parts[2];
    gt_error e;
    for (int k = 0; k < 2; ++k) {
        kStages[k](&direct);
        parts[k] = part_of_stage(&replayed, k);
    }
    for (int k = 0; k < 2; ++k)
        CHECK(parts[k] && report_part_replay(&replayed, parts[k], kKeys[k], &e) == 0);
    CHECK(replayed_claims.count == 1 && replayed_claims.rows[0].record.low == -INFINITY);
    CHECK(replayed_claims.rows[0].figure == direct_claims.rows[0].figure &&
          replayed_claims.rows[0].ci_high == direct_claims.rows[0].ci_high);
    CHECK(replayed_doc.headlines[0].best_error == direct_doc.headlines[0].best_error);
    CHECK(replayed_doc.headline_count == 1 && isnan(replayed_doc.headlines[0].runner_up_error) &&
          signbit(replayed_doc.headlines[0].margin));
    context_end(&direct);
    context_end(&replayed);
    static const char *const files[] = {"report.md", "report.html", "summary.json", "claims.md"};
    for (int i = 0; i < 4; ++i)
        check_same_file(direct_dir, replayed_dir, files[i]);
    for (int k = 0; k < 2; ++k)
        cJSON_Delete(parts[k]);
}

/* A part with a call the report does not have, one of another stage, one of
 * another quality: each refused in words naming it. */
static void test_refusals(void)
{
    char dir[2048], path[4096];
    make_dir(dir, sizeof dir, "refused");
    snprintf(path, sizeof path, "%s/parts", dir);
    mkdir(path, 0777);
    snprintf(path, sizeof path, "%s/parts/x.json", dir);
    CHECK(write_text_file(path, "{\"gtlab_version\": \"" GTLAB_VERSION "\", \"quality\": \"production\", "
                                "\"project\": \"\", \"stage\": \"x\", \"seconds\": 1, \"journal\": "
                                "[[\"paragraph\", \"ok\"], [\"shout\", \"no\"]], \"summary\": {}, \"claims\": []}") == 0);
    cJSON *part = NULL;
    gt_error e;
    char why[256];
    CHECK(report_part_read(dir, "y", &part, &e) == 0); /* none */
    CHECK(report_part_read(dir, "x", &part, &e) == 1);
    CHECK(report_part_matches(part, QUALITY_PREVIEW, NULL, why, sizeof why) == -1 && strstr(why, "production"));
    CHECK(report_part_matches(part, QUALITY_PRODUCTION, NULL, why, sizeof why) == 0);
    CHECK(report_part_matches(part, QUALITY_PRODUCTION, "p.json", why, sizeof why) == -1);
    static claims_table claims;
    report doc;
    report_context ctx;
    context_begin(&ctx, &doc, &claims, dir);
    CHECK(report_part_replay(&ctx, part, path, &e) == -1 && strstr(e.message, "journal[1]"));
    report_free(&doc);
    cJSON_Delete(ctx.summary);
    cJSON_Delete(part);
    char other[4096];
    snprintf(other, sizeof other, "%s/parts/z.json", dir);
    CHECK(rename(path, other) == 0);
    CHECK(report_part_read(dir, "z", &part, &e) == -1 && strstr(e.message, "not the part of stage z"));
}

int main(void)
{
    test_replay_is_the_direct_report();
    test_refusals();
    return check_report("test_report_part");
}
