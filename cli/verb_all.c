/* gtlab all: the main job — every reference, fit, LUT and validation, and the
 * accuracy report (report.md, report.html, summary.json). */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "ao/ao_quality.h"
#include "report/report_context.h"
#include "report/report_frame.h"
#include "report/scene_list_section.h"
#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/files/atomic_file.h"
#include "core/files/output_set.h"
#include "core/progress.h"
#include "core/files/run_inputs.h"
#include "core/threads.h"

enum { STAGE_MAX = 64 };

/* The stages of the registered techniques, in the report's order. */
static const all_stage *stages[STAGE_MAX];
static int stage_count;

static const char *quality_name(int i) { return study_quality_name((study_quality)i); }

static const cli_option options[] = {
    CLI_CHOICE("quality", "Q", quality_name, STUDY_QUALITY_COUNT, "preview (a few minutes on 2 cores) or production"),
    CLI_OUTPUT("DIR", 0, "output folder"),
    CLI_INT32("threads", "T", 1, 1024, "worker threads (default: all cores; results do not depend on it)"),
    CLI_STRING("stages", "LIST", "comma-separated stage names from the list above (default: all);\n"
               "the report then holds those sections only. A stage that reads\n"
               "another's output uses it from this run, or from an earlier run\n"
               "into the same DIR"),
    CLI_STRING("project", "FILE", "a project file (gtlab init writes one): its scenes instead of the\n"
               "built-in ones; its quality, stages and output unless given here"),
    CLI_END};

/* The help's paragraph, with the registered stages. */
static void describe(char *text, size_t size)
{
    int k = snprintf(text, size, "Runs every stage on the built-in (or --project) scenes; writes the accuracy report:\n"
                     "  DIR/report.md, DIR/report.html   the report (figures under DIR/figures)\n"
                     "  DIR/summary.json                 every figure of the report, machine-readable\n"
                     "  DIR/ao/*.exr                     the references (with their .camera.json)\nStages:");
    for (int i = 0; i < stage_count && k < (int)size; ++i)
        k += snprintf(text + k, size - (size_t)k, "\n  %-20s %s%s%s", stages[i]->key, stages[i]->title,
                      stages[i]->needs ? ", reads the output of " : "", stages[i]->needs ? stages[i]->needs : "");
}

static int stage_index(const char *key);

/* Marks the stages named in the comma-separated list; -1 after an error (printed). */
static int select_stages(const char *list, int selected[STAGE_MAX])
{
    char copy[512];
    snprintf(copy, sizeof copy, "%s", list);
    memset(selected, 0, sizeof(int) * STAGE_MAX);
    for (char *tok = strtok(copy, ","); tok; tok = strtok(NULL, ",")) {
        int found = 0;
        for (int i = 0; i < stage_count; ++i)
            if (strcmp(tok, stages[i]->key) == 0)
                selected[i] = found = 1;
        const char *now = found ? NULL : technique_renamed(tok);
        if (now && stage_index(now) >= 0)
            return cli_failf("--stages", "stage '%s' is now '%s'", tok, now), -1;
        if (!found)
            return cli_failf("--stages", "unknown stage '%s' (see 'gtlab all --help')", tok), -1;
    }
    for (int i = 0; i < stage_count; ++i)
        if (selected[i])
            return 0;
    return cli_failf("--stages", "no stage named in '%s'", list), -1;
}

static int stage_index(const char *key)
{
    for (int i = 0; i < stage_count; ++i)
        if (strcmp(stages[i]->key, key) == 0)
            return i;
    return -1;
}

/* Whether key is a stage; if not, *now is its name today if it was renamed. */
static int stage_known_or_renamed(const char *key, const char **now)
{
    const char *renamed = technique_renamed(key);
    *now = stage_index(key) < 0 && renamed && stage_index(renamed) >= 0 ? renamed : NULL;
    return stage_index(key) >= 0;
}

static study_project project_file; /* --project FILE */

/* Parses the options into ctx and selected; 1 and the exit status to stop. */
static int parse_options(int argc, char **argv, report_context *ctx, int selected[STAGE_MAX], const char **stage_list,
                         const char **project, int *status)
{
    char description[8192];
    describe(description, sizeof description);
    const cli_command command = {"all", description, options, NULL, NULL};
    study_context *s = &ctx->study;
    gt_error e;
    if (cli_options_parse(&command, (void *[]){&s->quality, &s->output_dir, &s->threads, stage_list, project}, argc,
                          argv, status) != 0)
        return 1;
    if (*project && study_project_read(*project, stage_known_or_renamed, &project_file, &e) != 0)
        return *status = cli_fail(&e), 1;
    study_project_apply(*project ? &project_file : NULL, s, stage_list);
    /* The built-in scene set is every study's: the AO references stage renders it first. */
    s->study_scenes = ao_quality_of(s->quality)->study_scenes;
    return *stage_list && select_stages(*stage_list, selected) != 0 ? (*status = EXIT_USER_ERROR, 1) : 0;
}

/* Every selected stage's input is made earlier in this run or was made by an
 * earlier run into the same folder: checked before any work. */
static int check_inputs(const report_context *ctx, const int selected[STAGE_MAX])
{
    for (int i = 0; i < stage_count; ++i) {
        if (!selected[i] || !stages[i]->needs)
            continue;
        int k = stage_index(stages[i]->needs);
        if (k < 0 || k >= i || !stages[k]->writes)
            return cli_failf("all", "stage %s reads stage %s, which is not registered before it", stages[i]->key,
                             stages[i]->needs), -1;
        char path[4096];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", ctx->study.output_dir, stages[k]->writes);
        if (!selected[k] && (stat(path, &st) != 0 || !S_ISDIR(st.st_mode)))
            return cli_failf(path, "stage %s reads what stage %s writes here: add %s to --stages", stages[i]->key,
                             stages[k]->key, stages[k]->key), -1;
    }
    return 0;
}

/* No input of the run (the project and the files it names) is where the
 * run writes: the output folder itself, the report's files, figures/ and
 * each selected stage's folder; checked before any work (core/files/atomic_file.c
 * refuses any other input at its write). */
static int check_outputs(const report_context *ctx, const int selected[STAGE_MAX])
{
    static const char *const report_files[] = {"report.md", "report.html", "summary.json", "claims.md"};
    const char *dir = ctx->study.output_dir;
    char path[4096], what[128];
    gt_error e;
    if (run_inputs_check_output(dir, &e) != 0)
        return cli_fail(&e), -1;
    for (size_t i = 0; i < sizeof report_files / sizeof report_files[0]; ++i) {
        snprintf(path, sizeof path, "%s/%s", dir, report_files[i]);
        if (run_inputs_check_output(path, &e) != 0)
            return cli_fail(&e), -1;
    }
    snprintf(path, sizeof path, "%s/figures", dir);
    if (run_inputs_check_folder(path, "the report's figures are written there", &e) != 0)
        return cli_fail(&e), -1;
    for (int i = 0; i < stage_count; ++i) {
        if (!selected[i] || !stages[i]->writes)
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, stages[i]->writes);
        snprintf(what, sizeof what, "the stage %s writes there", stages[i]->key);
        if (run_inputs_check_folder(path, what, &e) != 0)
            return cli_fail(&e), -1;
    }
    return 0;
}

/* Each stage's wall time goes into summary.json's "stage_seconds" (by the
 * stage's --stages key, then "total"), so a run's cost is read, not guessed
 * (issue 46 item 4). */
static int run_stages(report_context *ctx, const int selected[STAGE_MAX])
{
    gt_error e;
    cJSON *stage_seconds = cJSON_AddObjectToObject(ctx->summary, "stage_seconds");
    double start = seconds_now();
    for (int i = 0; i < stage_count; ++i) {
        if (!selected[i])
            continue;
        fprintf(stderr, "gtlab all: %s\n", stages[i]->title);
        double t0 = seconds_now();
        if (stages[i]->run(ctx, &e) != 0)
            return cli_fail(&e);
        /* A finished stage keeps its files, whatever happens later. */
        if (output_set_commit(&e) != 0)
            gt_warn("gtlab all", "%s", e.message);
        output_set_begin();
        double seconds = seconds_now() - t0;
        cJSON_AddNumberToObject(stage_seconds, stages[i]->key, seconds);
        fprintf(stderr, "gtlab all: %s done in %.1f s\n", stages[i]->title, seconds);
    }
    cJSON_AddNumberToObject(stage_seconds, "total", seconds_now() - start);
    if (claims_table_check(ctx->claims, &e) != 0) { /* a record the protocol refuses: gtlab's own fault */
        cli_fail(&e);
        return EXIT_INTERNAL_ERROR;
    }
    claims_table_render(ctx->claims, ctx->doc, ctx->summary);
    if (report_write(ctx->doc, ctx->study.output_dir, &e) != 0 || report_write_summary(ctx, &e) != 0)
        return cli_fail(&e);
    return EXIT_OK;
}

int verb_all(int argc, char **argv)
{
    stage_count = (int)technique_stages(stages, STAGE_MAX);
    static claims_table claims;
    report_context ctx = {{NULL, (study_quality)-1, threads_default(), NULL, NULL, 0}, NULL, NULL, &claims};
    int selected[STAGE_MAX];
    for (int i = 0; i < STAGE_MAX; ++i)
        selected[i] = 1;
    const char *stage_list = NULL, *project = NULL;
    int status;
    if (parse_options(argc, argv, &ctx, selected, &stage_list, &project, &status) != 0)
        return status;
    if (check_inputs(&ctx, selected) != 0 || check_outputs(&ctx, selected) != 0)
        return EXIT_USER_ERROR;
    if ((status = cli_make_output_dir(ctx.study.output_dir)) != 0)
        return status;
    char probe[4096];
    snprintf(probe, sizeof probe, "%s/report.md", ctx.study.output_dir);
    gt_error e;
    if (atomic_file_check_writable(probe, &e) != 0)
        return cli_fail(&e);
    report doc;
    report_init(&doc, "gtlab accuracy report");
    ctx.doc = &doc;
    ctx.summary = cJSON_CreateObject();
    report_introduce(&ctx, stage_list, project);
    scene_list_section(&ctx, &project_file, project);
    status = run_stages(&ctx, selected);
    if (status == EXIT_OK)
        printf("report: %s/report.html and %s/report.md\n", ctx.study.output_dir, ctx.study.output_dir);
    report_free(&doc);
    cJSON_Delete(ctx.summary);
    return status;
}

static const cli_option init_options[] = {CLI_OUTPUT("FILE", 0, "the project file to write (default gtlab.json)"),
                                          CLI_END};

int verb_init(int argc, char **argv)
{
    const char *path = "gtlab.json";
    int status;
    const char *about = "Writes an example project file for 'gtlab all --project FILE'; never overwrites one.";
    const cli_command command = {"init", about, init_options, NULL, NULL};
    gt_error e;
    if (cli_options_parse(&command, (void *[]){&path}, argc, argv, &status) != 0)
        return status;
    return study_project_write_example(path, &e) != 0 ? cli_fail(&e) : (printf("wrote %s\n", path), EXIT_OK);
}
