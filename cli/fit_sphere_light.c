/* gtlab fit sphere-light: refits Decima's sphere-light radius reduction and
 * normalisation (SIGGRAPH 2017, appendix "Spherical Area Lighting": "still
 * in flux ... to better match our reference") to gtlab's Monte Carlo
 * reference (studies/sphere_light.h), and writes the constants for an
 * engine: JSON, a C header, HLSL and GLSL (fitters/fit_sphere_light_outputs.h). */
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "fitters/fit_sphere_light_outputs.h"
#include "studies/sphere_light.h"
#include "core/threads.h"

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

static const cli_option options[] = {
    CLI_OUTPUT("F.json", 0, "where to write (the others beside it)"),
    CLI_INT("train", "N", 16, 10000000, "configurations fitted"),
    CLI_INT("test", "N", 16, 10000000, "held-out configurations"),
    CLI_INT("samples", "S", 2, 1 << 24, "MIS samples per reference"),
    CLI_SEED("seed", "seed of the configurations and samples"), CLI_THREADS, CLI_END};
static const cli_command command = {
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
    "  fit.h       the constants for realtime/sphere_light.h (C)\n"
    "  fit.hlsl    GetNoHSquared (corrected) and EvaluateSphericalAreaGGX with the constants\n"
    "  fit.glsl    the same for GLSL",
    options, NULL, NULL};

int fit_sphere_light(int argc, char **argv)
{
    const char *output = NULL;
    long train = 8000, test = 4000, samples = 1024, seed = 1, threads = threads_default();
    int status;
    if (cli_options_parse(&command, (void *[]){&output, &train, &test, &samples, &seed, &threads}, argc, argv,
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
