/* gtlab approx vo: volumetric obscurance with 4 samples
 * (realtime/volumetric_obscurance.c) on a G-buffer. */
#include <getopt.h>
#include <stdio.h>

#include "cli/approx_io.h"
#include "cli/cli.h"
#include "realtime/volumetric_obscurance.h"
#include "core/reference_schema.h"

static void print_help(void)
{
    printf("usage: gtlab approx vo --gbuffer G.exr [options] -o out.exr\n"
           "\n"
           "Volumetric obscurance (Loos and Sloan 2010) with CryENGINE 3's 4 samples\n"
           "(Kaplanyan, SIGGRAPH 2010): the fraction of a sphere about the surface point\n"
           "behind the depth buffer, from 4 line integrals; ao.V = min(1, 2 (1 - fraction)),\n"
           "1 on a plane. Depth only.\n"
           "\n"
           "  --radius R            world-space sphere radius (default 1)\n"
           "  --max-radius-px P     clamp of its screen-space radius (default 256)\n"
           "  --pattern on|off      rotate the samples by the GTAO talk's 4x4 pattern (default on)\n"
           "  --denoise on|off      the 4x4 bilateral spatial denoiser (default on)\n"
           "  --frames N            frames accumulated (static camera; default 1)\n"
           "%s",
           approx_common_help);
}

static int compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? vo_render(g, params, ao) : -1;
}

static int parse_option(int c, const char *arg, void *params)
{
    vo_params *p = params;
    double v;
    long n;
    switch (c) {
    case 'r': return cli_parse_double("--radius", arg, 1e-9, 1e30, &v) ? -1 : (p->radius = (float)v, 0);
    case 'm': return cli_parse_double("--max-radius-px", arg, 1, 4096, &v) ? -1 : (p->max_radius_px = (float)v, 0);
    case 'P': return approx_parse_switch("--pattern", arg, &p->pattern);
    case 'D': return approx_parse_switch("--denoise", arg, &p->denoise);
    case 'F': return cli_parse_int("--frames", arg, 1, 100000, &n) ? -1 : (p->frames = (int)n, 0);
    default: return cli_usage_error("approx vo"), -1;
    }
}

static void settings_text(const void *params, char *text, size_t size) { vo_params_text(params, text, size); }

int approx_vo(int argc, char **argv)
{
    static const struct option longs[] = {
        {"radius", required_argument, 0, 'r'},  {"max-radius-px", required_argument, 0, 'm'},
        {"pattern", required_argument, 0, 'P'}, {"denoise", required_argument, 0, 'D'},
        {"frames", required_argument, 0, 'F'},  APPROX_COMMON_OPTIONS};
    static const approx_technique technique = {"vo", longs, print_help, parse_option, settings_text, compute};
    vo_params p = {1.0f, 256.0f, 1, 1, 1};
    return approx_main(&technique, &p, argc, argv);
}
