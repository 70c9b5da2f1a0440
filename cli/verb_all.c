/* gtlab all: the main job — every reference, fit, LUT and validation, and the
 * accuracy report (report.md, report.html, summary.json). */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include <sys/stat.h>

#include "ao/ao_quality.h"
#include "report/report_context.h"
#include "report/report_frame.h"
#include "report/report_part.h"
#include "cli/all_plan.h"
#include "report/scene_list_section.h"
#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/files/atomic_file.h"
#include "core/files/output_set.h"
#include "core/progress.h"
#include "core/files/run_inputs.h"
#include "core/threads.h"
#include "raytracer/distributed_render.h"

enum { STAGE_MAX = 64 };

/* The stages of the registered techniques, in the report's order. */
static const all_stage *stages[STAGE_MAX];
static int stage_count;

static const char *quality_name(int i) { return study_quality_name((study_quality)i); }

static const cli_option options[] = {
    CLI_CHOICE("quality", "Q", quality_name, STUDY_QUALITY_COUNT, "preview (the quick job) or production"),
    CLI_OUTPUT("DIR", 0, "output folder"),
    CLI_INT32("threads", "T", 1, 1024, "worker threads (default: all cores; results do not depend on it)"),
    CLI_STRING("stages", "LIST", "comma-separated stage names from the list above (default: all);\n"
               "the report keeps the other stages' sections that earlier runs\n"
               "left in DIR/parts. A stage that reads another's output uses it\n"
               "from this run, or from an earlier run into the same DIR"),
    CLI_STRING("project", "FILE", "a project file (gtlab init writes one): its scenes instead of the\n"
               "built-in ones; its quality, stages and output unless given here"),
    CLI_FLAG("assemble", "run no stage: the report from the parts earlier runs (or a plan's\n"
             "tasks) left in DIR/parts, every --stages one required"),
    CLI_FLAG("plan", "run nothing: write DIR/plan/ for a batch scheduler (with --jobs N):\n"
             "jobs.txt, job.sh (a Slurm array, or 'bash job.sh INDEX'), assemble.sh\n"
             "and submit.sh; the tasks run whole chains of stages (--parts-only)\n"
             "and assemble.sh writes the report, the bits of one process.\n"
             "Under 'mpirun -n N gtlab all' the ranks share the stages the same way"),
    CLI_INT("jobs", "N", 1, 64, "the plan's tasks (at most one per chain of stages)"),
    CLI_FLAG("parts-only", "run the stages and write their parts (DIR/parts), no report: a\n"
             "plan's task"),
    CLI_END};

/* How this run goes: its stages and project, and what it does with them. */
typedef struct {
    const char *stage_list, *project;
    int assemble, plan, parts_only;
    long jobs;
} all_mode;

/* The help's paragraph, with the registered stages. */
static void describe(char *text, size_t size)
{
    int k = snprintf(text, size, "Runs every stage on the built-in (or --project) scenes; writes the accuracy report:\n"
                     "  DIR/report.md, DIR/report.html   the report (figures under DIR/figures)\n"
                     "  DIR/summary.json                 every figure of the report, machine-readable\n"
                     "  DIR/ao/*.exr                     the references (with their .camera.json)\n"
                     "  DIR/parts/STAGE.json             each stage's part of the report: a rerun of some\n"
                     "                                   stages keeps the others' sections (same quality\n"
                     "                                   and project)\nStages:");
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
static int parse_options(int argc, char **argv, report_context *ctx, int selected[STAGE_MAX], all_mode *m,
                         int *status)
{
    char description[8192];
    describe(description, sizeof description);
    const cli_command command = {"all", description, options, NULL, NULL};
    study_context *s = &ctx->study;
    gt_error e;
    void *values[] = {&s->quality, &s->output_dir, &s->threads, &m->stage_list, &m->project,
                      &m->assemble,  &m->plan,       &m->jobs,    &m->parts_only};
    if (cli_options_parse(&command, values, argc, argv, status) != 0)
        return 1;
    if (m->project && study_project_read(m->project, stage_known_or_renamed, &project_file, &e) != 0)
        return *status = cli_fail(&e), 1;
    study_project_apply(m->project ? &project_file : NULL, s, &m->stage_list);
    /* The built-in scene set is every study's: the AO references stage renders it first. */
    s->study_scenes = ao_quality_of(s->quality)->study_scenes;
    return m->stage_list && select_stages(m->stage_list, selected) != 0 ? (*status = EXIT_USER_ERROR, 1) : 0;
}

/* The modes that exclude each other, and --jobs with --plan only. */
static int check_mode(const all_mode *m, render_share job)
{
    if (m->plan + m->assemble + m->parts_only > 1)
        return cli_failf("all", "--plan, --assemble and --parts-only exclude each other"), -1;
    if (m->plan != (m->jobs > 0))
        return cli_failf(m->plan ? "--plan" : "--jobs", m->plan ? "needs --jobs N" : "is the plan's: add --plan"), -1;
    if (job.ranks > 1 && (m->plan || m->assemble || m->parts_only))
        return cli_failf("mpirun", "--plan, --assemble and --parts-only run in one process: drop mpirun (under "
                         "mpirun the ranks share the stages by themselves)"), -1;
    return 0;
}

/* The report's parts by stage (report/report_part.h): this run's, or an
 * earlier run's found in DIR/parts with the same quality and project; NULL:
 * none. A part's claims point into it: kept until the report is written. */
static cJSON *parts[STAGE_MAX];

/* Reads the earlier parts of the stages this run does not run (selected[i]
 * 0), before any work: a malformed one is an error, one of another quality
 * or project is left out with a warning. */
static int read_earlier_parts(const report_context *ctx, const int selected[STAGE_MAX], const char *project)
{
    gt_error e;
    char why[256];
    for (int i = 0; i < stage_count; ++i) {
        if (selected[i])
            continue;
        int found = report_part_read(ctx->study.output_dir, stages[i]->key, &parts[i], &e);
        if (found < 0)
            return cli_fail(&e), -1;
        if (found && report_part_matches(parts[i], ctx->study.quality, project, why, sizeof why) != 0) {
            gt_warn(ctx->study.output_dir, "the part of stage %s in parts/ was %s: its section is left out",
                    stages[i]->key, why);
            cJSON_Delete(parts[i]), parts[i] = NULL;
        }
    }
    return 0;
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

/* With --assemble: the stages to assemble, every selected one's part in DIR. */
static int check_parts_present(const report_context *ctx, int selected[STAGE_MAX], const char *stage_list)
{
    int any = 0;
    for (int i = 0; i < stage_count; ++i) {
        if (stage_list && selected[i] && !parts[i])
            return cli_failf(ctx->study.output_dir, "--assemble: no part of stage %s at this quality and project in "
                             "parts/ (run it: gtlab all --stages %s)", stages[i]->key, stages[i]->key), -1;
        if (stage_list && !selected[i])
            cJSON_Delete(parts[i]), parts[i] = NULL;
        any |= parts[i] != NULL;
        selected[i] = 0;
    }
    return any ? 0 : (cli_failf(ctx->study.output_dir, "--assemble: no stage's part in parts/"), -1);
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
    snprintf(path, sizeof path, "%s/%s", dir, REPORT_PARTS_DIR);
    if (run_inputs_check_folder(path, "the stages' parts of the report are written there", &e) != 0)
        return cli_fail(&e), -1;
    snprintf(path, sizeof path, "%s/plan", dir);
    if (run_inputs_check_folder(path, "'gtlab all --plan' writes its files there", &e) != 0)
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

/* Each stage's seconds in an earlier run at this quality and project (its
 * part in DIR), NaN where none: the plan's costs. */
static void known_seconds(const report_context *ctx, const char *project, double seconds[STAGE_MAX])
{
    char why[256];
    gt_error e;
    for (int i = 0; i < stage_count; ++i) {
        cJSON *part = NULL;
        seconds[i] = NAN;
        if (report_part_read(ctx->study.output_dir, stages[i]->key, &part, &e) == 1 &&
            report_part_matches(part, ctx->study.quality, project, why, sizeof why) == 0)
            seconds[i] = report_part_seconds(part);
        cJSON_Delete(part);
    }
}

/* Where a run of the marked stages is: each stage's place among them and
 * its seconds in an earlier run (NaN: not known). */
typedef struct {
    int place[STAGE_MAX], count;
    double last_seconds[STAGE_MAX];
} run_progress;

/* The seconds the stages from i on took last time, or NaN if one is unknown. */
static double seconds_left(const int run[STAGE_MAX], const run_progress *rp, int i)
{
    double left = 0;
    for (int j = i; j < stage_count; ++j)
        if (run[j])
            left += rp->last_seconds[j];
    return left;
}

/* The stage's line ("gtlab all: [3/23] GTAO validation (223 s last time;
 * about 5 min left in all)"), its bar's prefix, and what an interruption
 * says: the stages kept and the command that runs the rest. */
static void announce_stage(const report_context *ctx, const int run[STAGE_MAX], const run_progress *rp, int i,
                           const char *project)
{
    char prefix[128], last[160] = "", took[32], left[32], note[1024];
    snprintf(prefix, sizeof prefix, "[%d/%d %s]", rp->place[i], rp->count, stages[i]->key);
    progress_set_stage(prefix);
    if (!isnan(rp->last_seconds[i])) {
        progress_duration_text(rp->last_seconds[i], took, sizeof took);
        double rest = seconds_left(run, rp, i);
        progress_duration_text(rest, left, sizeof left);
        snprintf(last, sizeof last, " (%s last time%s%s%s)", took, isnan(rest) ? "" : "; about ",
                 isnan(rest) ? "" : left, isnan(rest) ? "" : " left in all");
    }
    fprintf(stderr, "gtlab all: [%d/%d] %s%s\n", rp->place[i], rp->count, stages[i]->title, last);
    int n = snprintf(note, sizeof note, "gtlab all: interrupted in stage %s; the %d stage(s) before it are kept "
                     "with their parts (%s/%s/), and 'gtlab all --quality %s%s%s --stages ", stages[i]->key,
                     rp->place[i] - 1, ctx->study.output_dir, REPORT_PARTS_DIR, study_quality_name(ctx->study.quality),
                     project ? " --project " : "", project ? project : "");
    for (int j = i, first = 1; j < stage_count && n < (int)sizeof note; ++j)
        if (run[j])
            n += snprintf(note + n, sizeof note - (size_t)n, "%s%s", first ? "" : ",", stages[j]->key), first = 0;
    if (n < (int)sizeof note)
        snprintf(note + n, sizeof note - (size_t)n, " -o %s' runs the rest into the same report\n",
                 ctx->study.output_dir);
    output_set_interrupt_note(note);
}

/* Runs stage i with its part recorded, then writes the part (DIR/parts)
 * and keeps the stage's files, whatever happens later. */
static int run_stage(const report_context *ctx, int i, const char *project, gt_error *e)
{
    report_part_recorder rec;
    report_context stage;
    if (report_part_begin(&rec, ctx, &stage, e) != 0)
        return -1;
    double t0 = seconds_now();
    if (stages[i]->run(&stage, e) != 0)
        return report_part_discard(&rec), -1;
    double seconds = seconds_now() - t0;
    if (!(parts[i] = report_part_end(&rec, ctx, stages[i]->key, project, seconds, e)) ||
        report_part_write(ctx->study.output_dir, parts[i], e) != 0)
        return -1;
    gt_error kept;
    if (output_set_commit(&kept) != 0)
        gt_warn("gtlab all", "%s", kept.message);
    output_set_begin();
    output_set_interrupt_note(NULL);
    progress_set_stage(NULL);
    fprintf(stderr, "gtlab all: %s done in %.1f s\n", stages[i]->title, seconds);
    return 0;
}

/* The stages with a part that this run did not make, comma-separated,
 * when it made some ("" for a run of every stage, or one assembling parts
 * alone: its report reads as one process's, whose bits it has). */
static void earlier_stages(const int selected[STAGE_MAX], char *out, size_t size)
{
    size_t n = 0;
    int ran = 0;
    out[0] = 0;
    for (int i = 0; i < stage_count; ++i)
        ran |= selected[i];
    for (int i = 0; ran && i < stage_count && n < size; ++i)
        if (parts[i] && !selected[i])
            n += (size_t)snprintf(out + n, size - n, "%s%s", n ? ", " : "", stages[i]->key);
}

/* Each stage's wall time goes into summary.json's "stage_seconds" (by the
 * stage's --stages key, then "total": their sum), so a run's cost is read,
 * not guessed (issue 46 item 4); then every part, in the stages' order. */
static int replay_parts(report_context *ctx, gt_error *e)
{
    cJSON *stage_seconds = cJSON_AddObjectToObject(ctx->summary, "stage_seconds");
    double total = 0;
    for (int i = 0; i < stage_count; ++i)
        if (parts[i]) {
            cJSON_AddNumberToObject(stage_seconds, stages[i]->key, report_part_seconds(parts[i]));
            total += report_part_seconds(parts[i]);
        }
    cJSON_AddNumberToObject(stage_seconds, "total", total);
    char what[4096];
    for (int i = 0; i < stage_count; ++i) {
        snprintf(what, sizeof what, "%s/%s/%s.json", ctx->study.output_dir, REPORT_PARTS_DIR, stages[i]->key);
        if (parts[i] && report_part_replay(ctx, parts[i], what, e) != 0)
            return -1;
    }
    return 0;
}

/* The report from the parts: introduction, scenes, every part, claims. */
static int assemble_report(report_context *ctx, const int selected[STAGE_MAX], const char *stage_list,
                           const char *project)
{
    char earlier[2048];
    gt_error e;
    earlier_stages(selected, earlier, sizeof earlier);
    report_introduce(ctx, stage_list, project, earlier);
    scene_list_section(ctx, &project_file, project);
    if (replay_parts(ctx, &e) != 0)
        return cli_fail(&e);
    if (claims_table_check(ctx->claims, &e) != 0) { /* a record the protocol refuses: gtlab's own fault */
        cli_fail(&e);
        return EXIT_INTERNAL_ERROR;
    }
    claims_table_render(ctx->claims, ctx->doc, ctx->summary);
    if (report_write(ctx->doc, ctx->study.output_dir, &e) != 0 || report_write_summary(ctx, &e) != 0)
        return cli_fail(&e);
    return EXIT_OK;
}

/* The report assembled from parts[] into DIR (selected: what this run ran). */
static int assemble_and_print(report_context *ctx, const int selected[STAGE_MAX], const all_mode *m)
{
    report doc;
    report_init(&doc, "gtlab accuracy report");
    ctx->doc = &doc;
    ctx->summary = cJSON_CreateObject();
    int status = assemble_report(ctx, selected, m->stage_list, m->project);
    if (status == EXIT_OK)
        printf("report: %s/report.html and %s/report.md\n", ctx->study.output_dir, ctx->study.output_dir);
    report_free(&doc);
    cJSON_Delete(ctx->summary);
    return status;
}

/* Runs the stages marked in run (each its part); -1 after the error. */
static int run_marked(const report_context *ctx, const int run[STAGE_MAX], const char *project, int *status)
{
    gt_error e;
    run_progress rp = {.count = 0};
    known_seconds(ctx, project, rp.last_seconds);
    for (int i = 0; i < stage_count; ++i)
        rp.place[i] = run[i] ? ++rp.count : 0;
    for (int i = 0; i < stage_count; ++i) {
        if (!run[i])
            continue;
        announce_stage(ctx, run, &rp, i, project);
        if (run_stage(ctx, i, project, &e) != 0)
            return *status = cli_fail(&e), -1;
    }
    return 0;
}

static void print_plan(const report_context *ctx, const all_plan *plan)
{
    printf("%s/plan: %d tasks (jobs.txt, job.sh), assemble.sh; 'bash %s/plan/submit.sh' submits them to Slurm\n",
           ctx->study.output_dir, plan->tasks, ctx->study.output_dir);
    for (int t = 0; t < plan->tasks; ++t) {
        printf("  task %d (about %.0f s):", t, plan->cost[t]);
        for (int i = 0; i < stage_count; ++i)
            if (plan->task[i] == t)
                printf(" %s", stages[i]->key);
        printf("\n");
    }
}

/* --plan: DIR/plan's files; no stage runs. */
static int write_plan(const report_context *ctx, const int selected[STAGE_MAX], const all_mode *m)
{
    double seconds[STAGE_MAX];
    all_plan plan;
    gt_error e;
    known_seconds(ctx, m->project, seconds);
    all_plan_make(stages, stage_count, selected, seconds, (int)m->jobs, &plan);
    const all_plan_run run = {study_quality_name(ctx->study.quality), m->project, m->stage_list,
                              ctx->study.output_dir};
    if (all_plan_write(stages, stage_count, &plan, &run, &e) != 0)
        return cli_fail(&e);
    print_plan(ctx, &plan);
    return EXIT_OK;
}

/* Under mpirun: every rank makes the plan of `ranks` tasks from the same
 * files (a barrier before any part is written), runs its task's stages
 * rendering alone, and rank 0 assembles the report once all succeeded. */
static int run_ranks(report_context *ctx, const int selected[STAGE_MAX], const all_mode *m, render_share job)
{
    double seconds[STAGE_MAX];
    all_plan plan;
    int mine[STAGE_MAX] = {0}, status = EXIT_OK;
    known_seconds(ctx, m->project, seconds);
    all_plan_make(stages, stage_count, selected, seconds, job.ranks, &plan);
    distributed_all(1);
    distributed_render_alone();
    for (int i = 0; i < stage_count; ++i)
        mine[i] = selected[i] && plan.task[i] == job.rank;
    int ok = run_marked(ctx, mine, m->project, &status) == 0;
    if (!distributed_all(ok))
        return ok ? (job.rank == 0 ? cli_failf("mpirun", "a rank's stage failed (its error above): no report")
                                   : EXIT_USER_ERROR)
                  : status;
    if (job.rank != 0)
        return EXIT_OK;
    gt_error e;
    for (int i = 0; i < stage_count; ++i) {
        int found = selected[i] && !mine[i] ? report_part_read(ctx->study.output_dir, stages[i]->key, &parts[i], &e)
                                            : 1;
        if (found != 1)
            return found < 0 ? cli_fail(&e) : cli_failf(stages[i]->key, "no part in parts/ after its rank ran it");
    }
    return assemble_and_print(ctx, selected, m);
}

static void free_parts(void)
{
    for (int i = 0; i < STAGE_MAX; ++i)
        cJSON_Delete(parts[i]), parts[i] = NULL;
}

/* The checks before any work: earlier parts, inputs, outputs, the folder. */
static int prepare(report_context *ctx, int selected[STAGE_MAX], const all_mode *m)
{
    int none[STAGE_MAX] = {0};
    /* A plan's task reads no other stage's part (they are its sibling tasks'). */
    const int reads_none = m->plan || m->parts_only;
    if ((!reads_none && read_earlier_parts(ctx, m->assemble ? none : selected, m->project) != 0) ||
        (m->assemble && check_parts_present(ctx, selected, m->stage_list) != 0) ||
        check_inputs(ctx, selected) != 0 || check_outputs(ctx, selected) != 0)
        return EXIT_USER_ERROR;
    int status = cli_make_output_dir(ctx->study.output_dir);
    if (status != 0)
        return status;
    char probe[4096];
    snprintf(probe, sizeof probe, "%s/report.md", ctx->study.output_dir);
    gt_error e;
    return atomic_file_check_writable(probe, &e) != 0 ? cli_fail(&e) : EXIT_OK;
}

static int run_all(report_context *ctx, int selected[STAGE_MAX], const all_mode *m)
{
    gt_error e;
    if (distributed_begin(&e) != 0)
        return cli_fail(&e);
    render_share job = distributed_job();
    int status;
    if (check_mode(m, job) != 0)
        return EXIT_USER_ERROR;
    if ((status = prepare(ctx, selected, m)) != EXIT_OK)
        return status;
    if (m->plan)
        return write_plan(ctx, selected, m);
    if (job.ranks > 1)
        return run_ranks(ctx, selected, m, job);
    if (run_marked(ctx, selected, m->project, &status) != 0 || m->parts_only)
        return m->parts_only && status == 0 ? EXIT_OK : status;
    return assemble_and_print(ctx, selected, m);
}

int verb_all(int argc, char **argv)
{
    stage_count = (int)technique_stages(stages, STAGE_MAX);
    static claims_table claims;
    report_context ctx = {{NULL, (study_quality)-1, threads_default(), NULL, NULL, 0}, NULL, NULL, &claims};
    int selected[STAGE_MAX];
    for (int i = 0; i < STAGE_MAX; ++i)
        selected[i] = 1;
    all_mode m = {0};
    int status;
    if (parse_options(argc, argv, &ctx, selected, &m, &status) != 0)
        return status;
    status = run_all(&ctx, selected, &m);
    free_parts();
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
