/* Ambient occlusion and bent-normal references (README.md): the AO stage of
 * `gtlab all` (its references are the inputs of the screen-space
 * techniques' stages) and `gtlab bench convergence`, the AO reference's time
 * to an RMSE, plain and with the height-field control variate, on every
 * built-in scene (ao_convergence.h; the figure: ao_convergence_plot.h). */
#define _GNU_SOURCE
#include <stdio.h>

#include "ao/ao_convergence.h"
#include "ao/ao_convergence_plot.h"
#include "ao/ao_references.h"
#include "ao/ao_section.h"
#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"

static const cli_option options[] = {
    CLI_OUTPUT("DIR", 0, "output folder"), CLI_INT32("width", "W", 8, 4096, "image width"),
    CLI_INT32("height", "H", 8, 4096, "image height"), CLI_INT32("threads", "T", 1, 1024, "threads"),
    CLI_INT32("reference-spp", "N", 16, 1 << 20, "samples of the reference"),
    CLI_INT32("max-spp", "N", 16, 1 << 20, "longest render of a series"),
    CLI_DOUBLE("target", "RMSE", 1e-6, 1.0, "the RMSE timed"), CLI_END};
static const cli_command command = {
    "bench convergence",
    "Measures, in one run, per built-in scene: the RMSE of ao.V against a converged\n"
    "reference (a control-variate render of --reference-spp samples) as a function of\n"
    "the wall time of the whole render (Embree scene, G-buffer, the control variate's\n"
    "horizons and pilot, sampling), for plain sampling and for --control-variate\n"
    "heightfield, each a series of renders at 16, 32, ... spp; then\n"
    "the time each needs to reach the target RMSE and their ratio (plain / control\n"
    "variate). Writes DIR/convergence.dat and DIR/convergence.png (gnuplot).",
    options, NULL, NULL};

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

static int bench_convergence(int argc, char **argv)
{
    ao_convergence_request rq = ao_convergence_default_request(threads_default());
    const char *dir = "bench_convergence";
    int status;
    if (cli_options_parse(&command, (void *[]){&dir, &rq.width, &rq.height, &rq.threads, &rq.reference_spp,
                          &rq.max_spp, &rq.target}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(dir)) != 0)
        return status;
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

GTLAB_STUDY_STAGE(all_stage_ao_references, ao_references, ao_references_section)

const technique technique_ao = {
    .name = "ao",
    .subcommands = {[VERB_BENCH] = CLI_SUBCOMMANDS(
        {"convergence", bench_convergence, "AO time to RMSE 0.01, plain against the height-field control variate"})},
    .stages = ALL_STAGES({"ao", "AO references", all_stage_ao_references, AO_REFERENCES_DIR, NULL}),
};
