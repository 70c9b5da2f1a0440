/* gtlab fit PROBLEM: a Ceres fit. This file holds only the table of
 * problems and the dispatch; each problem lives in cli/fit_<problem>.c. */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} fit_problem;

static const fit_problem problems[] = {
    {"gtao-params", fit_gtao_params, "GTAO radius, falloff and thickness against 3-D AO references"},
};

static void print_help(FILE *out)
{
    fprintf(out, "usage: gtlab fit PROBLEM [options] -o fit.json\n\nProblems:\n");
    for (size_t i = 0; i < sizeof problems / sizeof problems[0]; ++i)
        fprintf(out, "  %-12s %s\n", problems[i].name, problems[i].summary);
    fprintf(out, "\n'gtlab fit PROBLEM --help' lists each problem's options.\n");
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
        if (strcmp(argv[1], problems[i].name) == 0) {
            cli_reset_getopt();
            return problems[i].run(argc - 1, argv + 1);
        }
    return cli_failf(argv[1], "unknown problem (see 'gtlab fit --help')");
}
