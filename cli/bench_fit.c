/* gtlab bench fit: the time of a multi-bounce joint fit (a, b, c linear in
 * the albedo) over a million samples through the Ceres bridge, with one
 * residual block per sample against blocks of 1024 (fitters/ceres_bridge.h),
 * measured by studies/multibounce_fit_timing.h. */
#define _GNU_SOURCE
#include <getopt.h>
#include <stdio.h>

#include "cli/cli.h"
#include "studies/multibounce_fit_timing.h"

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
