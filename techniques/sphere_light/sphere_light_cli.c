/* GGX sphere lights: Karis's representative point and Decima's
 * GetNoHSquared. `gtlab fit sphere-light`, `gtlab check sphere-noh`,
 * `gtlab bench sphere-light` and the stage sphere-light (sphere_light/sphere_light_study.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"
#include "sphere_light/sphere_light_fit_outputs.h"
#include "sphere_light/sphere_light_section.h"
#include "sphere_light/sphere_light_study.h"
#include "sphere_light/sphere_noh_figures.h"

static void print_outcome(const sphere_fit_settings *s, const sphere_fit_outcome *o)
{
    printf("fitted on %d configurations (%s, %d iterations):\n", s->train,
           o->fit.converged ? "converged" : "NOT converged", o->fit.iterations);
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j)
        printf("  %-17s %10.5g +- %-9.2g (published %g)\n", o->constants[j].name, o->constants[j].value,
               o->constants[j].stderr_, o->constants[j].published);
    printf("held-out error, ln((model + 0.01)/(reference + 0.01)) over %d configurations:\n", s->test);
    const char *names[SPHERE_FIT_MODELS] = {"Karis", "Decima published", "Decima refit"};
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m) {
        const sphere_light_errors *x = &o->held_out[m].errors;
        printf("  %-17s mean |error| %.4f +- %.4f, RMS %.4f +- %.4f\n", names[m], x->mean_abs, x->mean_abs_stderr,
               x->rms, x->rms_stderr);
    }
    printf("reference noise: mean relative standard error %.4f\n", o->mean_reference_rel_stderr);
}

static const cli_option fit_options[] = {
    CLI_OUTPUT("F.json", 0, "where to write (the others beside it)"),
    CLI_INT("train", "N", 16, 10000000, "configurations fitted"),
    CLI_INT("test", "N", 16, 10000000, "held-out configurations"),
    CLI_INT("samples", "S", 2, 1 << 24, "MIS samples per reference"),
    CLI_SEED("seed", "seed of the configurations and samples"), CLI_THREADS, CLI_END};
static const cli_command fit_command = {
    "fit sphere-light",
    "Refits the radius reduction and the normalisation constants of Decima's\n"
    "EvaluateSphericalAreaGGX (SIGGRAPH 2017 appendix; published 0.25, 0.25, 3.0) to Monte\n"
    "Carlo references of a GGX surface under a uniform spherical light, over a realistic\n"
    "distribution of roughness (0.05-1), angular size (the sun's to 30 deg), view angle and\n"
    "light direction (mostly near the mirror direction, where highlights are). The error is\n"
    "ln((model + 0.01) / (reference + 0.01)) in 1/sr per unit normal illuminance: relative\n"
    "where the highlight is. Errors of Karis's, the published and the refitted constants are\n"
    "measured on held-out configurations, with standard errors. The radius reduction is\n"
    "profiled (held on a grid while the normalisation is fitted: the cost is rugged in it);\n"
    "its value and standard error come from a parabola through the profile. Writes\n"
    "  fit.json    values, standard errors, covariance, errors before/after, data used\n"
    "  fit.h       the constants for sphere_light/sphere_light.h (C)\n"
    "  fit.hlsl    GetNoHSquared (corrected) and EvaluateSphericalAreaGGX with the constants\n"
    "  fit.glsl    the same for GLSL",
    fit_options, NULL, NULL};

static int fit_sphere_light(int argc, char **argv)
{
    const char *output = NULL;
    long train = 8000, test = 4000, samples = 1024, seed = 1, threads = threads_default();
    int status;
    if (cli_options_parse(&fit_command, (void *[]){&output, &train, &test, &samples, &seed, &threads}, argc, argv,
                          &status) != 0)
        return status;
    if (!output)
        return cli_failf("fit sphere-light", "no output given (-o fit.json)");
    sphere_fit_settings s = {(int)train, (int)test, (uint32_t)samples, (uint32_t)seed, (int)threads};
    static sphere_fit_outcome o;
    gt_error e;
    if (sphere_fit_check_writable(output, &e) != 0 || sphere_fit_study(&s, &o, &e) != 0 ||
        sphere_fit_write(&s, &o, output, &e) != 0)
        return cli_fail(&e);
    print_outcome(&s, &o);
    printf("written: %s and its .h, .hlsl, .glsl (%.1f s)\n", output, o.seconds);
    return EXIT_OK;
}

static const cli_option bench_options[] = {
    CLI_INT("count", "N", 1024, 1L << 28, "configurations per pass"), CLI_INT("repeats", "R", 1, 100, "passes"),
    CLI_END};
static const cli_command bench_command = {
    "bench sphere-light",
    "The cost of GetNoHSquared without (Karis) and with (Decima) the Newton step, as C\n"
    "compiled in this binary (x86-64 scalar SSE, -O3, steps always inlined):\n"
    "  instructions   static count of each function's instructions, from objdump's\n"
    "                 disassembly of this binary (both are straight code but for the\n"
    "                 early-out branch)\n"
    "  time           nanoseconds per call over an array of N random configurations,\n"
    "                 one thread, best of R passes\n"
    "The talk measured +87% GPU cycles for the step; a CPU is not a GPU, so both figures\n"
    "are printed, not compared.",
    bench_options, NULL, NULL};

static int bench_sphere_light(int argc, char **argv)
{
    long count = 1L << 22, repeats = 5;
    int status;
    if (cli_options_parse(&bench_command, (void *[]){&count, &repeats}, argc, argv, &status) != 0)
        return status;
    sphere_cost cost;
    sphere_cost_study(count, (int)repeats, &cost);
    if (isnan(cost.ns_karis))
        return cli_failf("bench sphere-light", "out of memory for %ld configurations", count);
    sphere_cost_print(stdout, &cost, count, (int)repeats);
    return EXIT_OK;
}

static const cli_option check_options[] = {
    CLI_OUTPUT("DIR", 0, "output folder"),
    CLI_INT("steps", "N", 2, 64, "grid points per dimension (default 16: 65536 configurations)"),
    CLI_INT("rim-steps", "K", 16, 65536, "brute-force angles on the rim before refinement"), CLI_END};
static const cli_command check_command = {
    "check sphere-noh",
    "How close GetNoHSquared (Decima, SIGGRAPH 2017) comes to the largest (N.H)^2 over a\n"
    "spherical light: for every configuration of a grid over n.v, the light's elevation\n"
    "and azimuth and its angular size (tan(sigma) from 0.001 to 1), the shortfall below\n"
    "the brute-force maximum over the rim of Karis's point (0 Newton steps), the talk's\n"
    "one Newton step, two steps, and one step guarded (taken only where f''(0) < 0, i.e.\n"
    "where it heads for a maximum; not in the talk). Prints the mean, 99th percentile and worst case, and\n"
    "the share of configurations where a step makes things worse; writes\n"
    "  DIR/sphere_noh.csv        every configuration\n"
    "  DIR/sphere_noh_map.csv    means over (n.v, light elevation)\n"
    "  DIR/sphere_noh_map.png    where the step helps or hurts (and .gp scripts)\n"
    "  DIR/sphere_noh_by_nv.csv  mean shortfalls against n.v\n"
    "  DIR/sphere_noh_error.png  mean shortfall against n.v",
    check_options, NULL, NULL};

static void print_stats(const sphere_noh_stats *st)
{
    printf("%ld configurations, R inside the light (exact, 1) in %ld\n", st->configurations, st->r_inside);
    printf("shortfall of (N.H)^2 below the brute-force maximum, R outside:\n");
    printf("%-22s %12s %12s %12s %14s %14s  (than)\n", "", "mean", "99th pct", "worst", "worse", "better");
    for (int m = 0; m < NOH_METHODS; ++m) {
        const sphere_noh_row *r = &st->rows[m];
        printf("%-22s %12.4g %12.4g %12.4g %13.2f%% %13.2f%%  %s\n", r->method, r->mean, r->p99, r->worst,
               100.0 * r->share_worse, 100.0 * r->share_better, r->has_baseline ? r->baseline : "");
    }
}

static int check_sphere_noh(int argc, char **argv)
{
    const char *dir = "sphere-noh";
    long steps = 16, rim_steps = 256;
    int status;
    if (cli_options_parse(&check_command, (void *[]){&dir, &steps, &rim_steps}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(dir)) != 0)
        return status;
    sphere_noh_sweep sweep = {(int)steps, (int)steps, (int)steps, (int)steps, (int)rim_steps};
    sphere_noh_stats st;
    gt_error e;
    if (sphere_noh_study(&sweep, dir, &st, &e) != 0 || sphere_noh_plots(dir, &e) != 0)
        return cli_fail(&e);
    print_stats(&st);
    printf("written: %s/sphere_noh.csv, sphere_noh_map.csv, sphere_noh_map.png, sphere_noh_error.png\n", dir);
    return EXIT_OK;
}

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_sphere_light, sphere_light_result, sphere_light_study, sphere_light_section)

const technique technique_sphere_light = {
    .name = "sphere-light",
    .subcommands = {
        [VERB_FIT] = CLI_SUBCOMMANDS(
            {"sphere-light", fit_sphere_light, "Decima's sphere-light radius reduction and normalisation vs MC references"}),
        [VERB_CHECK] = CLI_SUBCOMMANDS(
            {"sphere-noh", check_sphere_noh, "GetNoHSquared (Karis, 1 and 2 Newton steps) against the brute-force max of (N.H)^2"}),
        [VERB_BENCH] = CLI_SUBCOMMANDS(
            {"sphere-light", bench_sphere_light, "cost of the Newton step: instructions and ns"}),
    },
    .stages = ALL_STAGES({"sphere-light", "GGX sphere lights", all_stage_sphere_light, NULL, NULL}),
};
