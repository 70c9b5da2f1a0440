/* gtlab approx specular-occlusion: every specular-occlusion variant of the
 * GTSO talk (cone/cone, cone/lobe LUT) and its baselines on a G-buffer and
 * an AO / bent-normal image (realtime/specular_occlusion_screen.h), from files
 * to file by studies/specular_occlusion_approx.h. */
#define _GNU_SOURCE
#include <getopt.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "studies/specular_occlusion_approx.h"
#include "core/threads.h"

static void print_help(void)
{
    printf("usage: gtlab approx specular-occlusion --gbuffer g.exr --ao ao.exr [options] -o out.exr\n"
           "\n"
           "Specular occlusion V_s from what a real-time renderer has: the G-buffer (N.*, P.*,\n"
           "roughness.Y, mask.A and the camera in the header: any gtlab reference file) and the\n"
           "AO and bent normal (ao.V, ao.Vuniform, bent.*: 'gtlab render ao'). Writes specocc.V\n"
           "and mask.A, so 'gtlab compare ref.exr out.exr --channel specocc.V' scores it.\n"
           "\n"
           "options:\n"
           "  --gbuffer F.exr     G-buffer channels and camera\n"
           "  --ao F.exr          ao.V, bent.X/Y/Z and ao.Vuniform (may be the same file; a\n"
           "                    'gtlab approx gtao' output serves the cosine weighting)\n"
           "  --variant V         lut (GTSO cone/lobe, default), ao (AO as specular occlusion),\n"
           "                      lagarde (Lagarde 2014), cone-exact:M or cone-oat:M (cone/cone\n"
           "                      with the exact cap intersection or Oat 2007's), M the\n"
           "                      reflection-cone mapping: drobot, uludag, phong-u (with --u),\n"
           "                      exp2-alpha (2^(-3.32193 alpha^2)), exp2-perceptual\n"
           "                      (2^(-3.32193 r^2), r perceptual)\n"
           "  --u U               phong-u's parameter in (0, 1) (default 0.01, the talk's)\n"
           "  --ao-weighting W    cosine (ao.V, cos a_v = sqrt(1 - V); default) or uniform\n"
           "                      (ao.Vuniform, cos a_v = 1 - V)\n"
           "  --roughness R       perceptual roughness for every pixel (default: the --gbuffer\n"
           "                      reference's --roughness if it had one, else roughness.Y)\n"
           "  --lut-size N        lut: table size (default 32), built on the fly\n"
           "  --lobe L            lut: ggx (default), ggx-d or phong\n"
           "  -o, --output F.exr  output\n"
           "  -h, --help\n");
}

typedef struct {
    const char *gbuffer, *ao, *output, *variant;
    double u, roughness;
    so_ao_weighting weighting;
    long lut_size;
    so_lobe lobe;
} approx_options;

static int parse_options(int argc, char **argv, approx_options *o)
{
    static const struct option longs[] = {
        {"gbuffer", required_argument, 0, 'g'},  {"ao", required_argument, 0, 'a'},
        {"variant", required_argument, 0, 'v'},  {"u", required_argument, 0, 'u'},
        {"ao-weighting", required_argument, 0, 'w'}, {"roughness", required_argument, 0, 'r'},
        {"lut-size", required_argument, 0, 'n'}, {"lobe", required_argument, 0, 'l'},
        {"output", required_argument, 0, 'o'},   {"help", no_argument, 0, 'h'}, {0, 0, 0, 0}};
    int c;
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        switch (c) {
        case 'g': o->gbuffer = optarg; break;
        case 'a': o->ao = optarg; break;
        case 'v': o->variant = optarg; break;
        case 'o': o->output = optarg; break;
        case 'u': if (cli_parse_double("--u", optarg, 1e-12, 1.0 - 1e-12, &o->u)) return -1; break;
        case 'r': if (cli_parse_double("--roughness", optarg, 0.0, 1.0, &o->roughness)) return -1; break;
        case 'n': if (cli_parse_int("--lut-size", optarg, 2, 256, &o->lut_size)) return -1; break;
        case 'w':
            if (strcmp(optarg, "cosine") == 0)
                o->weighting = SO_AO_COSINE;
            else if (strcmp(optarg, "uniform") == 0)
                o->weighting = SO_AO_UNIFORM;
            else
                return cli_failf("--ao-weighting", "'%s' is neither cosine nor uniform", optarg), -1;
            break;
        case 'l': {
            int found = 0;
            for (int i = 0; i < SO_LOBE_COUNT; ++i)
                if (strcmp(optarg, so_lobe_name((so_lobe)i)) == 0)
                    o->lobe = (so_lobe)i, found = 1;
            if (!found)
                return cli_failf("--lobe", "unknown lobe '%s' (ggx, ggx-d or phong)", optarg), -1;
            break;
        }
        case 'h': print_help(); return 1;
        default: return cli_usage_error("approx specular-occlusion"), -1;
        }
    }
    if (optind < argc)
        return cli_failf("approx specular-occlusion", "unexpected argument '%s'", argv[optind]), -1;
    if (!o->gbuffer || !o->ao || !o->output)
        return cli_failf("approx specular-occlusion", "--gbuffer, --ao and -o/--output are required"), -1;
    return 0;
}

int approx_specular_occlusion(int argc, char **argv)
{
    approx_options o = {NULL, NULL, NULL, "lut", 0.01, -1.0, SO_AO_COSINE, 32, SO_LOBE_GGX};
    int parsed = parse_options(argc, argv, &o);
    if (parsed != 0)
        return parsed > 0 ? EXIT_OK : EXIT_USER_ERROR;
    so_variant v;
    if (so_variant_parse(o.variant, &v) != 0)
        return cli_failf("--variant", "unknown variant '%s' (see --help)", o.variant);
    v.u = o.u, v.weighting = o.weighting;
    so_approx_files files = {o.gbuffer, o.ao, o.output, o.roughness, (int)o.lut_size, o.lobe, threads_default()};
    gt_error e;
    return so_approx_from_files(&files, &v, &e) != 0 ? cli_fail(&e) : EXIT_OK;
}
