#define _GNU_SOURCE
#include "cli/cli.h"

#include "core/number_parse.h"

#include <getopt.h>
#include <stdarg.h>
#include <stdio.h>

int cli_fail(const gt_error *e)
{
    fprintf(stderr, "gtlab: %s\n", e->message);
    return EXIT_USER_ERROR;
}

int cli_failf(const char *subject, const char *fmt, ...)
{
    fprintf(stderr, "gtlab: %s: ", subject);
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return EXIT_USER_ERROR;
}

int cli_usage_error(const char *verb)
{
    fprintf(stderr, "gtlab: %s: invalid usage (see 'gtlab %s --help')\n", verb, verb);
    return EXIT_USER_ERROR;
}

int cli_parse_int(const char *option, const char *text, long lo, long hi, long *out)
{
    gt_error e;
    return parse_whole_in(option, text, lo, hi, out, &e) != 0 ? (cli_fail(&e), -1) : 0;
}

int cli_parse_double(const char *option, const char *text, double lo, double hi, double *out)
{
    gt_error e;
    return parse_real_in(option, text, lo, hi, out, &e) != 0 ? (cli_fail(&e), -1) : 0;
}

void cli_reset_getopt(void)
{
    optind = 0; /* glibc: 0 also re-initialises its internal state */
    opterr = 0; /* we print our own one-line errors */
}
