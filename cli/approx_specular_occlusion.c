/* gtlab approx specular-occlusion: every specular-occlusion variant of the
 * GTSO talk (cone/cone, cone/lobe LUT) and its baselines on a G-buffer and
 * an AO / bent-normal image (realtime/specular_occlusion_screen.h). */
#define _GNU_SOURCE
#include <getopt.h>
#include <omp.h>
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "core/exr_io.h"
#include "core/reference_schema.h"
#include "studies/specular_occlusion_inputs.h"

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

/* The output: specocc.V, mask.A, the camera and the variant in the header. */
static int write_output(const approx_options *o, const image *gbuffer, const so_pixel_inputs *in,
                        const so_variant *v, gt_error *e)
{
    image out;
    if (image_init(&out, in->width, in->height) != 0)
        return gt_error_set(e, o->output, "out of memory");
    float *vs = image_add_channel(&out, CH_SPECOCC), *mask = image_add_channel(&out, CH_MASK);
    char label[128];
    so_variant_label(v, label, sizeof label);
    int rc = vs && mask ? 0 : gt_error_set(e, o->output, "out of memory");
    if (rc == 0) {
        so_approx_evaluate(in, v, vs);
        memcpy(mask, in->mask, sizeof(float) * image_pixel_count(&out));
        rc = image_set_attribute(&out, ATTR_APPROX, label) |
             image_set_attribute(&out, ATTR_CAMERA, image_get_attribute(gbuffer, ATTR_CAMERA));
        rc = rc ? gt_error_set(e, o->output, "out of memory") : exr_write(o->output, &out, e);
    }
    image_free(&out);
    return rc;
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
    gt_error e;
    image gbuffer, ao;
    if (exr_read(o.gbuffer, &gbuffer, &e) != 0)
        return cli_fail(&e);
    if (o.roughness < 0.0)
        o.roughness = so_reference_roughness(&gbuffer);
    if (exr_read(o.ao, &ao, &e) != 0) {
        image_free(&gbuffer);
        return cli_fail(&e);
    }
    so_pixel_inputs in;
    so_lut lut = {0};
    int status = EXIT_OK;
    if (so_inputs_from_images(&gbuffer, o.gbuffer, &ao, o.ao, o.roughness, &in, &e) != 0) {
        status = cli_fail(&e);
    } else if (v.weighting == SO_AO_UNIFORM && !in.ao_uniform) {
        status = cli_failf(o.ao, "no ao.Vuniform channel, which --ao-weighting uniform needs");
        so_inputs_free(&in);
    } else {
        if (v.kind == SO_VARIANT_LUT && so_lut_build(&lut, (int)o.lut_size, o.lobe, SO_AXES_ANGLES, omp_get_num_procs()) != 0)
            status = cli_failf("approx specular-occlusion", "out of memory");
        v.lut = &lut;
        if (status == EXIT_OK && write_output(&o, &gbuffer, &in, &v, &e) != 0)
            status = cli_fail(&e);
        so_lut_free(&lut);
        so_inputs_free(&in);
    }
    image_free(&gbuffer);
    image_free(&ao);
    return status;
}
