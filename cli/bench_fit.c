/* gtlab bench fit: the time of a multi-bounce joint fit (a, b, c linear in
 * the albedo) over a million samples through the Ceres bridge, with one
 * residual block per sample against blocks of 1024 (fitters/ceres_bridge.h),
 * measured by studies/multibounce_fit_timing.h. */
#define _GNU_SOURCE
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "studies/multibounce_fit_timing.h"

static const cli_option options[] = {
    CLI_INT("samples", "N", 100, 100000000, "samples"), CLI_INT("repeats", "R", 1, 100, "runs per figure"), CLI_END};
static const cli_command command = {
    "bench fit",
    "Times the joint multi-bounce fit (6 coefficients, gtlab fit multibounce's model)\n"
    "of N synthetic samples (7 albedos, V_d spread over (0, 1], V'_d a cubic plus\n"
    "noise) through the Ceres bridge, solve and covariance, with one residual block\n"
    "per sample and with blocks of 1024 samples; single-threaded. Each figure is the\n"
    "best of R runs.",
    options, NULL, NULL};

int bench_fit(int argc, char **argv)
{
    long samples = 1000000, repeats = 1;
    int status;
    if (cli_options_parse(&command, (void *[]){&samples, &repeats}, argc, argv, &status) != 0)
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
