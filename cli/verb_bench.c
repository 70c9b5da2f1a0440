/* gtlab bench: throughput figures and their ratios, measured in one run
 * (throughput/ray_throughput_study.h); here the options, the dispatch to the
 * techniques' benchmarks and the printing. */
#define _GNU_SOURCE
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "throughput/ray_throughput_study.h"
#include "core/threads.h"

static const cli_option options[] = {CLI_BENCH_VIEW, CLI_END};
static const cli_command command = {
    "bench",
    "'gtlab bench rays' measures, in one run, on the same scene, camera and machine:\n"
    "  raw Embree   occlusion rays/s through rtcOccluded1, rtcOccluded1M (streams of 64\n"
    "               and 128) and rtcOccluded8/16 packets, on a prepared array of the very\n"
    "               rays the AO reference traces at 64 spp, in its order (incoherent: per\n"
    "               sample one cosine- and one uniform-distributed direction leaving the\n"
    "               visible surfaces); the best of the call forms is the reference figure\n"
    "  gtlab AO     rays/s of the AO reference loop at 64 spp (sampling, Embree,\n"
    "               exact accumulation)\n"
    "and prints their ratio, and the speed-up of T threads over 1. Each figure is the\n"
    "best of R passes.\n"
    "'gtlab bench specular-occlusion': samples/s of the specular-occlusion reference\n"
    "(64 spp, roughness 0.5), 1 thread and T threads.",
    options, "rays|specular-occlusion|gtao|multibounce|fit|sphere-light|convergence|env-diffuse|shader",
    "Other benchmarks, each with --help: gtlab bench gtao (GTAO in the talk's configuration\n"
    "at 1920x1080 and every preset's cost per pixel), multibounce, fit, sphere-light,\n"
    "convergence (AO time to RMSE 0.01, plain against the height-field control variate),\n"
    "env-diffuse (the environment-lit diffuse reference against the white-dome one)."};

static void print_rays(const ray_throughput_result *r)
{
    const ray_throughput_row *gtlab = &r->rows[RAY_THROUGHPUT_GTLAB_ROW], *ratio = &r->rows[RAY_THROUGHPUT_RATIO_ROW];
    printf("scene %s, %ld rays per pass, 1 and %d threads\n\n", r->scene, r->rays_per_pass, r->threads);
    printf("%-34s %14s %14s\n", "occlusion rays/s", "1 thread", "threads");
    for (int call = 0; call < RAW_CALL_COUNT; ++call)
        printf("%-34s %14.4g %14.4g\n", r->rows[call].name, r->rows[call].one_thread, r->rows[call].threads);
    printf("%-34s %14.4g %14.4g\n", "Embree best (raw)", r->raw_best_1_thread, r->raw_best_threads);
    printf("%-34s %14.4g %14.4g\n", "gtlab AO reference, end to end", gtlab->one_thread, gtlab->threads);
    printf("\n%-34s %14.3f %14.3f\n", "ratio gtlab / raw Embree", ratio->one_thread, ratio->threads);
    printf("%-34s %14s %14.3f\n", "speed-up threads / 1 thread (gtlab)", "", r->speedup_gtlab);
    printf("%-34s %14s %14.3f\n", "speed-up threads / 1 thread (raw)", "", r->speedup_raw);
}

/* `gtlab bench rays`, measured and printed. */
static int run_rays(const char *spec, int width, int height, int threads, int repeats)
{
    gt_error e;
    ray_throughput_result r;
    if (ray_throughput_measure(spec, width, height, threads, repeats, &r, &e) != 0)
        return cli_fail(&e);
    print_rays(&r);
    return EXIT_OK;
}

/* The index in registered[] of the technique's benchmark `name`, or -1. */
static int registered_index(const cli_subcommand *registered, size_t count, const char *name)
{
    for (size_t i = 0; i < count; ++i)
        if (strcmp(name, registered[i].name) == 0)
            return (int)i;
    return -1;
}

int verb_bench(int argc, char **argv)
{
    /* The techniques' own benchmarks, each with its options (cli/techniques.c). */
    cli_subcommand registered[32];
    size_t count = technique_subcommands(VERB_BENCH, registered, 32);
    int at = argc >= 2 ? registered_index(registered, count, argv[1]) : -1;
    if (at >= 0) {
        cli_reset_getopt();
        return registered[at].run(argc - 1, argv + 1);
    }
    const char *scene_spec = "builtin:menger";
    long width = 256, height = 256, threads = threads_default(), repeats = 3;
    cli_arguments name;
    int status;
    if (cli_options_parse(&command, (void *[]){&scene_spec, &width, &height, &threads, &repeats, &name}, argc, argv,
                          &status) != 0)
        return status;
    if (name.count > 1)
        return cli_failf("bench", "unexpected argument '%s'", name.values[1]);
    /* A technique's benchmark named after options of this table (`gtlab bench
     * --scene S specular-occlusion`; the parse moved the name last): run as if
     * named first. */
    if (name.count == 1 && (at = registered_index(registered, count, name.values[0])) >= 0) {
        char *named = argv[argc - 1];
        memmove(argv + 2, argv + 1, (size_t)(argc - 2) * sizeof *argv);
        argv[1] = named;
        cli_reset_getopt();
        return registered[at].run(argc - 1, argv + 1);
    }
    const char *now = name.count == 1 ? technique_renamed(name.values[0]) : NULL;
    if (now && registered_index(registered, count, now) >= 0)
        return cli_failf("bench", "'%s' is now '%s' (gtlab bench %s)", name.values[0], now, now);
    if (name.count == 0 || strcmp(name.values[0], "rays") != 0)
        return cli_failf("bench", "name a benchmark: rays, specular-occlusion, gtao, multibounce, fit, sphere-light, "
                                  "convergence or env-diffuse (see 'gtlab bench --help')");
    return run_rays(scene_spec, (int)width, (int)height, (int)threads, (int)repeats);
}
