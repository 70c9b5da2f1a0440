/* gtlab approx TECHNIQUE: a real-time approximation on a G-buffer. One file
 * per technique (cli/approx_<name>.c); this holds only the table. */
#include "cli/cli.h"
#include "cli/subcommands.h"

static const cli_subcommand techniques[] = {
    {"gtao", approx_gtao, "ground-truth AO (Jimenez et al. 2016): cosine-weighted horizons, bent normals"},
    {"hbao", approx_hbao, "horizon-based AO (Bavoil et al. 2008): uniform weighting"},
    {"vo", approx_vo, "volumetric obscurance with 4 samples (Loos and Sloan 2010; CryENGINE 3)"},
    {"specular-occlusion", approx_specular_occlusion, "GTSO and the other specular-occlusion variants from AO + bent normal"},
};

int verb_approx(int argc, char **argv)
{
    const cli_subcommand_verb v = {"approx", "TECHNIQUE --gbuffer g.exr [options] -o out.exr", "techniques", "technique",
                                   techniques, sizeof techniques / sizeof techniques[0]};
    return cli_run_subcommand(&v, argc, argv);
}
