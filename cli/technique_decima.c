/* Decima (Advances in Real-Time Rendering 2017) on the command line. The height fog (Kojima; issue 16): its
 * atmosphere LUTs (`gtlab lut|bench atmosphere`, stage atmosphere; studies/atmosphere_luts.h); the analytic fog
 * is techniques/height_fog/.
 * Anti-aliasing (issue 19): `gtlab approx|bench aa`, stage aa (studies/anti_aliasing.h, aa_commands.h). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/exr_io.h"
#include "core/threads.h"
#include "report/anti_aliasing_section.h"
#include "report/atmosphere_section.h"
#include "core/pixel_filter.h"
#include "studies/aa_commands.h"
#include "studies/anti_aliasing.h"
#include "studies/atmosphere_luts.h"

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

GTLAB_STUDY_STAGE(all_stage_aa, aa, aa_section)

static int approx_aa(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_CHOICE("technique", "T", aa_technique_short_name, AA_T_TECHNIQUES, "none, fxaa, taa, edge-taa, checkerboard"),
        CLI_STRING("scene", "S", "builtin:NAME or a glTF file"), CLI_INT32("frames", "N", 1, 100000, "frames"),
        CLI_INT32("threads", "T", 1, 1024, "worker threads; the result does not depend on it"), CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {"approx aa", "An AA technique over 384x288 frames of a pan (4 cm, 0.25 deg a "
        "frame): DIR/<technique>_NNN.exr, .png\n(display values; studies/aa_commands.h).", options, NULL, NULL};
    aa_frames_request rq = {"builtin:aa-thin", 384, 288, 8, {0.04f, 0.0f, 0.0f}, 0.25f, 3, NULL, (int)threads_default(),
                            0, 0};
    int status;
    gt_error e;
    if (cli_options_parse(&command, (void *[]){&rq.technique, &rq.scene, &rq.frames, &rq.threads, &rq.dir}, argc, argv,
                          &status) != 0 || (status = cli_make_output_dir(rq.dir)) != 0)
        return status;
    return aa_approx(&rq, &e) == 0 ? EXIT_OK : cli_fail(&e);
}

static const char *truth_filter_name(int i) { return pixel_filter_name(i); }

static int render_frames(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_STRING("scene", "S", "builtin:NAME or a glTF file (default builtin:aa-thin)"),
        CLI_INT32("width", "W", 8, 8192, "frame width"), CLI_INT32("height", "H", 8, 8192, "frame height"),
        CLI_INT32("frames", "N", 1, 100000, "frames"),
        CLI_CHOICE("jitter", "T", aa_technique_short_name, AA_T_TECHNIQUES, "whose sub-pixel jitter: none (centres), "
                   "taa (Halton 2,3),\nedge-taa (edge midpoints), checkerboard (corners); fxaa = none"),
        CLI_INT32("truth", "S", 0, 16, "also each frame's truth, S x S stratified samples a pixel\n(4: 16x, 8: 64x; "
                  "0: none)"),
        CLI_CHOICE("filter", "F", truth_filter_name, PIXEL_FILTER_COUNT, "the truth's pixel filter: box or "
                   "blackman-harris"),
        CLI_INT32("threads", "T", 1, 1024, "worker threads; the result does not depend on it"), CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {"render frames", "Shaded frames (sun + sky, shadow rays) of a pan, 4 cm and 0.25 "
        "deg a frame: DIR/frame_NNN.exr with\nframe.R/G/B (linear), depth.Z, motion.X/Y, disoccluded.V and, with "
        "--truth, truth.R/G/B\n(studies/aa_commands.h).", options, NULL, NULL};
    aa_frames_request rq = {"builtin:aa-thin", 384, 288, 8, {0.04f, 0.0f, 0.0f}, 0.25f, 0, NULL, (int)threads_default(),
                            0, PIXEL_FILTER_BLACKMAN_HARRIS};
    int status;
    gt_error e;
    if (cli_options_parse(&command, (void *[]){&rq.scene, &rq.width, &rq.height, &rq.frames, &rq.technique,
                                              &rq.truth_strata, &rq.truth_filter, &rq.threads, &rq.dir},
                          argc, argv, &status) != 0 || (status = cli_make_output_dir(rq.dir)) != 0)
        return status;
    return aa_frames_write(&rq, &e) == 0 ? EXIT_OK : cli_fail(&e);
}

static int bench_aa(int argc, char **argv)
{
    static const cli_command command = {"bench aa", "ms per 1920x1080 frame per AA technique, in C.", threads_only, NULL, NULL};
    long threads = threads_default();
    int status;
    gt_error e;
    if (cli_options_parse(&command, (void *[]){&threads}, argc, argv, &status) != 0)
        return status;
    return aa_bench_print(stdout, (int)threads, &e) == 0 ? EXIT_OK : cli_fail(&e);
}

const technique technique_anti_aliasing = {.name = "aa",
    .subcommands = {[VERB_APPROX] = (const cli_subcommand[]){{"aa", approx_aa, "anti-aliasing over frames of a pan"}, {0}},
                    [VERB_RENDER] = CLI_SUBCOMMANDS({"frames", render_frames, "shaded frames of a pan with motion, and their truth"}),
                    [VERB_BENCH] = (const cli_subcommand[]){{"aa", bench_aa, "anti-aliasing: ms per 1080p frame"}, {0}}},
    .stages = (const all_stage[]){{"aa", "anti-aliasing against supersampled truth", all_stage_aa, AA_DIR, NULL}, {0}}};
