/* Verbs whose first argument names what they act on (`gtlab fit PROBLEM`,
 * `gtlab check NAME`, `gtlab approx TECHNIQUE`, `gtlab lut NAME`): each
 * keeps a table of subcommands, one file per subcommand, and dispatches
 * through here so every such verb lists, helps and fails the same way. */
#ifndef GTLAB_CLI_SUBCOMMANDS_H
#define GTLAB_CLI_SUBCOMMANDS_H

#include <stddef.h>

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv); /* argv[0] is the subcommand's name */
    const char *summary;
} cli_subcommand;

typedef struct {
    const char *verb;  /* "fit" */
    const char *usage; /* "PROBLEM [options] -o fit.json" */
    const char *kind;  /* "problems": the heading of the list in --help */
    const char *noun;  /* "fit problem": what an unknown name is not */
    const cli_subcommand *table;
    size_t count;
    /* The name now of what went by `former` before, or NULL (told only when it is
     * one of this verb's subcommands); NULL: none renamed. */
    const char *(*renamed)(const char *former);
} cli_subcommand_verb;

/* Runs the subcommand named by argv[1] with argv + 1; with no argument
 * prints the list on stderr (exit 1); with --help on stdout (exit 0). */
int cli_run_subcommand(const cli_subcommand_verb *v, int argc, char **argv);

#endif
