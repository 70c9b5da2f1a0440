/* gtlab approx gtao: GTAO (realtime/gtao.c) on a G-buffer. */
#include <stdio.h>
#include <string.h>

#include "cli/approx_io.h"
#include "cli/cli.h"
#include "core/reference_schema.h"
#include "realtime/gtao.h"

/* The parameters and the preset they started from (for the header). */
typedef struct {
    gtao_params p;
    const char *preset;
} gtao_settings;

static int compute(const ss_gbuffer *g, const void *settings, image *out)
{
    const gtao_params *p = &((const gtao_settings *)settings)->p;
    float *ao = image_add_channel(out, CH_AO);
    float *bent[3] = {image_add_channel(out, CH_BENT_X), image_add_channel(out, CH_BENT_Y),
                      image_add_channel(out, CH_BENT_Z)};
    if (!ao || !bent[0] || !bent[1] || !bent[2])
        return -1;
    return gtao_render(g, p, ao, bent);
}

static void settings_text(const void *settings, char *text, size_t size)
{
    const gtao_settings *s = settings;
    char params[512];
    gtao_params_text(&s->p, params, sizeof params);
    snprintf(text, size, "preset=%s %s", s->preset, params);
}

/* The preset comes first, whatever its place among the options (the other
 * options override it). */
static const char *find_preset(int argc, char **argv)
{
    const char *preset = "medium";
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--preset") == 0 && i + 1 < argc)
            preset = argv[i + 1];
        else if (strncmp(argv[i], "--preset=", 9) == 0)
            preset = argv[i] + 9;
    }
    return preset;
}

static const char *weighting_name(int i) { return i == GTAO_UNIFORM ? "uniform" : "cosine"; }
static const char *bent_name(int i) { return i ? "halfway" : "exact"; }

static const cli_option options[] = {
    CLI_STRING("preset", "P", "low | medium (the talk's: 1 direction per pixel, 8 samples,\n"
               "4x4 spatial noise and denoiser) | high | ultra | reference\n(brute force: 64 regular slices, exact "
               "horizons through\nevery pixel cell, no noise, no denoiser)"),
    CLI_FLOAT("radius", "R", 1e-9, 1e30, "world-space search radius"),
    CLI_FLOAT("falloff", "F", 0, 1, "fraction of the radius over which samples fade out, in\n[0, 1]; the talk's "
              "150 to 200 inches"),
    CLI_FLOAT("max-radius-px", "P", 1, 4096, "clamp of the screen-space radius in pixels"),
    CLI_FLOAT("thickness", "T", 0, 0.999, "thickness heuristic in [0, 1): how fast a horizon relaxes\n"
              "behind a thin occluder (0: off)"),
    CLI_INT32("slices", "N", 1, 4096, "slice directions per pixel and frame"),
    CLI_INT32("steps", "N", 0, GTAO_MAX_STEPS, "samples per side of a slice (1..256); 0: exact horizons,\n"
              "both ends of every pixel cell within the radius"),
    CLI_INT32("frames", "N", 1, 100000, "frames of the spatio-temporal pattern accumulated by the\n"
              "temporal filter (static camera; 24 is a full cycle)"),
    CLI_SWITCH("pattern", "the talk's 4x4 spatial and 6x4 temporal pattern (off:\nregular slices, step offset 0.5)"),
    CLI_SWITCH("denoise", "the 4x4 bilateral spatial denoiser"),
    CLI_SWITCH("fast-math", "the talk's fast acos and sqrt"),
    CLI_CHOICE("weighting", "W", weighting_name, 2, "cosine | uniform (HBAO's measure)"),
    CLI_CHOICE("bent", "B", bent_name, 2, "bent normal: the cosine-weighted mean direction of each\n"
               "slice's visible arc (exact) or the talk's direction\nhalfway between the horizons (16 degrees off on a plane)"),
    CLI_END};

int approx_gtao(int argc, char **argv)
{
    static const approx_technique technique = {
        "gtao",
        "Ground-truth ambient occlusion (Jimenez et al., SIGGRAPH 2016) on a G-buffer:\n"
        "per slice the two horizons found on the depth buffer, the cosine-weighted arc\n"
        "integrated analytically with the normal projected onto the slice. Writes ao.V\n"
        "(cosine AO, or uniform with --weighting uniform) and bent.X/Y/Z (world space).\n"
        "The preset's values are the defaults; the other options override them.\n"
        "example: gtlab approx gtao --gbuffer ao.exr --preset high --radius 2 -o gtao.exr",
        options, settings_text, compute};
    gtao_settings s = {.preset = find_preset(argc, argv)};
    if (gtao_preset(s.preset, &s.p) != 0)
        return cli_failf("--preset", "unknown preset '%s' (low, medium, high, ultra, reference)", s.preset);
    gtao_params *p = &s.p;
    return approx_main(&technique, &s, (void *[]){&s.preset, &p->radius, &p->falloff, &p->max_radius_px,
                       &p->thickness, &p->slices, &p->steps, &p->frames, &p->pattern, &p->denoise, &p->fast_math,
                       &p->weighting, &p->bent_halfway}, argc, argv);
}
