/* INSIDE's volumetric lights (Gjoel & Svendsen, GDC 2016; issue 29): the
 * ray-march against the single-scattering reference (volumetric_light/volumetric_light_study.h; the
 * reference itself is `gtlab render volumetric-light`): `gtlab approx
 * volumetric-light`, `gtlab bench volumetric-light`, stage volumetric-light. */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/files/exr_io.h"
#include "core/threads.h"
#include "volumetric_light/volumetric_light_section.h"
#include "volumetric_light/volumetric_light_study.h"

static const char *noise_name(int i) { return raymarch_noise_name((raymarch_noise)i); }

static int approx_raymarch(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_INT("width", "W", 16, 4096, "image width (default 256)"),
        CLI_INT("height", "H", 16, 4096, "image height (default 256)"),
        CLI_INT("steps", "N", 1, 4096, "samples per ray (default 6)"),
        CLI_CHOICE("noise", "K", noise_name, RAYMARCH_NOISE_COUNT, "none, white, bayer, ign or blue (default blue)"),
        CLI_INT("frames", "F", 1, 4096, "frames accumulated, alpha 0.1 (default 1)"),
        CLI_FLAG("half", "march at half resolution, depth-aware upsample"),
        CLI_INT("shadow-map", "S", 8, 8192, "shadow-map texels per axis (default 512)"),
        CLI_THREADS,
        CLI_OUTPUT("F.exr", 1, "vlight.L.R/G/B"),
        CLI_END};
    static const cli_command command = {
        "approx volumetric-light",
        "INSIDE's volumetric-light ray-march (volumetric_light/volumetric_light_raymarch.h) on builtin:cornell with the\n"
        "default spot of `gtlab render volumetric-light`: N uniform steps in the cone, shadow map, start\n"
        "offset by noise, optionally half resolution and accumulated over frames.",
        options, NULL, NULL};
    long width = 256, height = 256, steps = 6, frames = 1, shadow = 512, threads = threads_default();
    int noise = RAYMARCH_NOISE_BLUE, half = 0, status;
    const char *out_path = NULL;
    if (cli_options_parse(&command, (void *[]){&width, &height, &steps, &noise, &frames, &half, &shadow, &threads,
                                              &out_path},
                          argc, argv, &status) != 0)
        return status;
    volumetric_light_approx_request rq = {(int)width, (int)height, (int)steps, (int)frames, half, (int)shadow, (int)threads,
                                (raymarch_noise)noise, 0.1};
    image out;
    gt_error e;
    if (volumetric_light_approx_image(&rq, &out, &e) != 0)
        return cli_fail(&e);
    int rc = exr_write(out_path, &out, &e);
    image_free(&out);
    return rc == 0 ? EXIT_OK : cli_fail(&e);
}

static int bench_raymarch(int argc, char **argv)
{
    static const cli_option options[] = {CLI_INT("steps", "N", 1, 4096, "samples per ray (default 32)"), CLI_END};
    static const cli_command command = {
        "bench volumetric-light",
        "The volumetric-light ray-march's cost in C, one thread: nanoseconds per pixel per sample\n"
        "(builtin:cornell 256x256, blue noise, 512^2 shadow map with 2x2 PCF).",
        options, NULL, NULL};
    long steps = 32;
    int status;
    if (cli_options_parse(&command, (void *[]){&steps}, argc, argv, &status) != 0)
        return status;
    double ns;
    gt_error e;
    if (volumetric_light_bench(256, 256, (int)steps, &ns, &e) != 0)
        return cli_fail(&e);
    printf("volumetric-light: %.2f ns per pixel per sample (%ld steps)\n", ns, steps);
    return EXIT_OK;
}

GTLAB_STUDY_STAGE(all_stage_volumetric, volumetric_light, volumetric_light_section)

const technique technique_volumetric_light = {
    .name = "volumetric-light",
    .subcommands = {
        [VERB_APPROX] = CLI_SUBCOMMANDS(
            {"volumetric-light", approx_raymarch, "INSIDE's volumetric-light ray-march (noise, steps, half res, frames)"}),
        [VERB_BENCH] = CLI_SUBCOMMANDS(
            {"volumetric-light", bench_raymarch, "volumetric-light ray-march: ns per pixel per sample"}),
    },
    .stages = ALL_STAGES({"volumetric-light", "volumetric lights (INSIDE)", all_stage_volumetric, VOLUMETRIC_LIGHT_DIR, NULL}),
    .renamed = TECHNIQUE_RENAMES({"volumetric", "volumetric-light"}, {"raymarch", "volumetric-light"}),
};
