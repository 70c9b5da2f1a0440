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

/* The index in v's table of the subcommand `name`, or -1. */
static int subcommand_index(const cli_subcommand_verb *v, const char *name)
{
    for (size_t i = 0; i < v->count; ++i)
        if (strcmp(name, v->table[i].name) == 0)
            return (int)i;
    return -1;
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
    int at = subcommand_index(v, argv[1]);
    if (at >= 0) {
        cli_reset_getopt();
        return v->table[at].run(argc - 1, argv + 1);
    }
    const char *now = v->renamed ? v->renamed(argv[1]) : NULL;
    if (now && subcommand_index(v, now) >= 0) {
        fprintf(stderr, "gtlab: %s %s: '%s' is now '%s' (gtlab %s %s)\n", v->verb, argv[1], argv[1], now, v->verb, now);
        return EXIT_USER_ERROR;
    }
    fprintf(stderr, "gtlab: %s: unknown %s (see 'gtlab %s --help')\n", argv[1], v->noun, v->verb);
    return EXIT_USER_ERROR;
}
