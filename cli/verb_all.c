/* gtlab all: the main job — every reference, fit, LUT and validation, and the
 * accuracy report (report.md, report.html, summary.json). */
#define _GNU_SOURCE
#include <errno.h>
#include <getopt.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/all_stages.h"
#include "cli/cli.h"
#include "core/atomic_file.h"
#include "core/progress.h"

typedef struct {
    const char *key, *name;
    int (*run)(all_context *ctx, gt_error *e);
} all_stage;

enum { STAGE_COUNT = 6 };
static const all_stage stages[STAGE_COUNT] = {
    {"ao", "AO references", all_stage_ao_references},
    {"gtao", "GTAO validation", all_stage_gtao},
    {"multibounce", "multi-bounce refit", all_stage_multibounce},
    {"specular-occlusion", "specular occlusion", all_stage_specular_occlusion},
    {"sphere-light", "GGX sphere lights", all_stage_sphere_light},
    {"throughput", "ray throughput", all_stage_ray_throughput},
};

static void print_help(void)
{
    printf("usage: gtlab all [--quality preview|production] [-o DIR] [--threads T] [--stages LIST]\n"
           "\n"
           "Runs every stage on the built-in scenes and writes the accuracy report:\n"
           "  DIR/report.md, DIR/report.html   the report (figures under DIR/figures)\n"
           "  DIR/summary.json                 every figure of the report, machine-readable\n"
           "  DIR/ao/*.exr                     the references (with their .camera.json)\n"
           "Stages:\n");
    for (int i = 0; i < STAGE_COUNT; ++i)
        printf("  %-20s %s\n", stages[i].key, stages[i].name);
    printf("\n"
           "  --quality Q   preview (default: a few minutes on 2 cores) or production\n"
           "  -o, --output DIR   output folder (default results)\n"
           "  --threads T   worker threads (default: all cores; results do not depend on it)\n"
           "  --stages LIST comma-separated stage names from the list above (default: all);\n"
           "                the report then holds those sections only. gtao reads DIR/ao/,\n"
           "                which the ao stage writes (in this run or an earlier one)\n");
}

/* Marks the stages named in the comma-separated list; -1 after an error (printed). */
static int select_stages(const char *list, int selected[STAGE_COUNT])
{
    char copy[512];
    snprintf(copy, sizeof copy, "%s", list);
    memset(selected, 0, sizeof(int) * STAGE_COUNT);
    for (char *tok = strtok(copy, ","); tok; tok = strtok(NULL, ",")) {
        int found = 0;
        for (int i = 0; i < STAGE_COUNT; ++i)
            if (strcmp(tok, stages[i].key) == 0)
                selected[i] = found = 1;
        if (!found)
            return cli_failf("--stages", "unknown stage '%s' (see 'gtlab all --help')", tok), -1;
    }
    for (int i = 0; i < STAGE_COUNT; ++i)
        if (selected[i])
            return 0;
    return cli_failf("--stages", "no stage named in '%s'", list), -1;
}

static int write_summary(const all_context *ctx, gt_error *e)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/summary.json", ctx->study.output_dir);
    char *text = cJSON_Print(ctx->summary);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

int verb_all(int argc, char **argv)
{
    static const struct option longs[] = {{"quality", required_argument, 0, 'q'},
                                          {"output", required_argument, 0, 'o'},
                                          {"threads", required_argument, 0, 't'},
                                          {"stages", required_argument, 0, 's'},
                                          {"help", no_argument, 0, 'h'},
                                          {0, 0, 0, 0}};
    all_context ctx = {{"results", QUALITY_PREVIEW, omp_get_num_procs()}, NULL, NULL};
    long threads;
    int c, selected[STAGE_COUNT] = {1, 1, 1, 1, 1, 1};
    const char *stage_list = NULL;
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        switch (c) {
        case 'q':
            if (strcmp(optarg, "preview") == 0)
                ctx.study.quality = QUALITY_PREVIEW;
            else if (strcmp(optarg, "production") == 0)
                ctx.study.quality = QUALITY_PRODUCTION;
            else
                return cli_failf("--quality", "'%s' is neither preview nor production", optarg);
            break;
        case 'o': ctx.study.output_dir = optarg; break;
        case 't':
            if (cli_parse_int("--threads", optarg, 1, 1024, &threads))
                return EXIT_USER_ERROR;
            ctx.study.threads = (int)threads;
            break;
        case 's':
            if (select_stages(optarg, selected) != 0)
                return EXIT_USER_ERROR;
            stage_list = optarg;
            break;
        case 'h': print_help(); return EXIT_OK;
        default: return cli_usage_error("all");
        }
    }
    if (optind < argc)
        return cli_failf("all", "unexpected argument '%s'", argv[optind]);
    gt_error e;
    if (mkdir(ctx.study.output_dir, 0755) != 0 && errno != EEXIST)
        return cli_failf(ctx.study.output_dir, "cannot create folder: %s", strerror(errno));
    char probe[4096];
    snprintf(probe, sizeof probe, "%s/report.md", ctx.study.output_dir);
    if (atomic_file_check_writable(probe, &e) != 0)
        return cli_fail(&e);

    report doc;
    report_init(&doc, "gtlab accuracy report");
    ctx.doc = &doc;
    ctx.summary = cJSON_CreateObject();
    const char *quality = ctx.study.quality == QUALITY_PREVIEW ? "preview" : "production";
    cJSON_AddStringToObject(ctx.summary, "gtlab_version", GTLAB_VERSION);
    cJSON_AddStringToObject(ctx.summary, "quality", quality);
    char stage_option[512] = "";
    if (stage_list)
        snprintf(stage_option, sizeof stage_option, " --stages %s", stage_list);
    report_paragraph(&doc,
                     "Made by gtlab %s with 'gtlab all --quality %s%s'. Every figure below comes from that run; "
                     "rerunning the command reproduces the images bit for bit (timings vary with the machine). "
                     "Machine-readable figures: summary.json.",
                     GTLAB_VERSION, quality, stage_option);
    report_findings_here(&doc);
    int status = EXIT_OK;
    for (int i = 0; i < STAGE_COUNT && status == EXIT_OK; ++i) {
        if (!selected[i])
            continue;
        fprintf(stderr, "gtlab all: %s\n", stages[i].name);
        double t0 = seconds_now();
        if (stages[i].run(&ctx, &e) != 0)
            status = cli_fail(&e);
        else
            fprintf(stderr, "gtlab all: %s done in %.1f s\n", stages[i].name, seconds_now() - t0);
    }
    if (status == EXIT_OK && (report_write(&doc, ctx.study.output_dir, &e) != 0 || write_summary(&ctx, &e) != 0))
        status = cli_fail(&e);
    if (status == EXIT_OK)
        printf("report: %s/report.html and %s/report.md\n", ctx.study.output_dir, ctx.study.output_dir);
    report_free(&doc);
    cJSON_Delete(ctx.summary);
    return status;
}
