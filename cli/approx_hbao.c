/* gtlab approx hbao: horizon-based AO (realtime/hbao.c) on a G-buffer. */
#include <getopt.h>
#include <stdio.h>

#include "cli/approx_io.h"
#include "cli/cli.h"
#include "realtime/hbao.h"
#include "core/reference_schema.h"

static void print_help(void)
{
    printf("usage: gtlab approx hbao --gbuffer G.exr [options] -o out.exr\n"
           "\n"
           "Horizon-based AO (Bavoil et al. 2008): uniform weighting, per screen direction\n"
           "the occluded elevation from the surface tangent up to the horizon. Without\n"
           "attenuation it equals 'gtlab approx gtao --weighting uniform --falloff 0'.\n"
           "Writes ao.V (uniform AO).\n"
           "\n"
           "  --directions N        screen directions per pixel and frame (default 8)\n"
           "  --steps N             samples per direction, 1..256 (default 8); 0: exact\n"
           "  --radius R            world-space radius (default 1)\n"
           "  --max-radius-px P     clamp of the screen-space radius (default 256)\n"
           "  --attenuation on|off  Bavoil's per-sample W(r) = 1 - r^2/R^2 (default on)\n"
           APPROX_FRAMES_HELP
           "%s",
           approx_common_help);
}

static int compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? hbao_render(g, params, ao) : -1;
}

static int parse_option(int c, const char *arg, void *params)
{
    hbao_params *p = params;
    double v;
    long n;
    switch (c) {
    case 'd': return cli_parse_int("--directions", arg, 1, 4096, &n) ? -1 : (p->directions = (int)n, 0);
    case 'n': return cli_parse_int("--steps", arg, 0, 256, &n) ? -1 : (p->steps = (int)n, 0);
    case 'r': return cli_parse_double("--radius", arg, 1e-9, 1e30, &v) ? -1 : (p->radius = (float)v, 0);
    case 'm': return cli_parse_double("--max-radius-px", arg, 1, 4096, &v) ? -1 : (p->max_radius_px = (float)v, 0);
    case 'A': return approx_parse_switch("--attenuation", arg, &p->attenuation);
    case 'P': return approx_parse_switch("--pattern", arg, &p->pattern);
    case 'D': return approx_parse_switch("--denoise", arg, &p->denoise);
    case 'F': return cli_parse_int("--frames", arg, 1, 100000, &n) ? -1 : (p->frames = (int)n, 0);
    default: return cli_usage_error("approx hbao"), -1;
    }
}

static void settings_text(const void *params, char *text, size_t size) { hbao_params_text(params, text, size); }

int approx_hbao(int argc, char **argv)
{
    static const struct option longs[] = {
        {"directions", required_argument, 0, 'd'}, {"steps", required_argument, 0, 'n'},
        {"radius", required_argument, 0, 'r'},     {"max-radius-px", required_argument, 0, 'm'},
        {"attenuation", required_argument, 0, 'A'}, {"pattern", required_argument, 0, 'P'},
        {"denoise", required_argument, 0, 'D'},    {"frames", required_argument, 0, 'F'},
        APPROX_COMMON_OPTIONS};
    static const approx_technique technique = {"hbao", longs, print_help, parse_option, settings_text, compute};
    hbao_params p = {8, 8, 1.0f, 256.0f, 1, 1, 0, 1};
    return approx_main(&technique, &p, argc, argv);
}
