/* Decima (Advances in Real-Time Rendering 2017) on the command line. The height fog (Kojima; issue 16): its
 * atmosphere LUTs (`gtlab lut|bench atmosphere`, stage atmosphere; studies/atmosphere_luts.h), the analytic fog
 * (`gtlab approx height-fog`, `gtlab bench fog`, stage fog; studies/height_fog.h; references: `gtlab render fog`).
 * Anti-aliasing (issue 19) is in techniques/anti_aliasing/. */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/exr_io.h"
#include "core/threads.h"
#include "report/atmosphere_section.h"
#include "report/height_fog_section.h"
#include "studies/atmosphere_luts.h"
#include "studies/height_fog.h"

#define AXIS(name, help) CLI_INT(name, "N", 1, ATMOSPHERE_LUT_MAX_AXIS, help)
static const cli_option threads_only[] = {CLI_THREADS, CLI_END};

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
                   "the axes' mappings (luts/atmosphere_lut_axes.h): linear (default;\n"
                   "theta_s, theta_v, y linear), yusov2013 (the talk's [Yus13]) or\n"
                   "bruneton2008 (Bruneton & Neyret 2008); the nonlinear ones: an even\n"
                   "--theta-v of at least 4"),
        CLI_THREADS, CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {"lut atmosphere",
        "Tabulates the three LUTs of the Decima height fog (Kojima 2017) over Bruneton 2017's\n"
        "atmosphere and a dense-fog weather: L_inscatter(theta_s, theta_v, y, t) per species\n"
        "without phase (multiple scattering in the Rayleigh table), L_sun(theta_s, y, t) (sun\n"
        "irradiance at y) and L_sky(theta_s, y, t) (mean sky radiance at y); luts/atmosphere_luts.h.\n"
        "Defaults: the talk's (8, 64, 8, 4) = 128 KB and (64, 1, 4) = 4 KB. Writes, linear:\n"
        "DIR/atmosphere_{inscatter,sun,sky}.exr, atmosphere_luts.h, .hlsl, .glsl (one lookup);\n"
        "yusov2013 or bruneton2008: DIR/atmosphere_{inscatter,sun,sky}_<P>.exr only (their\n"
        "lookup is C: luts/atmosphere_lut_axes.h). Each EXR names its parametrization\n"
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
    static const cli_command command = {"bench atmosphere",
        "Seconds to build the full set of atmosphere LUTs at the talk's sizes, for two weathers\n"
        "and their blends (t axis of 4: four precomputations with multiple scattering, then\n"
        "the texels). Issue 16's goal: under 10 s on 2 cores.", threads_only, NULL, NULL};
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

static const char *weather_name(int i) { return i == 0 ? "sunny" : "dense"; }
static const char *const model_names[] = {"published", "clamp-fixed", "sun-attenuated", "sky-attenuated"};
static const char *model_name(int i) { return model_names[i]; }

static int approx_height_fog(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_REQUIRED_STRING("gbuffer", "G.exr", "a render gbuffer or fog file (P, mask.A, its camera)"),
        CLI_CHOICE("weather", "W", weather_name, 2, "sunny or dense"),
        CLI_DOUBLE("sun-elevation", "DEG", -90, 90, "the sun above the horizon"),
        CLI_CHOICE("model", "M", model_name, HEIGHT_FOG_MODELS, "published, clamp-fixed, sun- or sky-attenuated"),
        CLI_OUTPUT("out.exr", 1, "fog.L.R/G/B and fog.T.R/G/B"), CLI_END};
    static const cli_command command = {"approx height-fog",
        "The Decima talk's analytic HeightFog() (realtime/height_fog.h) per pixel: as published, with its\n"
        "clamp fixed, with the sun attenuated by the fog, or the sun and the sky (docs/decisions.md).", options,
        NULL, NULL};
    const char *in = NULL, *out_path = NULL;
    int weather = 0, model = 0, status;
    double elevation = 25.0;
    if (cli_options_parse(&command, (void *[]){&in, &weather, &elevation, &model, &out_path}, argc, argv, &status))
        return status;
    image g, out;
    gt_error e;
    if (exr_read(in, &g, &e) != 0)
        return cli_fail(&e);
    int rc = height_fog_approx_image(&g, in, weather_name(weather), elevation, (height_fog_model)model, &out, &e);
    image_free(&g);
    if (rc == 0)
        rc = exr_write(out_path, &out, &e), image_free(&out);
    return rc == 0 ? EXIT_OK : cli_fail(&e);
}

static int bench_fog(int argc, char **argv)
{
    static const cli_command command = {"bench fog", "Reference rays per second (path tracing, dense fog, terrain "
        "128x96) and the analytic\nmodels' nanoseconds per pixel in C (goal < 20).", threads_only, NULL, NULL};
    long threads = threads_default();
    int status;
    if (cli_options_parse(&command, (void *[]){&threads}, argc, argv, &status) != 0)
        return status;
    double rays;
    height_fog_timing t;
    gt_error e;
    if (height_fog_bench((int)threads, &rays, &t, &e) != 0)
        return cli_fail(&e);
    height_fog_bench_print(stdout, rays, &t);
    return EXIT_OK;
}

GTLAB_STUDY_STAGE(all_stage_fog, height_fog, height_fog_section)

const technique technique_fog = {.name = "fog",
    .subcommands = {[VERB_APPROX] = (const cli_subcommand[]){{"height-fog", approx_height_fog,
                        "the Decima talk's analytic height fog (published or corrected)"}, {0}},
                    [VERB_BENCH] = (const cli_subcommand[]){{"fog", bench_fog, "height fog: reference rays/s, analytic ns/pixel"}, {0}}},
    .stages = (const all_stage[]){{"fog", "height fog", all_stage_fog, HEIGHT_FOG_DIR, NULL}, {0}}};
