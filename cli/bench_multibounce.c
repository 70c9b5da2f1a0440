/* gtlab bench multibounce: the multi-bounce reference's paths/s and rays/s
 * against raw Embree closest-hit queries, and N albedos in one pass against
 * N single-albedo renders (issue 3, "Performance"; studies/multibounce_bench.h);
 * here the options and the printing. */
#define _GNU_SOURCE
#include <getopt.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "studies/multibounce_bench.h"
#include "core/threads.h"

static void print_help(void)
{
    printf("usage: gtlab bench multibounce [--scene S] [--width W] [--height H] [--spp N]\n"
           "                               [--albedo LIST] [--bounces N|inf] [--threads T] [--repeats R]\n"
           "\n"
           "Measures, in one run, on the same scene, camera and machine:\n"
           "  gtlab multibounce  paths/s and rays/s of the multi-bounce reference loop (all\n"
           "                     albedos in one pass), per core (1 thread) and with T threads\n"
           "  raw Embree         closest-hit rays/s of rtcIntersect1 and rtcIntersect1M\n"
           "                     (streams of 64) on the first rays of the same paths\n"
           "                     (cosine-distributed, incoherent), traversal only\n"
           "  one pass vs N      seconds of one render of N albedos against N renders of one\n"
           "                     albedo each (T threads), and their ratio\n"
           "Each figure is the best of R passes (default 2).\n"
           "\n"
           "  --scene S      builtin:NAME or a glTF file (default builtin:cornell)\n"
           "  --width W --height H   image size (default 128x128)\n"
           "  --spp N        samples (paths) per pixel (default 64)\n"
           "  --albedo LIST  grey albedos (default 0.1,0.2,0.3,0.4,0.5,0.7,0.9)\n"
           "  --bounces N    inter-reflections, or inf (default 4)\n"
           "  --threads T    threads for the parallel figures (default: all cores)\n"
           "  --repeats R    passes per figure (default 2)\n");
}

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
    static const struct option longs[] = {
        {"scene", required_argument, 0, 's'},   {"width", required_argument, 0, 'W'},
        {"height", required_argument, 0, 'H'},  {"spp", required_argument, 0, 'n'},
        {"albedo", required_argument, 0, 'a'},  {"bounces", required_argument, 0, 'b'},
        {"threads", required_argument, 0, 't'}, {"repeats", required_argument, 0, 'r'},
        {"help", no_argument, 0, 'h'},          {0, 0, 0, 0}};
    const char *spec = "builtin:cornell";
    long width = 128, height = 128, spp = 64, threads = threads_default(), repeats = 2;
    multibounce_settings settings = {0};
    settings.bounces = 4;
    gt_error e;
    if (multibounce_parse_albedos("0.1,0.2,0.3,0.4,0.5,0.7,0.9", &settings, &e) != 0)
        return cli_fail(&e);
    int c;
    while ((c = getopt_long(argc, argv, "h", longs, NULL)) != -1) {
        switch (c) {
        case 's': spec = optarg; break;
        case 'W': if (cli_parse_int("--width", optarg, 16, 8192, &width)) return EXIT_USER_ERROR; break;
        case 'H': if (cli_parse_int("--height", optarg, 16, 8192, &height)) return EXIT_USER_ERROR; break;
        case 'n': if (cli_parse_int("--spp", optarg, 1, 1 << 20, &spp)) return EXIT_USER_ERROR; break;
        case 't': if (cli_parse_int("--threads", optarg, 1, 1024, &threads)) return EXIT_USER_ERROR; break;
        case 'r': if (cli_parse_int("--repeats", optarg, 1, 100, &repeats)) return EXIT_USER_ERROR; break;
        case 'a':
            if (multibounce_parse_albedos(optarg, &settings, &e) != 0)
                return cli_fail(&e);
            if (settings.scene_albedo)
                return cli_failf("--albedo", "the benchmark compares grey albedos; 'scene' is not one");
            break;
        case 'b': if (multibounce_parse_bounces(optarg, &settings, &e) != 0) return cli_fail(&e); break;
        case 'h': print_help(); return EXIT_OK;
        default: return cli_usage_error("bench multibounce");
        }
    }
    if (optind < argc)
        return cli_failf("bench multibounce", "unexpected argument '%s'", argv[optind]);
    multibounce_benchmark b;
    if (multibounce_bench_run(spec, (int)width, (int)height, &settings, (int)spp, (int)threads, (int)repeats, &b,
                              &e) != 0)
        return cli_fail(&e);
    print_report(spec, &settings, &b);
    return EXIT_OK;
}
