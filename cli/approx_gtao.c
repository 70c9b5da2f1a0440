/* gtlab approx gtao: GTAO (realtime/gtao.c) on a G-buffer. */
#include <getopt.h>
#include <stdio.h>
#include <string.h>

#include "cli/approx_io.h"
#include "cli/cli.h"
#include "realtime/gtao.h"
#include "core/reference_schema.h"

static void print_help(void)
{
    printf("usage: gtlab approx gtao --gbuffer G.exr [--preset P] [options] -o out.exr\n"
           "\n"
           "Ground-truth ambient occlusion (Jimenez et al., SIGGRAPH 2016) on a G-buffer:\n"
           "per slice the two horizons found on the depth buffer, the cosine-weighted arc\n"
           "integrated analytically with the normal projected onto the slice. Writes ao.V\n"
           "(cosine AO, or uniform with --weighting uniform) and bent.X/Y/Z (world space).\n"
           "\n"
           "  --preset P            low | medium (the talk's: 1 direction per pixel, 8 samples,\n"
           "                        4x4 spatial noise and denoiser) | high | ultra | reference\n"
           "                        (brute force: 64 regular slices, exact horizons through\n"
           "                        every pixel cell, no noise, no denoiser); default medium\n"
           "  --radius R            world-space search radius (default 1)\n"
           "  --falloff F           fraction of the radius over which samples fade out, in\n"
           "                        [0, 1] (default 0.25: the talk's 150 to 200 inches)\n"
           "  --max-radius-px P     clamp of the screen-space radius in pixels (default 256)\n"
           "  --slices N            slice directions per pixel and frame\n"
           "  --steps N             samples per side of a slice (1..256); 0: exact horizons,\n"
           "                        both ends of every pixel cell within the radius\n"
           "  --thickness T         thickness heuristic in [0, 1): how fast a horizon relaxes\n"
           "                        behind a thin occluder (default 0: off)\n"
           "  --weighting W         cosine (default) | uniform (HBAO's measure)\n"
           "  --frames N            frames of the spatio-temporal pattern accumulated by the\n"
           "                        temporal filter (static camera; 24 is a full cycle)\n"
           "  --pattern on|off      the talk's 4x4 spatial and 6x4 temporal pattern (off:\n"
           "                        regular slices, step offset 0.5)\n"
           "  --denoise on|off      the 4x4 bilateral spatial denoiser\n"
           "  --fast-math on|off    the talk's fast acos and sqrt\n"
           "  --bent exact|halfway  bent normal: the cosine-weighted mean direction of each\n"
           "                        slice's visible arc (default) or the talk's direction\n"
           "                        halfway between the horizons (16 degrees off on a plane)\n"
           "%s"
           "\nexample: gtlab approx gtao --gbuffer ao.exr --preset high --radius 2 -o gtao.exr\n",
           approx_common_help);
}

static int compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    float *bent[3] = {image_add_channel(out, CH_BENT_X), image_add_channel(out, CH_BENT_Y),
                      image_add_channel(out, CH_BENT_Z)};
    if (!ao || !bent[0] || !bent[1] || !bent[2])
        return -1;
    return gtao_render(g, params, ao, bent);
}

/* Options that override the preset. */
/* The parameters and the preset they started from (for the header). */
typedef struct {
    gtao_params p;
    const char *preset;
} gtao_settings;

static int compute_settings(const ss_gbuffer *g, const void *settings, image *out)
{
    return compute(g, &((const gtao_settings *)settings)->p, out);
}

static void settings_text(const void *settings, char *text, size_t size)
{
    const gtao_settings *s = settings;
    char params[512];
    gtao_params_text(&s->p, params, sizeof params);
    snprintf(text, size, "preset=%s %s", s->preset, params);
}

static int parse_option(int c, const char *arg, void *settings)
{
    gtao_params *p = &((gtao_settings *)settings)->p;
    double v;
    long n;
    switch (c) {
    case 'p': return 0; /* read first, by find_preset */
    case 'r': return cli_parse_double("--radius", arg, 1e-9, 1e30, &v) ? -1 : (p->radius = (float)v, 0);
    case 'f': return cli_parse_double("--falloff", arg, 0, 1, &v) ? -1 : (p->falloff = (float)v, 0);
    case 'm': return cli_parse_double("--max-radius-px", arg, 1, 4096, &v) ? -1 : (p->max_radius_px = (float)v, 0);
    case 'T': return cli_parse_double("--thickness", arg, 0, 0.999, &v) ? -1 : (p->thickness = (float)v, 0);
    case 's': return cli_parse_int("--slices", arg, 1, 4096, &n) ? -1 : (p->slices = (int)n, 0);
    case 'n': return cli_parse_int("--steps", arg, 0, GTAO_MAX_STEPS, &n) ? -1 : (p->steps = (int)n, 0);
    case 'F': return cli_parse_int("--frames", arg, 1, 100000, &n) ? -1 : (p->frames = (int)n, 0);
    case 'P': return approx_parse_switch("--pattern", arg, &p->pattern);
    case 'D': return approx_parse_switch("--denoise", arg, &p->denoise);
    case 'M': return approx_parse_switch("--fast-math", arg, &p->fast_math);
    case 'B':
        if (strcmp(arg, "exact") == 0 || strcmp(arg, "halfway") == 0) {
            p->bent_halfway = arg[0] == 'h';
            return 0;
        }
        return cli_failf("--bent", "'%s' is neither exact nor halfway", arg), -1;
    case 'W':
        if (strcmp(arg, "cosine") == 0 || strcmp(arg, "uniform") == 0) {
            p->weighting = arg[0] == 'u' ? GTAO_UNIFORM : GTAO_COSINE;
            return 0;
        }
        return cli_failf("--weighting", "'%s' is neither cosine nor uniform", arg), -1;
    default: return cli_usage_error("approx gtao"), -1;
    }
}

/* The preset comes first, whatever its place among the options. */
static int find_preset(int argc, char **argv, const char **preset)
{
    *preset = "medium";
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--preset") == 0 && i + 1 < argc)
            *preset = argv[i + 1];
        else if (strncmp(argv[i], "--preset=", 9) == 0)
            *preset = argv[i] + 9;
    }
    return 0;
}

int approx_gtao(int argc, char **argv)
{
    static const struct option longs[] = {
        {"preset", required_argument, 0, 'p'},      {"radius", required_argument, 0, 'r'},
        {"falloff", required_argument, 0, 'f'},     {"max-radius-px", required_argument, 0, 'm'},
        {"thickness", required_argument, 0, 'T'},   {"slices", required_argument, 0, 's'},
        {"steps", required_argument, 0, 'n'},       {"frames", required_argument, 0, 'F'},
        {"pattern", required_argument, 0, 'P'},     {"denoise", required_argument, 0, 'D'},
        {"fast-math", required_argument, 0, 'M'},   {"weighting", required_argument, 0, 'W'},
        {"bent", required_argument, 0, 'B'},
        APPROX_COMMON_OPTIONS};
    static const approx_technique technique = {"gtao", longs, print_help, parse_option, settings_text, compute_settings};
    gtao_settings settings;
    find_preset(argc, argv, &settings.preset);
    if (gtao_preset(settings.preset, &settings.p) != 0)
        return cli_failf("--preset", "unknown preset '%s' (low, medium, high, ultra, reference)", settings.preset);
    return approx_main(&technique, &settings, argc, argv);
}
