/* The command-line face of the Decima atmosphere LUTs (Kojima 2017; issue
 * 16, items 3 and 5): `gtlab lut atmosphere` (one set of tables, written),
 * `gtlab bench atmosphere` and the stage atmosphere of `gtlab all` (the
 * study, atmosphere_luts_study.h, and its section). */
#include <stdio.h>

#include "atmosphere/atmosphere_luts_study.h"
#include "atmosphere/atmosphere_section.h"
#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"

#define AXIS(name, help) CLI_INT(name, "N", 1, ATMOSPHERE_LUT_MAX_AXIS, help)

static const char *parametrization_tag(int i) { return atmosphere_lut_parametrization_tag((atmosphere_lut_parametrization)i); }

static int lut_atmosphere(int argc, char **argv)
{
    static const cli_option options[] = {
        AXIS("theta-s", "in-scatter: sun zenith samples over [0, 96 deg] (yusov2013,\nbruneton2008: 101.4 deg)"),
        AXIS("theta-v", "in-scatter: view zenith samples over [0, 180 deg]"),
        AXIS("altitude", "in-scatter: altitude samples over [0, 2 km]"),
        AXIS("weathers", "weather blends t over [0, 1] (clear to dense fog), every table"),
        AXIS("light-theta-s", "sun and sky tables: sun zenith samples"),
        AXIS("light-altitude", "sun and sky tables: altitude samples"),
        CLI_CHOICE("parametrization", "P", parametrization_tag, ATMOSPHERE_PARAMS,
                   "the axes' mappings (atmosphere/atmosphere_lut_axes.h): linear (default;\n"
                   "theta_s, theta_v, y linear), yusov2013 (the talk's [Yus13]) or\n"
                   "bruneton2008 (Bruneton & Neyret 2008); the nonlinear ones: an even\n"
                   "--theta-v of at least 4"),
        CLI_THREADS, CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {"lut atmosphere",
        "Tabulates the three LUTs of the Decima height fog (Kojima 2017) over Bruneton 2017's\n"
        "atmosphere and a dense-fog weather: L_inscatter(theta_s, theta_v, y, t) per species\n"
        "without phase (multiple scattering in the Rayleigh table), L_sun(theta_s, y, t) (sun\n"
        "irradiance at y) and L_sky(theta_s, y, t) (mean sky radiance at y);\n"
        "atmosphere/atmosphere_luts.h.\n"
        "Defaults: the talk's (8, 64, 8, 4) = 128 KB and (64, 1, 4) = 4 KB. Writes, linear:\n"
        "DIR/atmosphere_{inscatter,sun,sky}.exr, atmosphere_luts.h, .hlsl, .glsl (one lookup);\n"
        "yusov2013 or bruneton2008: DIR/atmosphere_{inscatter,sun,sky}_<P>.exr only (their\n"
        "lookup is C: atmosphere/atmosphere_lut_axes.h). Each EXR names its parametrization\n"
        "(gtlab.lut.parametrization), sizes and axes (gtlab.lut); the bytes do not depend on\n"
        "--threads.", options, NULL, NULL};
    long n[6] = {8, 64, 8, 4, 64, 1}, threads = threads_default();
    const char *dir = NULL;
    int status, kind = ATMOSPHERE_PARAM_LINEAR;
    if (cli_options_parse(&command, (void *[]){&n[0], &n[1], &n[2], &n[3], &n[4], &n[5], &kind, &threads, &dir}, argc,
                          argv, &status) != 0)
        return status;
    char msg[256];
    int inscatter[4] = {(int)n[0], (int)n[1], (int)n[2], (int)n[3]};
    if (atmosphere_lut_parametrization_check((atmosphere_lut_parametrization)kind, inscatter, msg, sizeof msg) != 0)
        return fprintf(stderr, "gtlab: --theta-v: %s\n", msg), EXIT_USER_ERROR;
    if ((status = cli_make_output_dir(dir)) != 0)
        return status;
    atmosphere_lut_sizes sizes = {{(int)n[0], (int)n[1], (int)n[2], (int)n[3]}, {(int)n[4], 1, (int)n[5], (int)n[3]},
                                  {(int)n[4], 1, (int)n[5], (int)n[3]}};
    double seconds;
    gt_error e;
    if (atmosphere_luts_write_tables(dir, &sizes, (atmosphere_lut_parametrization)kind, (int)threads, &seconds, &e) != 0)
        return cli_fail(&e);
    if (kind == ATMOSPHERE_PARAM_LINEAR)
        printf("%s/atmosphere_{inscatter,sun,sky}.exr, atmosphere_luts.{h,hlsl,glsl}", dir);
    else
        printf("%s/atmosphere_{inscatter,sun,sky}_%s.exr", dir, parametrization_tag(kind));
    printf(" (%s): built in %.2f s (%.0f + 2 x %.0f bytes)\n",
           atmosphere_lut_parametrization_name((atmosphere_lut_parametrization)kind), seconds,
           atmosphere_lut_bytes(ATMOSPHERE_TABLE_INSCATTER, sizes.inscatter), atmosphere_lut_bytes(ATMOSPHERE_TABLE_SUN, sizes.sun));
    return EXIT_OK;
}

static int bench_atmosphere(int argc, char **argv)
{
    static const cli_option options[] = {CLI_THREADS, CLI_END};
    static const cli_command command = {"bench atmosphere",
        "Seconds to build the full set of atmosphere LUTs at the talk's sizes, for two weathers\n"
        "and their blends (t axis of 4: four precomputations with multiple scattering, then\n"
        "the texels). Issue 16's goal: under 10 s on 2 cores.", options, NULL, NULL};
    long threads = threads_default();
    int status;
    if (cli_options_parse(&command, (void *[]){&threads}, argc, argv, &status) != 0)
        return status;
    atmosphere_model m = atmosphere_model_default();
    atmosphere_lut_sizes sizes = atmosphere_lut_sizes_talk();
    atmosphere_luts luts;
    char msg[256];
    if (atmosphere_luts_build(&luts, &m, &sizes, (int)threads, msg, sizeof msg) != 0)
        return fprintf(stderr, "gtlab bench atmosphere: %s\n", msg), EXIT_USER_ERROR;
    printf("atmosphere LUTs, talk sizes, two weathers (4 blends), %ld threads: %.2f s\n", threads, luts.build_seconds);
    atmosphere_luts_free(&luts);
    return EXIT_OK;
}

GTLAB_STUDY_STAGE(all_stage_atmosphere, atmosphere_luts, atmosphere_section)

const technique technique_atmosphere = {.name = "atmosphere",
    .subcommands = {[VERB_LUT] = (const cli_subcommand[]){{"atmosphere", lut_atmosphere,
                        "Decima height-fog atmosphere: in-scatter, sun, sky vs theta_s, theta_v, y, weather"}, {0}},
                    [VERB_BENCH] = (const cli_subcommand[]){{"atmosphere", bench_atmosphere,
                        "atmosphere LUTs: build seconds at the talk's sizes, two weathers"}, {0}}},
    .stages = (const all_stage[]){
        {"atmosphere", "Decima atmosphere LUTs and their sizes", all_stage_atmosphere, ATMOSPHERE_LUTS_DIR, NULL}, {0}}};
