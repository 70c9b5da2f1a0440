/* gtlab fit PROBLEM: a Ceres fit of one problem's model to references. This
 * file holds only the table of problems and the dispatch; each problem lives
 * in cli/fit_<problem>.c. */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} fit_problem;

static const fit_problem problems[] = {
    {"multibounce", fit_multibounce, "GTAO multi-bounce cubic (Jimenez et al. 2016) from multi-bounce references"},
};

static void print_help(FILE *out)
{
    fprintf(out, "usage: gtlab fit PROBLEM [options] -o fit.json   (gtlab fit PROBLEM --help for each)\n\n"
                 "Fits a real-time model's constants to references with Ceres; writes the values,\n"
                 "standard errors, covariance and residual statistics as JSON.\n\nproblems:\n");
    for (size_t i = 0; i < sizeof problems / sizeof problems[0]; ++i)
        fprintf(out, "  %-12s %s\n", problems[i].name, problems[i].summary);
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
    return cli_failf(argv[1], "unknown fit problem (see 'gtlab fit --help')");
}
