/* Environment lighting (issue 28): `gtlab bench env-diffuse`, the
 * environment-lit diffuse reference's samples/s against the white-dome
 * multibounce reference on the same scene (raytracer/environment_throughput.h). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"
#include "raytracer/environment_throughput.h"
#include "studies/study.h"

static const cli_option bench_options[] = {
    CLI_STRING("scene", "S", "builtin:NAME or a glTF file (default builtin:cornell)"),
    CLI_STRING("environment", "E", "white, sky, sun or an image file (default: Blender's sunset.exr)"),
    CLI_INT("width", "W", 16, 8192, "image width"), CLI_INT("height", "H", 16, 8192, "image height"),
    CLI_INT("spp", "N", 1, 1 << 20, "samples (paths) per pixel"),
    CLI_INT("bounces", "N", 0, 1024, "inter-reflections (default 4)"),
    CLI_INT("threads", "T", 1, 1024, "threads (default: all cores)"),
    CLI_INT("repeats", "R", 1, 100, "passes per figure"), CLI_END};
static const cli_command bench_command = {
    "bench env-diffuse",
    "Measures, in one run, on the same scene, camera, G-buffer and machine, samples/s of\n"
    "  multibounce   the white-dome reference (grey albedo 0.5, --bounces)\n"
    "  env-diffuse   the environment-lit reference, same albedo and bounces (MIS of\n"
    "                cosine and environment sampling, one ray per vertex)\n"
    "and their ratio env-diffuse / multibounce (issue 28's goal: >= 0.7). Each figure\n"
    "is the best of R passes, the two loops alternating.",
    bench_options, NULL, NULL};

#define BLENDER_SUNSET "/usr/share/blender/datafiles/studiolights/world/sunset.exr"

static int bench_env_diffuse(int argc, char **argv)
{
    const char *spec = "builtin:cornell", *environment = BLENDER_SUNSET;
    long width = 128, height = 128, spp = 64, bounces = 4, threads = threads_default(), repeats = 3;
    int status;
    if (cli_options_parse(&bench_command,
                          (void *[]){&spec, &environment, &width, &height, &spp, &bounces, &threads, &repeats}, argc,
                          argv, &status) != 0)
        return status;
    multibounce_settings albedo = {.albedo_count = 1, .albedos = {0.5f}, .bounces = (int)bounces};
    environment_render_settings light;
    environment_render_settings_default(&light);
    snprintf(light.environment, sizeof light.environment, "%s", environment);
    scene s;
    camera cam;
    gt_error e;
    environment_throughput r;
    if (study_load_view(spec, (int)width, (int)height, &s, &cam, &e) != 0)
        return cli_fail(&e);
    int rc = environment_throughput_run(&s, &cam, &albedo, &light, (int)spp, (int)threads, (int)repeats, &r, &e);
    scene_free(&s);
    if (rc != 0)
        return cli_fail(&e);
    printf("scene %s, %ldx%ld, %ld spp, albedo 0.5, %ld bounces, %d threads, best of %ld\n", spec, width, height, spp,
           bounces, r.threads, repeats);
    printf("environment %s\n\n", environment);
    printf("%-34s %14s %14s\n", "", "samples/s", "rays/s");
    printf("%-34s %14.4g %14.4g\n", "multibounce (white dome)", r.multibounce_samples_per_s, r.multibounce_rays_per_s);
    printf("%-34s %14.4g %14.4g\n", "env-diffuse", r.environment_samples_per_s, r.environment_rays_per_s);
    printf("\nratio env-diffuse / multibounce samples/s: %.3f (goal >= 0.7)\n", r.ratio);
    return EXIT_OK;
}

const technique technique_environment = {
    .name = "environment",
    .subcommands = {[VERB_BENCH] = CLI_SUBCOMMANDS(
        {"env-diffuse", bench_env_diffuse, "environment-lit diffuse samples/s against the white-dome multibounce"})},
};
