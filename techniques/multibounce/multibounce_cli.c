/* GTAO's multi-bounce approximation (Jimenez et al. 2016) and its refit:
 * `gtlab fit multibounce` (the cubic refitted to multi-bounce references:
 * multibounce_fit_input.h, multibounce_fit.h, the formula multibounce.h),
 * `gtlab bench multibounce` (the reference's paths/s against raw Embree; N
 * albedos in one pass: multibounce_bench.h), `gtlab bench fit` (the joint
 * fit through the Ceres bridge, one residual block per sample against blocks
 * of 1024: multibounce_fit_timing.h) and the stage multibounce. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"
#include "multibounce/multibounce_bench.h"
#include "multibounce/multibounce_fit.h"
#include "multibounce/multibounce_fit_input.h"
#include "multibounce/multibounce_fit_timing.h"
#include "multibounce/multibounce_section.h"

enum { MAX_FILES = 256 };

static const cli_option fit_options[] = {
    CLI_CUSTOM("data", "F ...", cli_list_add, "reference EXRs (the option may repeat; further file names\n"
               "after it are data too); all rendered with the same --bounces"),
    CLI_OUTPUT("F", 0, "the JSON: coefficients, standard errors, covariance, RMSE and\n"
               "max error on the data, the talk's on the same data, LOO\n"
               "table, data used (files, scenes, albedos, counts, weights)"),
    CLI_OUTPUT_FILE("header", "F.h", "C header with the fitted functions (default: F without .json, .h)"),
    CLI_OUTPUT_FILE("hlsl", "F.hlsl", "HLSL GTAOMultiBounce with the new coefficients (default: .hlsl)"),
    CLI_OUTPUT_FILE("glsl", "F.glsl", "the same in GLSL (default: .glsl)"), CLI_END};
static const cli_command fit_command = {
    "fit multibounce",
    "Fits V'_d = max(V_d, ((a V_d + b) V_d + c) V_d) (GTAOMultiBounce, Jimenez et al. 2016)\n"
    "to references made by 'gtlab render multibounce --albedo 0.1,0.2,...' (grey albedos;\n"
    "each surface pixel, mask.A = 1, gives one sample (V_d = ao.V, V'_d, albedo) per albedo):\n"
    "  per albedo      the cubic's a, b, c\n"
    "  joint linear    a = a0 + a1 albedo, b, c likewise, fitted to all samples at once\n"
    "  joint quadratic a, b, c quadratic in the albedo (3+ albedos), preferred only if\n"
    "                  its leave-one-scene-out error is lower\n"
    "Every scene and every albedo counts equally, whatever its pixel count. With 2+\n"
    "scenes (the files' gtlab.scene) each scene is held out in turn: the model fitted\n"
    "on the others is scored on it. The talk's published coefficients are scored on\n"
    "the same data. Fits run through Ceres; standard errors from its covariance.",
    fit_options, "[B.exr ...]",
    "example: gtlab render multibounce --scene builtin:corner --albedo 0.1,0.2,0.3,0.4,0.5,0.7,0.9 -o c.exr\n"
    "         gtlab fit multibounce --data c.exr m.exr -o fit.json\n"
    "exit status: 0 success, 1 bad input, 2 internal error"};

/* The fit_command line as one string, for the outputs' provenance. */
static void command_text(int argc, char **argv, char *out, size_t size)
{
    size_t used = (size_t)snprintf(out, size, "gtlab fit");
    for (int i = 0; i < argc && used < size; ++i)
        used += (size_t)snprintf(out + used, size - used, " %s", argv[i]);
}

static int fit_multibounce(int argc, char **argv)
{
    const char *files[MAX_FILES], *output = NULL, *header = NULL, *hlsl = NULL, *glsl = NULL;
    cli_list data = {files, 0, MAX_FILES, "--data"};
    cli_arguments more;
    char command_line[4096];
    command_text(argc, argv, command_line, sizeof command_line); /* before getopt permutes argv */
    int status;
    if (cli_options_parse(&fit_command, (void *[]){&data, &output, &header, &hlsl, &glsl, &more}, argc, argv, &status) != 0)
        return status;
    if (more.count > 0 && data.count == 0)
        return cli_failf("fit multibounce", "unexpected argument '%s' (data files follow --data)", more.values[0]);
    for (int i = 0; i < more.count; ++i)
        if (cli_list_add(&data, more.values[i]) != 0)
            return EXIT_USER_ERROR;
    if (data.count == 0)
        return cli_failf("--data", "no reference files given (see 'gtlab fit multibounce --help')");
    if (!output)
        return cli_failf("-o", "an output file is required (fit.json)");
    multibounce_output_files out = {output, header, hlsl, glsl, {{0}}};
    gt_error e;
    if (multibounce_output_files_resolve(&out, &e) != 0)
        return cli_fail(&e);
    if (multibounce_fit_files(files, data.count, command_line, &out, stdout, &e) != 0)
        return cli_fail(&e);
    return EXIT_OK;
}

static int parse_albedos(void *settings, const char *text)
{
    gt_error e;
    if (multibounce_parse_albedos(text, settings, &e) != 0)
        return cli_fail(&e), -1;
    if (((multibounce_settings *)settings)->scene_albedo)
        return cli_failf("--albedo", "the benchmark compares grey albedos; 'scene' is not one"), -1;
    return 0;
}

static int parse_bounces(void *settings, const char *text)
{
    gt_error e;
    return multibounce_parse_bounces(text, settings, &e) != 0 ? (cli_fail(&e), -1) : 0;
}

static const cli_option bench_options[] = {
    CLI_STRING("scene", "S", "builtin:NAME or a glTF file"), CLI_INT("width", "W", 16, 8192, "image width"),
    CLI_INT("height", "H", 16, 8192, "image height"), CLI_INT("spp", "N", 1, 1 << 20, "samples (paths) per pixel"),
    CLI_CUSTOM("albedo", "LIST", parse_albedos, "grey albedos (default 0.1,0.2,0.3,0.4,0.5,0.7,0.9)"),
    CLI_CUSTOM("bounces", "N|inf", parse_bounces, "inter-reflections, or inf (default 4)"),
    CLI_INT("threads", "T", 1, 1024, "threads for the parallel figures (default: all cores)"),
    CLI_INT("repeats", "R", 1, 100, "passes per figure"), CLI_END};
static const cli_command bench_command = {
    "bench multibounce",
    "Measures, in one run, on the same scene, camera and machine:\n"
    "  gtlab multibounce  paths/s and rays/s of the multi-bounce reference loop (all\n"
    "                     albedos in one pass), per core (1 thread) and with T threads\n"
    "  raw Embree         closest-hit rays/s of rtcIntersect1 and rtcIntersect1M\n"
    "                     (streams of 64) on the first rays of the same paths\n"
    "                     (cosine-distributed, incoherent), traversal only\n"
    "  one pass vs N      seconds of one render of N albedos against N renders of one\n"
    "                     albedo each (T threads), and their ratio\n"
    "Each figure is the best of R passes.",
    bench_options, NULL, NULL};

static int bench_multibounce(int argc, char **argv)
{
    const char *spec = "builtin:cornell";
    long width = 128, height = 128, spp = 64, threads = threads_default(), repeats = 2;
    multibounce_settings settings = {0};
    settings.bounces = 4;
    gt_error e;
    int status;
    if (multibounce_parse_albedos("0.1,0.2,0.3,0.4,0.5,0.7,0.9", &settings, &e) != 0)
        return cli_fail(&e);
    if (cli_options_parse(&bench_command, (void *[]){&spec, &width, &height, &spp, &settings, &settings, &threads, &repeats},
                          argc, argv, &status) != 0)
        return status;
    multibounce_benchmark b;
    if (multibounce_bench_run(spec, (int)width, (int)height, &settings, (int)spp, (int)threads, (int)repeats, &b,
                              &e) != 0)
        return cli_fail(&e);
    multibounce_benchmark_print(stdout, spec, &settings, &b);
    return EXIT_OK;
}

static const cli_option bench_fit_options[] = {
    CLI_INT("samples", "N", 100, 100000000, "samples"), CLI_INT("repeats", "R", 1, 100, "runs per figure"), CLI_END};
static const cli_command bench_fit_command = {
    "bench fit",
    "Times the joint multi-bounce fit (6 coefficients, gtlab fit multibounce's model)\n"
    "of N synthetic samples (7 albedos, V_d spread over (0, 1], V'_d a cubic plus\n"
    "noise) through the Ceres bridge, solve and covariance, with one residual block\n"
    "per sample and with blocks of 1024 samples; single-threaded. Each figure is the\n"
    "best of R runs.",
    bench_fit_options, NULL, NULL};

static int bench_fit(int argc, char **argv)
{
    long samples = 1000000, repeats = 1;
    int status;
    if (cli_options_parse(&bench_fit_command, (void *[]){&samples, &repeats}, argc, argv, &status) != 0)
        return status;
    gt_error e;
    multibounce_fit_timing t[MULTIBOUNCE_FIT_TIMINGS];
    if (multibounce_fit_timing_run(samples, repeats, t, &e) != 0)
        return cli_fail(&e);
    printf("joint multi-bounce fit, %ld samples, 6 coefficients, 1 thread (solve + covariance)\n\n", samples);
    printf("%-28s %12s %12s %12s\n", "", "total s", "solve s", "iterations");
    for (int b = 0; b < MULTIBOUNCE_FIT_TIMINGS; ++b) {
        char label[64];
        snprintf(label, sizeof label, "blocks of %d sample%s", t[b].block_size, t[b].block_size > 1 ? "s" : "");
        printf("%-28s %12.3f %12.3f %12d\n", label, t[b].best_seconds, t[b].solve_seconds, t[b].iterations);
    }
    printf("\nratio (1-sample blocks / %d-sample blocks): %.1f\n", t[1].block_size,
           t[0].best_seconds / t[1].best_seconds);
    return EXIT_OK;
}

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_multibounce, multibounce_study_result, multibounce_study, multibounce_section)

const technique technique_multibounce = {
    .name = "multibounce",
    .subcommands = {
        [VERB_FIT] = CLI_SUBCOMMANDS(
            {"multibounce", fit_multibounce, "GTAO multi-bounce cubic (per albedo and joint in rho) vs multibounce renders"}),
        [VERB_BENCH] = CLI_SUBCOMMANDS(
            {"multibounce", bench_multibounce, "multi-bounce paths/s against raw Embree; N albedos in one pass"},
            {"fit", bench_fit, "a million-sample fit, 1- vs 1024-sample blocks"}),
    },
    .stages = ALL_STAGES({"multibounce", "multi-bounce refit", all_stage_multibounce, MULTIBOUNCE_STUDY_DIR, NULL}),
};
