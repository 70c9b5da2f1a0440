/* gtlab approx alchemy and gtlab approx crytek: the screen-space AO
 * baselines the GTAO talk names, Alchemy ambient obscurance
 * (realtime/alchemy_ao.c) and CryENGINE 2's SSAO (realtime/crytek_ssao.c),
 * on a G-buffer. */
#include <getopt.h>
#include <stdio.h>

#include "cli/approx_io.h"
#include "cli/cli.h"
#include "core/reference_schema.h"
#include "realtime/alchemy_ao.h"
#include "realtime/crytek_ssao.h"

static void alchemy_help(void)
{
    printf("usage: gtlab approx alchemy --gbuffer G.exr [options] -o out.exr\n"
           "\n"
           "Alchemy ambient obscurance (McGuire et al. 2011): from s points on a spiral\n"
           "over the screen disc of the radius, A = max(0, 1 - 2 sigma / s sum_i\n"
           "max(0, v_i.n + z_C beta) / (v_i.v_i + epsilon))^k. Writes ao.V (= A).\n"
           "\n"
           "  --samples N           s (default 12)\n"
           "  --radius R            world-space radius (default 1)\n"
           "  --max-radius-px P     clamp of its screen-space radius (default 256)\n"
           "  --sigma S             intensity (default 1)\n"
           "  --contrast K          k (default 1)\n"
           "  --beta B              bias distance per unit depth (default 1e-4)\n"
           APPROX_FRAMES_HELP
           "%s",
           approx_common_help);
}

static int alchemy_compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? alchemy_render(g, params, ao) : -1;
}

static int alchemy_parse(int c, const char *arg, void *params)
{
    alchemy_params *p = params;
    double v;
    long n;
    switch (c) {
    case 's': return cli_parse_int("--samples", arg, 1, 1024, &n) ? -1 : (p->samples = (int)n, 0);
    case 'r': return cli_parse_double("--radius", arg, 1e-9, 1e30, &v) ? -1 : (p->radius = (float)v, 0);
    case 'm': return cli_parse_double("--max-radius-px", arg, 1, 4096, &v) ? -1 : (p->max_radius_px = (float)v, 0);
    case 'S': return cli_parse_double("--sigma", arg, 0, 1e6, &v) ? -1 : (p->sigma = (float)v, 0);
    case 'K': return cli_parse_double("--contrast", arg, 1e-3, 1e3, &v) ? -1 : (p->contrast = (float)v, 0);
    case 'B': return cli_parse_double("--beta", arg, 0, 1, &v) ? -1 : (p->beta = (float)v, 0);
    case 'P': return approx_parse_switch("--pattern", arg, &p->pattern);
    case 'D': return approx_parse_switch("--denoise", arg, &p->denoise);
    case 'F': return cli_parse_int("--frames", arg, 1, 100000, &n) ? -1 : (p->frames = (int)n, 0);
    default: return cli_usage_error("approx alchemy"), -1;
    }
}

static void alchemy_text(const void *params, char *text, size_t size) { alchemy_params_text(params, text, size); }

int approx_alchemy(int argc, char **argv)
{
    static const struct option longs[] = {
        {"samples", required_argument, 0, 's'}, {"radius", required_argument, 0, 'r'},
        {"max-radius-px", required_argument, 0, 'm'}, {"sigma", required_argument, 0, 'S'},
        {"contrast", required_argument, 0, 'K'}, {"beta", required_argument, 0, 'B'},
        {"pattern", required_argument, 0, 'P'}, {"denoise", required_argument, 0, 'D'},
        {"frames", required_argument, 0, 'F'},  APPROX_COMMON_OPTIONS};
    static const approx_technique t = {"alchemy", longs, alchemy_help, alchemy_parse, alchemy_text, alchemy_compute};
    alchemy_params p = alchemy_default_params(1.0f);
    return approx_main(&t, &p, argc, argv);
}

static void crytek_help(void)
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
           APPROX_FRAMES_HELP
           "%s",
           CRYTEK_MAX_SAMPLES, approx_common_help);
}

static int crytek_compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? crytek_render(g, params, ao) : -1;
}

static int crytek_parse(int c, const char *arg, void *params)
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

static void crytek_text(const void *params, char *text, size_t size) { crytek_params_text(params, text, size); }

int approx_crytek(int argc, char **argv)
{
    static const struct option longs[] = {
        {"samples", required_argument, 0, 's'}, {"radius", required_argument, 0, 'r'},
        {"pattern", required_argument, 0, 'P'}, {"denoise", required_argument, 0, 'D'},
        {"frames", required_argument, 0, 'F'},  APPROX_COMMON_OPTIONS};
    static const approx_technique t = {"crytek", longs, crytek_help, crytek_parse, crytek_text, crytek_compute};
    crytek_params p = {16, 1.0f, 1, 0, 1};
    return approx_main(&t, &p, argc, argv);
}
