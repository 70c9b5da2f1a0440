/* gtlab approx specular-occlusion: every specular-occlusion variant of the
 * GTSO talk (cone/cone, cone/lobe LUT) and its baselines on a G-buffer and
 * an AO / bent-normal image (realtime/specular_occlusion_screen.h), from files
 * to file by studies/specular_occlusion_approx.h. */
#include "cli/cli.h"
#include "cli/cli_options.h"
#include "core/threads.h"
#include "studies/specular_occlusion_approx.h"

static const char *weighting_name(int i) { return i == SO_AO_UNIFORM ? "uniform" : "cosine"; }
static const char *lobe_name(int i) { return so_lobe_name((so_lobe)i); }

static const cli_option options[] = {
    CLI_REQUIRED_STRING("gbuffer", "F.exr", "G-buffer channels and camera"),
    CLI_REQUIRED_STRING("ao", "F.exr", "ao.V, bent.X/Y/Z and ao.Vuniform (may be the same file; a\n"
                        "'gtlab approx gtao' output serves the cosine weighting)"),
    CLI_STRING("variant", "V", "lut (GTSO cone/lobe), ao (AO as specular occlusion),\n"
               "lagarde (Lagarde 2014), cone-exact:M or cone-oat:M (cone/cone\n"
               "with the exact cap intersection or Oat 2007's), M the\n"
               "reflection-cone mapping: drobot, uludag, phong-u (with --u),\n"
               "exp2-alpha (2^(-3.32193 alpha^2)), exp2-perceptual\n(2^(-3.32193 r^2), r perceptual)"),
    CLI_DOUBLE("u", "U", 1e-12, 1.0 - 1e-12, "phong-u's parameter in (0, 1); the talk's 0.01"),
    CLI_CHOICE("ao-weighting", "W", weighting_name, 2, "cosine (ao.V, cos a_v = sqrt(1 - V)) or uniform\n"
               "(ao.Vuniform, cos a_v = 1 - V)"),
    CLI_DOUBLE("roughness", "R", 0.0, 1.0, "perceptual roughness for every pixel (default: the --gbuffer\n"
               "reference's --roughness if it had one, else roughness.Y)"),
    CLI_INT("lut-size", "N", 2, 256, "lut: table size, built on the fly"),
    CLI_CHOICE("lobe", "L", lobe_name, SO_LOBE_COUNT, "lut: ggx, ggx-d or phong"),
    CLI_OUTPUT("F.exr", 1, "output"), CLI_END};
static const cli_command command = {
    "approx specular-occlusion",
    "Specular occlusion V_s from what a real-time renderer has: the G-buffer (N.*, P.*,\n"
    "roughness.Y, mask.A and the camera in the header: any gtlab reference file) and the\n"
    "AO and bent normal (ao.V, ao.Vuniform, bent.*: 'gtlab render ao'). Writes specocc.V\n"
    "and mask.A, so 'gtlab compare ref.exr out.exr --channel specocc.V' scores it.",
    options, NULL, NULL};

int approx_specular_occlusion(int argc, char **argv)
{
    const char *gbuffer = NULL, *ao = NULL, *output = NULL, *variant = "lut";
    double u = 0.01, roughness = -1.0;
    int weighting = SO_AO_COSINE, lobe = SO_LOBE_GGX, status;
    long lut_size = 32;
    if (cli_options_parse(&command, (void *[]){&gbuffer, &ao, &variant, &u, &weighting, &roughness, &lut_size, &lobe,
                          &output}, argc, argv, &status) != 0)
        return status;
    so_variant v;
    if (so_variant_parse(variant, &v) != 0)
        return cli_failf("--variant", "unknown variant '%s' (see --help)", variant);
    v.u = u, v.weighting = (so_ao_weighting)weighting;
    so_approx_files files = {gbuffer, ao, output, roughness, (int)lut_size, (so_lobe)lobe, threads_default()};
    gt_error e;
    return so_approx_from_files(&files, &v, &e) != 0 ? cli_fail(&e) : EXIT_OK;
}
