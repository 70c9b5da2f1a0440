#include "cli/subcommands.h"

#include <stdio.h>
#include <string.h>

#include "cli/cli.h"

static void print_list(const cli_subcommand_verb *v, FILE *out)
{
    fprintf(out, "usage: gtlab %s %s     (gtlab %s NAME --help for each)\n\n%s:\n", v->verb, v->usage, v->verb,
            v->kind);
    for (size_t i = 0; i < v->count; ++i)
        fprintf(out, "  %-20s %s\n", v->table[i].name, v->table[i].summary);
}

int cli_run_subcommand(const cli_subcommand_verb *v, int argc, char **argv)
{
    if (argc < 2) {
        print_list(v, stderr);
        return EXIT_USER_ERROR;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        print_list(v, stdout);
        return EXIT_OK;
    }
    for (size_t i = 0; i < v->count; ++i)
        if (strcmp(argv[1], v->table[i].name) == 0) {
            cli_reset_getopt();
            return v->table[i].run(argc - 1, argv + 1);
        }
    fprintf(stderr, "gtlab: %s: unknown %s (see 'gtlab %s --help')\n", argv[1], v->noun, v->verb);
    return EXIT_USER_ERROR;
}
