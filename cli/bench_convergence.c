/* gtlab bench convergence: the AO reference's time to an RMSE, plain and
 * with the height-field control variate, on every built-in scene
 * (studies/ao_convergence.h; the figure: report/convergence_plot.h); here
 * the options and the printing. */
#define _GNU_SOURCE
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "core/threads.h"
#include "report/convergence_plot.h"
#include "studies/ao_convergence.h"

static void print_help(void)
{
    printf("usage: gtlab bench convergence [-o DIR] [--width W] [--height H] [--threads T]\n"
           "                               [--reference-spp N] [--max-spp N] [--target RMSE]\n"
           "\n"
           "Measures, in one run, per built-in scene: the RMSE of ao.V against a converged\n"
           "reference (a control-variate render of --reference-spp samples) as a function of\n"
           "the wall time of the whole render (Embree scene, G-buffer, the control variate's\n"
           "horizons and pilot, sampling), for plain sampling and for --control-variate\n"
           "heightfield, each a series of renders at 16, 32, ... spp; then\n"
           "the time each needs to reach the target RMSE and their ratio (plain / control\n"
           "variate). Writes DIR/convergence.dat and DIR/convergence.png (gnuplot).\n"
           "\n"
           "  -o DIR             output folder (default bench_convergence)\n"
           "  --width W --height H   image size (default 48x48)\n"
           "  --threads T        threads (default: all cores)\n"
           "  --reference-spp N  samples of the reference (default 16384)\n"
           "  --max-spp N        longest render of a series (default 4096)\n"
           "  --target RMSE      the RMSE timed (default 0.01)\n");
}

static const char *kind_mark(target_kind kind)
{
    return kind == TARGET_EXTRAPOLATED ? " (extrapolated)" : kind == TARGET_AT_FIRST ? " (first render, bound)" : "";
}

static void print_result(const ao_convergence_result *r)
{
    const ao_convergence_request *rq = &r->request;
    int faster3 = 0, compared = 0;
    double worst = 0.0;
    printf("AO reference, %dx%d, %d threads: seconds to RMSE %.3g of ao.V (reference %d spp)\n\n", rq->width,
           rq->height, rq->threads, rq->target, rq->reference_spp);
    printf("%-16s %12s %12s %9s\n", "scene", "plain s", "cv s", "speed-up");
    for (int i = 0; i < r->scene_count; ++i) {
        const ao_convergence_scene *s = &r->scenes[i];
        int exact = s->kind[CONVERGENCE_PLAIN] == TARGET_AT_FIRST && s->kind[CONVERGENCE_CV] == TARGET_AT_FIRST;
        printf("%-16s %12.4g %12.4g %8.2fx%s%s\n", s->scene, s->time_to_target[CONVERGENCE_PLAIN],
               s->time_to_target[CONVERGENCE_CV], s->speedup, exact ? "  (both at the first render: no ratio)" : "",
               exact ? "" : kind_mark(s->kind[CONVERGENCE_PLAIN] > s->kind[CONVERGENCE_CV] ? s->kind[CONVERGENCE_PLAIN]
                                                                                            : s->kind[CONVERGENCE_CV]));
        if (exact)
            continue;
        ++compared;
        faster3 += s->speedup >= 3.0;
        worst = compared == 1 || 1.0 / s->speedup > worst ? 1.0 / s->speedup : worst;
    }
    printf("\n%d of %d scenes (with a ratio) at least 3x faster; the worst is %.2fx %s\n", faster3, compared,
           worst >= 1.0 ? worst : 1.0 / worst, worst >= 1.0 ? "slower" : "faster");
}

/* One option into the request; 0, or an exit status. */
static int parse_option(int c, const char *arg, ao_convergence_request *rq, const char **dir)
{
    long v = 0;
    switch (c) {
    case 'o': *dir = arg; return 0;
    case 'W': return cli_parse_int("--width", arg, 8, 4096, &v) ? EXIT_USER_ERROR : (rq->width = (int)v, 0);
    case 'H': return cli_parse_int("--height", arg, 8, 4096, &v) ? EXIT_USER_ERROR : (rq->height = (int)v, 0);
    case 't': return cli_parse_int("--threads", arg, 1, 1024, &v) ? EXIT_USER_ERROR : (rq->threads = (int)v, 0);
    case 'R':
        return cli_parse_int("--reference-spp", arg, 16, 1 << 20, &v) ? EXIT_USER_ERROR
                                                                       : (rq->reference_spp = (int)v, 0);
    case 'M': return cli_parse_int("--max-spp", arg, 16, 1 << 20, &v) ? EXIT_USER_ERROR : (rq->max_spp = (int)v, 0);
    case 'T': return cli_parse_double("--target", arg, 1e-6, 1.0, &rq->target) ? EXIT_USER_ERROR : 0;
    default: return cli_usage_error("bench convergence");
    }
}

int bench_convergence(int argc, char **argv)
{
    static const struct option longs[] = {
        {"width", required_argument, 0, 'W'},   {"height", required_argument, 0, 'H'},
        {"threads", required_argument, 0, 't'}, {"reference-spp", required_argument, 0, 'R'},
        {"max-spp", required_argument, 0, 'M'}, {"target", required_argument, 0, 'T'},
        {"help", no_argument, 0, 'h'},          {0, 0, 0, 0}};
    ao_convergence_request rq = ao_convergence_default_request(threads_default());
    const char *dir = "bench_convergence";
    int c;
    while ((c = getopt_long(argc, argv, "ho:", longs, NULL)) != -1) {
        if (c == 'h') {
            print_help();
            return EXIT_OK;
        }
        int status = parse_option(c, optarg, &rq, &dir);
        if (status != 0)
            return status;
    }
    if (optind < argc)
        return cli_failf("bench convergence", "unexpected argument '%s'", argv[optind]);
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return cli_failf(dir, "cannot create the folder: %s", strerror(errno));
    static ao_convergence_result r;
    gt_error e;
    if (ao_convergence_run(&rq, &r, &e) != 0)
        return cli_fail(&e);
    print_result(&r);
    if (convergence_plot(&r, dir, &e) != 0)
        return cli_fail(&e);
    printf("figure: %s/convergence.png, data: %s/convergence.dat\n", dir, dir);
    return EXIT_OK;
}
