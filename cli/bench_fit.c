/* gtlab bench fit: the time of a multi-bounce joint fit (a, b, c linear in
 * the albedo) over a million samples through the Ceres bridge, with one
 * residual block per sample against blocks of 1024 (fitters/ceres_bridge.h). */
#define _GNU_SOURCE
#include <getopt.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "core/progress.h"
#include "fitters/fit_multibounce.h"

static void print_help(void)
{
    printf("usage: gtlab bench fit [--samples N] [--repeats R]\n"
           "\n"
           "Times the joint multi-bounce fit (6 coefficients, gtlab fit multibounce's model)\n"
           "of N synthetic samples (default 1000000: 7 albedos, V_d spread over (0, 1], V'_d\n"
           "a cubic plus noise) through the Ceres bridge, solve and covariance, with one\n"
           "residual block per sample and with blocks of 1024 samples; single-threaded.\n"
           "Each figure is the best of R runs (default 1).\n"
           "\n"
           "  --samples N   samples (default 1000000)\n"
           "  --repeats R   runs per figure (default 1)\n");
}

/* A uniform number in [-0.5, 0.5) from a hash of i: the synthetic noise. */
static double hashed_noise(uint64_t i)
{
    i = (i ^ (i >> 30)) * 0xBF58476D1CE4E5B9ull;
    i = (i ^ (i >> 27)) * 0x94D049BB133111EBull;
    i ^= i >> 31;
    return (double)(i >> 11) * 0x1p-53 - 0.5;
}

static int synthesise(multibounce_data *d, long n, gt_error *e)
{
    static const float albedos[7] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.7f, 0.9f};
    const multibounce_model truth = multibounce_model_jimenez2016(); /* any smooth curve serves a timing */
    int scene = multibounce_data_scene(d, "synthetic", e);
    for (long i = 0; i < n; ++i) {
        int a = multibounce_data_albedo(d, albedos[i % 7], e);
        double v = ((double)(i / 7) + 0.5) / (double)((n + 6) / 7);
        double y = gtao_multibounce(&truth, v, albedos[i % 7]) + 0.02 * hashed_noise((uint64_t)i);
        if (scene < 0 || a < 0 || multibounce_data_push(d, scene, a, (float)v, (float)y, e) != 0)
            return -1;
    }
    multibounce_data_weigh(d);
    return 0;
}

int bench_fit(int argc, char **argv)
{
    static const struct option longs[] = {{"samples", required_argument, 0, 'n'},
                                          {"repeats", required_argument, 0, 'r'},
                                          {"help", no_argument, 0, 'h'},
                                          {0, 0, 0, 0}};
    long samples = 1000000, repeats = 1;
    int c;
    while ((c = getopt_long(argc, argv, "h", longs, NULL)) != -1) {
        switch (c) {
        case 'n': if (cli_parse_int("--samples", optarg, 100, 100000000, &samples)) return EXIT_USER_ERROR; break;
        case 'r': if (cli_parse_int("--repeats", optarg, 1, 100, &repeats)) return EXIT_USER_ERROR; break;
        case 'h': print_help(); return EXIT_OK;
        default: return cli_usage_error("bench fit");
        }
    }
    if (optind < argc)
        return cli_failf("bench fit", "unexpected argument '%s'", argv[optind]);
    gt_error e;
    multibounce_data d;
    multibounce_data_init(&d);
    if (synthesise(&d, samples, &e) != 0) {
        multibounce_data_free(&d);
        return cli_fail(&e);
    }
    printf("joint multi-bounce fit, %ld samples, 6 coefficients, 1 thread (solve + covariance)\n\n", samples);
    printf("%-28s %12s %12s %12s\n", "", "total s", "solve s", "iterations");
    static const int block_sizes[2] = {1, MBFIT_DEFAULT_BLOCK};
    double best[2] = {INFINITY, INFINITY};
    for (int b = 0; b < 2; ++b) {
        multibounce_fit f;
        for (long r = 0; r < repeats; ++r) {
            const multibounce_fit_options o = {block_sizes[b], 0};
            double t0 = seconds_now();
            if (multibounce_fit_model(&d, 1, &o, &f, &e) != 0) {
                multibounce_data_free(&d);
                return cli_fail(&e);
            }
            best[b] = fmin(best[b], seconds_now() - t0);
        }
        char label[64];
        snprintf(label, sizeof label, "blocks of %d sample%s", block_sizes[b], block_sizes[b] > 1 ? "s" : "");
        printf("%-28s %12.3f %12.3f %12d\n", label, best[b], f.solver.seconds, f.solver.iterations);
    }
    printf("\nratio (1-sample blocks / %d-sample blocks): %.1f\n", MBFIT_DEFAULT_BLOCK, best[0] / best[1]);
    multibounce_data_free(&d);
    return EXIT_OK;
}
