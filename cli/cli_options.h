/* A subcommand's options as data: one table gives getopt its long options,
 * parses and range-checks each value into its destination, checks the
 * required ones, refuses stray arguments, and prints --help. A subcommand
 * then reads as what it computes:
 *
 *   long size = 32; const char *dir = NULL;
 *   static const cli_option opts[] = {
 *       CLI_INT("size", "N", 2, 256, "entries per axis (default 32)"),
 *       CLI_OUTPUT_DIR, CLI_END};
 *   const cli_command cmd = {"lut dfg", "Tabulates ...", opts, NULL, NULL};
 *   void *dest[] = {&size, &dir};
 *   int status; if (cli_options_parse(&cmd, dest, argc, argv, &status)) return status;
 *
 * The destinations are given in the table's order at the call, so the table
 * itself can be static. Defaults are the destinations' values before the
 * call, and --help prints them from there. Values a kind does not cover
 * ("N|inf", a list of albedos) take a CLI_CUSTOM parser; an option given
 * several times collects into a cli_list; positional arguments come back
 * in a cli_arguments after the options' destinations. */
#ifndef GTLAB_CLI_CLI_OPTIONS_H
#define GTLAB_CLI_CLI_OPTIONS_H

typedef enum {
    CLI_KIND_END,
    CLI_KIND_FLAG,   /* int: set to 1 */
    CLI_KIND_INT,    /* long, within [lo, hi] */
    CLI_KIND_INT32,  /* int, within [lo, hi] */
    CLI_KIND_DOUBLE, /* double, within [lo, hi] */
    CLI_KIND_FLOAT,  /* float, within [lo, hi] (parsed as a double, then rounded) */
    CLI_KIND_STRING, /* const char * (the argv string itself) */
    CLI_KIND_CHOICE, /* int: the index i of the value equal to choice(i), 0 <= i < hi */
    CLI_KIND_SWITCH, /* int: "on" 1, "off" 0 */
    CLI_KIND_CUSTOM  /* parse(dest, text) */
} cli_option_kind;

typedef struct {
    cli_option_kind kind;
    const char *name;  /* long name without "--" */
    char short_name;   /* 'o' for -o, or 0 */
    const char *value; /* the value's placeholder in the usage line ("N"), NULL for a flag */
    double lo, hi;
    const char *(*choice)(int index); /* CLI_KIND_CHOICE: the name of each value */
    int required;
    /* A file (or folder) the command writes: its value is no input, and
     * must not be one of the run's inputs (core/files/run_inputs.h). Every other
     * value, and every positional argument, that names an existing file is
     * noted as an input. */
    int writes;
    const char *help; /* may hold '\n': continuation lines are indented */
    /* CLI_KIND_CUSTOM: stores text's value in dest, or prints one line
     * ("gtlab: --option: problem") and returns -1. */
    int (*parse)(void *dest, const char *text);
} cli_option;

#define CLI_OPTION(k, n, v, l, h, text) {.kind = k, .name = n, .value = v, .lo = l, .hi = h, .help = text}
#define CLI_FLAG(n, text) CLI_OPTION(CLI_KIND_FLAG, n, NULL, 0, 0, text)
#define CLI_INT(n, v, l, h, text) CLI_OPTION(CLI_KIND_INT, n, v, l, h, text)
#define CLI_INT32(n, v, l, h, text) CLI_OPTION(CLI_KIND_INT32, n, v, l, h, text)
#define CLI_DOUBLE(n, v, l, h, text) CLI_OPTION(CLI_KIND_DOUBLE, n, v, l, h, text)
#define CLI_FLOAT(n, v, l, h, text) CLI_OPTION(CLI_KIND_FLOAT, n, v, l, h, text)
#define CLI_SEED(n, text) CLI_INT(n, "S", 0, 4294967295.0, text) /* a uint32_t, into a long */
#define CLI_STRING(n, v, text) CLI_OPTION(CLI_KIND_STRING, n, v, 0, 0, text)
#define CLI_REQUIRED_STRING(n, v, text) {.kind = CLI_KIND_STRING, .name = n, .value = v, .required = 1, .help = text}
#define CLI_CHOICE(n, v, names, count, text) {.kind = CLI_KIND_CHOICE, .name = n, .value = v, .hi = count, .choice = names, .help = text}
#define CLI_SWITCH(n, text) CLI_OPTION(CLI_KIND_SWITCH, n, "on|off", 0, 0, text)
#define CLI_CUSTOM(n, v, parser, text) {.kind = CLI_KIND_CUSTOM, .name = n, .value = v, .parse = parser, .help = text}
/* -o/--output: required (the table checks it) or not (the subcommand does). */
#define CLI_OUTPUT(v, is_required, text) {.kind = CLI_KIND_STRING, .name = "output", .short_name = 'o', .value = v, .required = is_required, .writes = 1, .help = text}
/* Another file the command writes (--heatmap F.png, --header F.h). */
#define CLI_OUTPUT_FILE(n, v, text) {.kind = CLI_KIND_STRING, .name = n, .value = v, .writes = 1, .help = text}
#define CLI_THREADS CLI_INT("threads", "T", 1, 1024, "worker threads (default: all cores); the result does not depend on it")
#define CLI_OUTPUT_DIR CLI_OUTPUT("DIR", 1, "output folder (created if absent)")
/* A throughput benchmark's view and passes (`gtlab bench rays`, `bench
 * specular-occlusion`): --scene, --width, --height, --threads, --repeats. */
#define CLI_BENCH_VIEW                                                                                       \
    CLI_STRING("scene", "S", "builtin:NAME or a glTF file"), CLI_INT("width", "W", 16, 8192, "image width"), \
        CLI_INT("height", "H", 16, 8192, "image height"),                                                    \
        CLI_INT("threads", "T", 1, 1024, "threads for the parallel figures (default: all cores)"),          \
        CLI_INT("repeats", "R", 1, 100, "passes per figure")
#define CLI_END {.kind = CLI_KIND_END}

typedef struct {
    const char *command;     /* "lut dfg": the words after "gtlab" */
    const char *description; /* the paragraph of --help */
    const cli_option *options;
    /* The placeholder of positional arguments in the usage line ("A.exr B.exr"),
     * or NULL when the subcommand takes none (a stray one is then an error). */
    const char *arguments;
    const char *epilogue; /* printed after the options (examples), or NULL */
} cli_command;

/* The positional arguments, when cli_command.arguments is set: its
 * destination follows the options' in dest. */
typedef struct {
    char **values;
    int count;
} cli_arguments;

/* The values of a repeatable option (a CLI_CUSTOM with cli_list_add). */
typedef struct {
    const char **values;
    int count, capacity;
    const char *option; /* "--data", for the error past capacity */
} cli_list;
int cli_list_add(void *list, const char *text);

/* Parses argv (argv[0] is the subcommand) into dest[i] for options[i]
 * (then the cli_arguments, if the command takes positional arguments).
 * Returns 0 to go on; otherwise the subcommand returns *status: EXIT_OK
 * after --help, EXIT_USER_ERROR after a one-line error on stderr. Every
 * value naming an existing file, but those of outputs (`writes`), and every
 * positional argument is noted as an input of the run (core/files/run_inputs.h);
 * an output that is one of them is then refused. */
int cli_options_parse(const cli_command *cmd, void *const *dest, int argc, char **argv, int *status);

/* Prints the --help text built from the table; each value option whose help
 * does not mention its default gets " (default X)" from *dest[i]. */
void cli_options_print_help(const cli_command *cmd, void *const *dest);

/* mkdir -p of one level: 0 if dir exists or was created, else a one-line
 * error naming it and EXIT_USER_ERROR. */
int cli_make_output_dir(const char *dir);

#endif
