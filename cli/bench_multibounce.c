/* gtlab bench multibounce: the multi-bounce reference's paths/s and rays/s
 * against raw Embree closest-hit queries, and N albedos in one pass against
 * N single-albedo renders (issue 3, "Performance"; studies/multibounce_bench.h);
 * here the options and the printing. */
#define _GNU_SOURCE
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "studies/multibounce_bench.h"
#include "core/threads.h"

/* --albedo LIST of grey albedos, --bounces N|inf, into the multibounce_settings. */
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

static const cli_option options[] = {
    CLI_STRING("scene", "S", "builtin:NAME or a glTF file"), CLI_INT("width", "W", 16, 8192, "image width"),
    CLI_INT("height", "H", 16, 8192, "image height"), CLI_INT("spp", "N", 1, 1 << 20, "samples (paths) per pixel"),
    CLI_CUSTOM("albedo", "LIST", parse_albedos, "grey albedos (default 0.1,0.2,0.3,0.4,0.5,0.7,0.9)"),
    CLI_CUSTOM("bounces", "N|inf", parse_bounces, "inter-reflections, or inf (default 4)"),
    CLI_INT("threads", "T", 1, 1024, "threads for the parallel figures (default: all cores)"),
    CLI_INT("repeats", "R", 1, 100, "passes per figure"), CLI_END};
static const cli_command command = {
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
    options, NULL, NULL};

static void print_report(const char *spec, const multibounce_settings *s, const multibounce_benchmark *b)
{
    printf("scene %s, %d albedos, %d spp, 1 and %d threads\n\n", spec, s->albedo_count, b->spp, b->threads);
    printf("%-44s %14s %14s\n", "", "1 thread", "threads");
    printf("%-44s %14.4g %14.4g\n", "gtlab multibounce paths/s", b->paths_per_s[0], b->paths_per_s[1]);
    printf("%-44s %14.4g %14.4g\n", "gtlab multibounce rays/s", b->rays_per_s[0], b->rays_per_s[1]);
    printf("%-44s %14.4g %14.4g\n", "raw Embree rtcIntersect1 rays/s", b->raw_intersect1[0], b->raw_intersect1[1]);
    printf("%-44s %14.4g %14.4g\n", "raw Embree rtcIntersect1M (64) rays/s", b->raw_intersect1m[0],
           b->raw_intersect1m[1]);
    printf("%-44s %14.3f %14.3f\n", "ratio gtlab / raw rtcIntersect1", b->rays_per_s[0] / b->raw_intersect1[0],
           b->rays_per_s[1] / b->raw_intersect1[1]);
    printf("\n%d albedos in one pass: %.3f s; one render per albedo: %.3f s in all; ratio %.2f\n", s->albedo_count,
           b->seconds_one_pass, b->seconds_separate, b->seconds_separate / b->seconds_one_pass);
}

int bench_multibounce(int argc, char **argv)
{
    const char *spec = "builtin:cornell";
    long width = 128, height = 128, spp = 64, threads = threads_default(), repeats = 2;
    multibounce_settings settings = {0};
    settings.bounces = 4;
    gt_error e;
    int status;
    if (multibounce_parse_albedos("0.1,0.2,0.3,0.4,0.5,0.7,0.9", &settings, &e) != 0)
        return cli_fail(&e);
    if (cli_options_parse(&command, (void *[]){&spec, &width, &height, &spp, &settings, &settings, &threads, &repeats},
                          argc, argv, &status) != 0)
        return status;
    multibounce_benchmark b;
    if (multibounce_bench_run(spec, (int)width, (int)height, &settings, (int)spp, (int)threads, (int)repeats, &b,
                              &e) != 0)
        return cli_fail(&e);
    print_report(spec, &settings, &b);
    return EXIT_OK;
}
