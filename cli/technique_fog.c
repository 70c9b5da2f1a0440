/* The height fog of the Decima talk: `gtlab approx height-fog`, `gtlab bench
 * fog` and its stage of `gtlab all` (studies/height_fog.h); the references
 * are `gtlab render fog` (raytracer/fog_integrator.h). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/exr_io.h"
#include "core/threads.h"
#include "report/height_fog_section.h"
#include "studies/height_fog.h"

static const char *weather_name(int i) { return i == 0 ? "sunny" : "dense"; }
static const char *model_name(int i) { return (const char *[]){"published", "clamp-fixed", "sun-attenuated"}[i]; }

static int approx_height_fog(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_REQUIRED_STRING("gbuffer", "G.exr", "a render gbuffer or fog file (P, mask.A, its camera)"),
        CLI_CHOICE("weather", "W", weather_name, 2, "sunny or dense"),
        CLI_DOUBLE("sun-elevation", "DEG", -90, 90, "the sun above the horizon"),
        CLI_CHOICE("model", "M", model_name, HEIGHT_FOG_MODELS, "published, clamp-fixed or sun-attenuated"),
        CLI_REQUIRED_STRING("output", "out.exr", "fog.L.R/G/B and fog.T.R/G/B"), CLI_END};
    static const cli_command command = {
        "approx height-fog",
        "The Decima talk's analytic HeightFog() (realtime/height_fog.h) per pixel: as published, with its\n"
        "clamp fixed, or with the sun attenuated by the fog (docs/decisions.md, \"Height fog\").",
        options, NULL, NULL};
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
    static const cli_command command = {
        "bench fog", "Reference rays per second (path tracing, dense fog, terrain 128x96) and the analytic\n"
                     "models' nanoseconds per pixel in C (goal < 20).", options, NULL, NULL};
    long threads = threads_default();
    int status;
    if (cli_options_parse(&command, (void *[]){&threads}, argc, argv, &status) != 0)
        return status;
    double rays, ns[HEIGHT_FOG_MODELS];
    gt_error e;
    if (height_fog_bench((int)threads, &rays, ns, &e) != 0)
        return cli_fail(&e);
    printf("reference: %.3g rays/s\nanalytic: %.2f ns/pixel published, %.2f clamp fixed, %.2f sun attenuated\n", rays,
           ns[0], ns[1], ns[2]);
    return EXIT_OK;
}

static int all_stage_fog(report_context *ctx, gt_error *e)
{
    static height_fog_result r;
    height_fog_request rq = height_fog_default_request(ctx->study.quality);
    return height_fog_study(&ctx->study, &rq, &r, e) != 0 ? -1 : height_fog_section(ctx, &r, e);
}

static const cli_subcommand approx[] = {
    {"height-fog", approx_height_fog, "the Decima talk's analytic height fog (published or corrected)"},
    {NULL, NULL, NULL}};
static const cli_subcommand bench[] = {{"fog", bench_fog, "height fog: reference rays/s, analytic ns/pixel"},
                                       {NULL, NULL, NULL}};
static const all_stage stages[] = {{"fog", "height fog", all_stage_fog, HEIGHT_FOG_DIR, NULL},
                                   {NULL, NULL, NULL, NULL, NULL}};

const technique technique_fog = {
    .name = "fog", .subcommands = {[VERB_APPROX] = approx, [VERB_BENCH] = bench}, .stages = stages};
