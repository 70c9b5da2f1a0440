/* gtlab lut NAME: a lookup table in every output format. One file per table
 * (cli/lut_<name>.c); this holds only the table of tables. */
#include "cli/cli.h"
#include "cli/subcommands.h"

static const cli_subcommand luts[] = {
    {"specular-occlusion", lut_specular_occlusion, "GTSO cone/lobe V_s(a_v, beta, r): EXR, 8-bit PNG, C header"},
};

int verb_lut(int argc, char **argv)
{
    const cli_subcommand_verb v = {"lut", "NAME [options] -o DIR", "tables", "table", luts, sizeof luts / sizeof luts[0]};
    return cli_run_subcommand(&v, argc, argv);
}
