/* gtlab approx crytek: CryENGINE 2's SSAO (realtime/crytek_ssao.c) on a
 * G-buffer. */
#include <getopt.h>
#include <stdio.h>

#include "cli/approx_io.h"
#include "cli/cli.h"
#include "core/reference_schema.h"
#include "realtime/crytek_ssao.h"

static void print_help(void)
{
    printf("usage: gtlab approx crytek --gbuffer G.exr [options] -o out.exr\n"
           "\n"
           "Screen-space AO as in CryENGINE 2 (Mittring 2007): N points in a sphere about\n"
           "the surface point, each occluded when the depth buffer lies in front of it by\n"
           "less than the radius; ao.V = min(1, 2 (1 - occluded fraction)), 1 on a plane.\n"
           "Depth only.\n"
           "\n"
           "  --samples N           points, even, 2..%d (default 16)\n"
           "  --radius R            world-space sphere radius (default 1)\n"
           "  --pattern on|off      rotate the points by the GTAO talk's 4x4 pattern (default on)\n"
           "  --denoise on|off      the 4x4 bilateral spatial denoiser (default off)\n"
           "  --frames N            frames accumulated (static camera; default 1)\n"
           "%s",
           CRYTEK_MAX_SAMPLES, approx_common_help);
}

static int compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? crytek_render(g, params, ao) : -1;
}

static int parse_option(int c, const char *arg, void *params)
{
    crytek_params *p = params;
    double v;
    long n;
    switch (c) {
    case 's':
        if (cli_parse_int("--samples", arg, 2, CRYTEK_MAX_SAMPLES, &n) != 0)
            return -1;
        if (n % 2 != 0)
            return cli_failf("--samples", "'%s' is odd: the points come in opposite pairs", arg), -1;
        p->samples = (int)n;
        return 0;
    case 'r': return cli_parse_double("--radius", arg, 1e-9, 1e30, &v) ? -1 : (p->radius = (float)v, 0);
    case 'P': return approx_parse_switch("--pattern", arg, &p->pattern);
    case 'D': return approx_parse_switch("--denoise", arg, &p->denoise);
    case 'F': return cli_parse_int("--frames", arg, 1, 100000, &n) ? -1 : (p->frames = (int)n, 0);
    default: return cli_usage_error("approx crytek"), -1;
    }
}

static void settings_text(const void *params, char *text, size_t size) { crytek_params_text(params, text, size); }

int approx_crytek(int argc, char **argv)
{
    static const struct option longs[] = {
        {"samples", required_argument, 0, 's'}, {"radius", required_argument, 0, 'r'},
        {"pattern", required_argument, 0, 'P'}, {"denoise", required_argument, 0, 'D'},
        {"frames", required_argument, 0, 'F'},  APPROX_COMMON_OPTIONS};
    static const approx_technique technique = {"crytek", longs, print_help, parse_option, settings_text, compute};
    crytek_params p = {16, 1.0f, 1, 0, 1};
    return approx_main(&technique, &p, argc, argv);
}
