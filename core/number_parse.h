/* Strict parsing of numbers given as text (command-line option values): the
 * whole string must be one number within [lo, hi]. Errors read
 * "<subject>: 'x' is not a number" or "<subject>: 5 is out of range [0, 1]"
 * (the subject is usually the option, "--roughness"). */
#ifndef GTLAB_CORE_NUMBER_PARSE_H
#define GTLAB_CORE_NUMBER_PARSE_H

#include "core/error.h"

/* A whole number in [lo, hi]. Returns 0, or -1 with e set. */
int parse_whole_in(const char *subject, const char *text, long lo, long hi, long *out, gt_error *e);
/* A finite real number in [lo, hi]. Returns 0, or -1 with e set. */
int parse_real_in(const char *subject, const char *text, double lo, double hi, double *out, gt_error *e);

#endif
