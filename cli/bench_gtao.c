/* gtlab bench gtao: GTAO at 1920x1080 in the talk's configuration (seeds/001,
 * "Achieving the Performance Target": half resolution, 1 direction per pixel,
 * 8 samples per direction, spatial and temporal denoisers), and the cost per
 * pixel of every preset next to the brute-force reference's and the
 * height-field Monte Carlo reference's, measured in one run
 * (studies/gtao_bench.h); here the options and the printing. */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "studies/gtao_bench.h"
#include "core/threads.h"

static const cli_option options[] = {
    CLI_STRING("scene", "S", "builtin:NAME or a glTF file"), CLI_THREADS,
    CLI_INT("repeats", "R", 1, 100, "passes per figure"), CLI_END};
static const cli_command command = {
    "bench gtao",
    "Measures, on one scene and camera:\n"
    "  talk's configuration  GTAO for a 1920x1080 frame at half resolution (960x540):\n"
    "                        1 direction per pixel, 8 samples per direction (4 per side),\n"
    "                        the 4x4 spatio-temporal pattern, fast acos/sqrt, the 4x4\n"
    "                        bilateral denoiser and the temporal accumulation, per frame\n"
    "                        (averaged over the 24-frame cycle), on 1 and T threads\n"
    "  presets               ns per pixel of one frame of each preset (low .. ultra and the\n"
    "                        brute-force reference) and of the height-field Monte Carlo\n"
    "                        reference at 64 spp, on a 240x136 image of the same view\n"
    "Each figure is the best of R passes.",
    options, NULL, NULL};

static void print_report(const char *spec, int threads, const gtao_bench_result *r)
{
    printf("scene %s; GTAO at %dx%d (1920x1080 at half resolution): %s\n\n", spec, GTAO_BENCH_HALF_WIDTH,
           GTAO_BENCH_HALF_HEIGHT, r->settings);
    printf("%-44s %12s %12s\n", "per frame (GTAO + denoisers)", "1 thread", "threads");
    printf("%-44s %9.2f ms %9.2f ms   (%d threads)\n\n", "talk's configuration", 1e3 * r->talk_seconds_1_thread,
           1e3 * r->talk_seconds_threads, threads);
    printf("cost per pixel, one frame on %dx%d, %d threads:\n", r->small_width, r->small_height, threads);
    double reference_ns = r->preset_ns[GTAO_PRESET_REFERENCE];
    for (int i = 0; i < GTAO_PRESET_COUNT; ++i)
        printf("  GTAO %-12s %12.1f ns/pixel   %8.4f of the brute-force reference\n", gtao_preset_names[i],
               r->preset_ns[i], r->preset_ns[i] / reference_ns);
    printf("  height-field MC, %d spp %8.1f ns/pixel   %8.4f of the brute-force reference\n",
           GTAO_BENCH_HEIGHTFIELD_SPP, r->heightfield_ns, r->heightfield_ns / reference_ns);
}

int bench_gtao(int argc, char **argv)
{
    const char *spec = "builtin:menger";
    long threads = threads_default(), repeats = 3;
    int status;
    if (cli_options_parse(&command, (void *[]){&spec, &threads, &repeats}, argc, argv, &status) != 0)
        return status;
    gt_error e;
    gtao_bench_result r;
    if (gtao_bench_run(spec, (int)threads, (int)repeats, &r, &e) != 0)
        return cli_fail(&e);
    print_report(spec, (int)threads, &r);
    return EXIT_OK;
}
