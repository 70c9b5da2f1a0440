/* A subcommand's options as data: one table gives getopt its long options,
 * parses and range-checks each value into its destination, checks the
 * required ones, refuses stray arguments, and prints --help. A subcommand
 * then reads as what it computes:
 *
 *   long size = 32; const char *dir = NULL;
 *   static const cli_option opts[] = {
 *       CLI_INT("size", "N", 2, 256, "entries per axis (default 32)"),
 *       CLI_OUTPUT_DIR, CLI_END};
 *   const cli_command cmd = {"lut dfg", "Tabulates ...", opts};
 *   void *dest[] = {&size, &dir};
 *   int status; if (cli_options_parse(&cmd, dest, argc, argv, &status)) return status;
 *
 * The destinations are given in the table's order at the call, so the table
 * itself can be static. Defaults are the destinations' values before the
 * call, and --help prints them from there. */
#ifndef GTLAB_CLI_CLI_OPTIONS_H
#define GTLAB_CLI_CLI_OPTIONS_H

typedef enum {
    CLI_KIND_END,
    CLI_KIND_FLAG,   /* int: set to 1 */
    CLI_KIND_INT,    /* long, within [lo, hi] */
    CLI_KIND_DOUBLE, /* double, within [lo, hi] */
    CLI_KIND_STRING, /* const char * (the argv string itself) */
    CLI_KIND_CHOICE  /* int: the index i of the value equal to choice(i), 0 <= i < hi */
} cli_option_kind;

typedef struct {
    cli_option_kind kind;
    const char *name;  /* long name without "--" */
    char short_name;   /* 'o' for -o, or 0 */
    const char *value; /* the value's placeholder in the usage line ("N"), NULL for a flag */
    double lo, hi;
    const char *(*choice)(int index); /* CLI_KIND_CHOICE: the name of each value */
    int required;
    const char *help; /* may hold '\n': continuation lines are indented */
} cli_option;

#define CLI_FLAG(name, help) {CLI_KIND_FLAG, name, 0, NULL, 0, 0, NULL, 0, help}
#define CLI_INT(name, value, lo, hi, help) {CLI_KIND_INT, name, 0, value, lo, hi, NULL, 0, help}
#define CLI_DOUBLE(name, value, lo, hi, help) {CLI_KIND_DOUBLE, name, 0, value, lo, hi, NULL, 0, help}
#define CLI_STRING(name, value, help) {CLI_KIND_STRING, name, 0, value, 0, 0, NULL, 0, help}
#define CLI_REQUIRED_STRING(name, value, help) {CLI_KIND_STRING, name, 0, value, 0, 0, NULL, 1, help}
#define CLI_CHOICE(name, value, names, count, help) {CLI_KIND_CHOICE, name, 0, value, 0, count, names, 0, help}
#define CLI_THREADS CLI_INT("threads", "T", 1, 1024, "worker threads (default: all cores); the result does not depend on it")
#define CLI_OUTPUT_DIR {CLI_KIND_STRING, "output", 'o', "DIR", 0, 0, NULL, 1, "output folder (created if absent)"}
#define CLI_END {CLI_KIND_END, NULL, 0, NULL, 0, 0, NULL, 0, NULL}

typedef struct {
    const char *command;     /* "lut dfg": the words after "gtlab" */
    const char *description; /* the paragraph of --help */
    const cli_option *options;
} cli_command;

/* Parses argv (argv[0] is the subcommand) into dest[i] for options[i].
 * Returns 0 to go on; otherwise the subcommand returns *status: EXIT_OK
 * after --help, EXIT_USER_ERROR after a one-line error on stderr. */
int cli_options_parse(const cli_command *cmd, void *const *dest, int argc, char **argv, int *status);

/* Prints the --help text built from the table; each value option whose help
 * does not mention its default gets " (default X)" from *dest[i]. */
void cli_options_print_help(const cli_command *cmd, void *const *dest);

/* mkdir -p of one level: 0 if dir exists or was created, else a one-line
 * error naming it and EXIT_USER_ERROR. */
int cli_make_output_dir(const char *dir);

#endif
