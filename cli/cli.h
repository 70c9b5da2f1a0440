/* The gtlab command line: one verb per file (verb_*.c), each an entry point
 * `int verb_NAME(int argc, char **argv)` returning the exit status:
 * 0 success, 1 user error (bad input, bad option), 2 internal error.
 * argv[0] is the verb itself, options follow (getopt_long). */
#ifndef GTLAB_CLI_CLI_H
#define GTLAB_CLI_CLI_H

#include <stdint.h>

#include "core/error.h"

enum { EXIT_OK = 0, EXIT_USER_ERROR = 1, EXIT_INTERNAL_ERROR = 2 };

int verb_scene(int argc, char **argv);
int verb_render(int argc, char **argv);
int verb_merge(int argc, char **argv);
int verb_plan(int argc, char **argv);
int verb_compare(int argc, char **argv);
int verb_bench(int argc, char **argv);
int verb_all(int argc, char **argv);
int verb_init(int argc, char **argv);
int verb_check(int argc, char **argv);
int verb_fit(int argc, char **argv);
int verb_lut(int argc, char **argv);
int verb_approx(int argc, char **argv);
int verb_shader(int argc, char **argv);

/* Prints "gtlab: <message>" on stderr and returns EXIT_USER_ERROR. */
int cli_fail(const gt_error *e);
/* Prints "gtlab: <subject>: <formatted problem>" and returns EXIT_USER_ERROR. */
int cli_failf(const char *subject, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* The usual reply to an unknown option or missing argument: one line pointing at --help. */
int cli_usage_error(const char *verb);

/* Strict number parsing of option values: the whole string must be a number
 * within [lo, hi]. On failure prints "gtlab: --option: ..." and returns -1. */
int cli_parse_int(const char *option, const char *text, long lo, long hi, long *out);
int cli_parse_double(const char *option, const char *text, double lo, double hi, double *out);

/* Reset getopt so each verb can parse from the start of its own argv. */
void cli_reset_getopt(void);

#endif
