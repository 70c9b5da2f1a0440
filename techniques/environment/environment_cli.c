/* Environment lighting (issue 28): `gtlab bench env-diffuse`, the
 * environment-lit diffuse reference's samples/s against the white-dome
 * multibounce reference on the same scene (techniques/environment/environment_throughput.h). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"
#include "environment/environment_throughput.h"
#include "environment/environment_section.h"
#include "environment/environment_study.h"

static const cli_option bench_options[] = {
    CLI_STRING("scene", "S", "builtin:NAME or a glTF file (default builtin:cornell)"),
    CLI_STRING("environment", "E", "white, sky, sun or an image file (default: Blender's sunset.exr)"),
    CLI_INT("width", "W", 16, 8192, "image width"), CLI_INT("height", "H", 16, 8192, "image height"),
    CLI_INT("spp", "N", 1, 1 << 20, "samples (paths) per pixel"),
    CLI_INT("bounces", "N", 0, 1024, "inter-reflections (default 4)"),
    CLI_INT("threads", "T", 1, 1024, "threads (default: all cores)"),
    CLI_INT("repeats", "R", 1, 100, "passes per figure"), CLI_END};
static const cli_command bench_command = {
    "bench env-diffuse",
    "Measures, in one run, on the same scene, camera, G-buffer and machine, samples/s of\n"
    "  multibounce   the white-dome reference (grey albedo 0.5, --bounces)\n"
    "  env-diffuse   the environment-lit reference, same albedo and bounces (MIS of\n"
    "                cosine and environment sampling, one ray per vertex)\n"
    "and their ratio env-diffuse / multibounce (issue 28's goal: >= 0.7). Each figure\n"
    "is the best of R passes, the two loops alternating.",
    bench_options, NULL, NULL};

#define BLENDER_SUNSET "/usr/share/blender/datafiles/studiolights/world/sunset.exr"

static int bench_env_diffuse(int argc, char **argv)
{
    const char *spec = "builtin:cornell", *environment = BLENDER_SUNSET;
    long width = 128, height = 128, spp = 64, bounces = 4, threads = threads_default(), repeats = 3;
    int status;
    if (cli_options_parse(&bench_command,
                          (void *[]){&spec, &environment, &width, &height, &spp, &bounces, &threads, &repeats}, argc,
                          argv, &status) != 0)
        return status;
    environment_bench_request rq = {spec, environment, (int)width, (int)height,
                                    (int)spp, (int)bounces, (int)threads, (int)repeats};
    gt_error e;
    return environment_throughput_bench(stdout, &rq, &e) == 0 ? EXIT_OK : cli_fail(&e);
}

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_environment, environment_study_result, environment_study, environment_section)

const technique technique_environment = {
    .name = "environment",
    .subcommands = {[VERB_BENCH] = CLI_SUBCOMMANDS(
        {"env-diffuse", bench_env_diffuse, "environment-lit diffuse samples/s against the white-dome multibounce"})},
    .stages = ALL_STAGES({"environment", "ambient terms under real environments", all_stage_environment, NULL, NULL}),
};
