/* gtlab approx TECHNIQUE: a real-time approximation on a G-buffer.
 * The subcommands come from the technique registry (cli/techniques.c):
 * each technique's face (e.g. techniques/gtao/gtao_cli.c) through
 * cli/approx_io.h. */
#include "cli/cli.h"
#include "cli/technique.h"

int verb_approx(int argc, char **argv)
{
    return technique_run_verb(VERB_APPROX, "approx", "TECHNIQUE --gbuffer g.exr [options] -o out.exr", "techniques", "technique", argc, argv);
}
