/* gtlab check NAME: accuracy checks of one piece of a technique against
 * brute force. One file per check (cli/check_<name>.c); this holds only
 * the table and the dispatch. */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} check_entry;

static const check_entry checks[] = {
    {"sphere-noh", check_sphere_noh, "GetNoHSquared (Karis, 1 and 2 Newton steps) against the brute-force max of (N.H)^2"},
};

static void print_help(FILE *out)
{
    fprintf(out, "usage: gtlab check NAME [options]     (gtlab check NAME --help for each)\n\nchecks:\n");
    for (size_t i = 0; i < sizeof checks / sizeof checks[0]; ++i)
        fprintf(out, "  %-12s %s\n", checks[i].name, checks[i].summary);
}

int verb_check(int argc, char **argv)
{
    if (argc < 2) {
        print_help(stderr);
        return EXIT_USER_ERROR;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        print_help(stdout);
        return EXIT_OK;
    }
    for (size_t i = 0; i < sizeof checks / sizeof checks[0]; ++i)
        if (strcmp(argv[1], checks[i].name) == 0)
            return checks[i].run(argc - 1, argv + 1);
    return cli_failf(argv[1], "unknown check (see 'gtlab check --help')");
}
