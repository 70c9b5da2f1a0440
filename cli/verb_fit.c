/* gtlab fit PROBLEM: Ceres fits of a technique's constants to references.
 * One file per problem (cli/fit_<problem>.c); this holds only the table
 * and the dispatch. */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} fit_entry;

static const fit_entry problems[] = {
    {"sphere-light", fit_sphere_light, "Decima's sphere-light radius reduction and normalisation vs MC references"},
};

static void print_help(FILE *out)
{
    fprintf(out, "usage: gtlab fit PROBLEM [options] -o fit.json     (gtlab fit PROBLEM --help for each)\n\n"
                 "problems:\n");
    for (size_t i = 0; i < sizeof problems / sizeof problems[0]; ++i)
        fprintf(out, "  %-14s %s\n", problems[i].name, problems[i].summary);
}

int verb_fit(int argc, char **argv)
{
    if (argc < 2) {
        print_help(stderr);
        return EXIT_USER_ERROR;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        print_help(stdout);
        return EXIT_OK;
    }
    for (size_t i = 0; i < sizeof problems / sizeof problems[0]; ++i)
        if (strcmp(argv[1], problems[i].name) == 0)
            return problems[i].run(argc - 1, argv + 1);
    return cli_failf(argv[1], "unknown fit problem (see 'gtlab fit --help')");
}
