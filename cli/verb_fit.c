/* gtlab fit PROBLEM: fits of a technique's constants to references (Ceres,
 * or a bracketing search where the error is not smooth).
 * One file per problem (cli/fit_<problem>.c); this holds only the table. */
#include "cli/cli.h"
#include "cli/subcommands.h"

static const cli_subcommand problems[] = {
    {"multibounce", fit_multibounce, "GTAO multi-bounce cubic (per albedo and joint in rho) vs multibounce renders"},
    {"sphere-light", fit_sphere_light, "Decima's sphere-light radius reduction and normalisation vs MC references"},
    {"gtao-params", fit_gtao_params, "GTAO radius, falloff and thickness against 3-D AO references"},
    {"aperture", fit_aperture, "GTSO gloss-to-aperture u by DSSIM against specular-occlusion references"},
};

int verb_fit(int argc, char **argv)
{
    const cli_subcommand_verb v = {"fit", "PROBLEM [options] -o fit.json", "problems", "fit problem", problems,
                                   sizeof problems / sizeof problems[0]};
    return cli_run_subcommand(&v, argc, argv);
}
