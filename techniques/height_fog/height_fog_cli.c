/* The command-line face of the Decima height fog (Kojima 2017; issue 16):
 * `gtlab approx height-fog` (the analytic fog over a G-buffer), `gtlab bench
 * height-fog` and the stage height-fog of `gtlab all` (the study, height_fog_study.h, with
 * the combination images, aerial_perspective_study.h, and their sections).
 * The references are `gtlab render fog` (techniques/height_fog/height_fog_quantity.c). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/files/exr_io.h"
#include "core/threads.h"
#include "height_fog/height_fog_section.h"
#include "height_fog/height_fog_study.h"

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
        "The Decima talk's analytic HeightFog() (height_fog/height_fog.h) per pixel: as published, with its\n"
        "clamp fixed, with the sun attenuated by the fog, or the sun and the sky\n"
        "(techniques/height_fog/README.md).", options, NULL, NULL};
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
    static const cli_option options[] = {CLI_THREADS, CLI_END};
    static const cli_command command = {"bench height-fog", "Reference rays per second (path tracing, dense fog, terrain "
        "128x96) and the analytic\nmodels' nanoseconds per pixel in C (goal < 20).", options, NULL, NULL};
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

const technique technique_height_fog = {.name = "height-fog",
    .subcommands = {[VERB_APPROX] = (const cli_subcommand[]){{"height-fog", approx_height_fog,
                        "the Decima talk's analytic height fog (published or corrected)"}, {0}},
                    [VERB_BENCH] = (const cli_subcommand[]){{"height-fog", bench_fog, "height fog: reference rays/s, analytic ns/pixel"}, {0}}},
    .stages = (const all_stage[]){{"height-fog", "height fog", all_stage_fog, HEIGHT_FOG_DIR, NULL}, {0}},
    .renamed = TECHNIQUE_RENAMES({"fog", "height-fog"})};
