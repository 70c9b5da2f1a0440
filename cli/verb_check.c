/* gtlab check NAME: accuracy checks of one piece of a technique against
 * brute force.
 * The subcommands come from the technique registry (cli/techniques.c). */
#include "cli/cli.h"
#include "cli/technique.h"

int verb_check(int argc, char **argv)
{
    return technique_run_verb(VERB_CHECK, "check", "NAME [options]", "checks", "check", argc, argv);
}
