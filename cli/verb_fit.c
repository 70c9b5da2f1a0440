/* gtlab fit PROBLEM: fits of a technique's constants to references (Ceres,
 * or a bracketing search where the error is not smooth).
 * The subcommands come from the technique registry (cli/techniques.c). */
#include "cli/cli.h"
#include "cli/technique.h"

int verb_fit(int argc, char **argv)
{
    return technique_run_verb(VERB_FIT, "fit", "PROBLEM [options] -o fit.json", "problems", "fit problem", argc, argv);
}
