/* gtlab lut NAME: a lookup table in every output format.
 * The subcommands come from the technique registry (cli/techniques.c). */
#include "cli/cli.h"
#include "cli/technique.h"

int verb_lut(int argc, char **argv)
{
    return technique_run_verb(VERB_LUT, "lut", "NAME [options] -o DIR", "tables", "table", argc, argv);
}
