/* gtlab check NAME: accuracy checks of one piece of a technique against
 * brute force. One file per check (cli/check_<name>.c); this holds only
 * the table. */
#include "cli/cli.h"
#include "cli/subcommands.h"

static const cli_subcommand checks[] = {
    {"sphere-noh", check_sphere_noh, "GetNoHSquared (Karis, 1 and 2 Newton steps) against the brute-force max of (N.H)^2"},
};

int verb_check(int argc, char **argv)
{
    const cli_subcommand_verb v = {"check", "NAME [options]", "checks", "check", checks, sizeof checks / sizeof checks[0]};
    return cli_run_subcommand(&v, argc, argv);
}
