/* gtlab fit PROBLEM: fit a technique's constants to references. A dispatcher: each
 * problem lives in cli/fit_<problem>.c. */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} fit_entry;

static const fit_entry problems[] = {
    {"aperture", fit_aperture, "GTSO gloss-to-aperture u by DSSIM against specular-occlusion references"},
};

static void print_help(FILE *out)
{
    fprintf(out, "usage: gtlab fit PROBLEM [options] -o fit.json     (gtlab fit PROBLEM --help for each)\n\nproblems:\n");
    for (size_t i = 0; i < sizeof problems / sizeof problems[0]; ++i)
        fprintf(out, "  %-20s %s\n", problems[i].name, problems[i].summary);
}

int verb_fit(int argc, char **argv)
{
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        print_help(argc < 2 ? stderr : stdout);
        return argc < 2 ? EXIT_USER_ERROR : EXIT_OK;
    }
    for (size_t i = 0; i < sizeof problems / sizeof problems[0]; ++i)
        if (strcmp(argv[1], problems[i].name) == 0) {
            cli_reset_getopt();
            return problems[i].run(argc - 1, argv + 1);
        }
    return cli_failf("fit", "unknown problem '%s' (see 'gtlab fit --help')", argv[1]);
}
