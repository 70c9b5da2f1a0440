#include "core/number_parse.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>

int parse_whole_in(const char *subject, const char *text, long lo, long hi, long *out, gt_error *e)
{
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    gt_quoted q;
    if (errno || end == text || *end != '\0')
        return gt_error_set(e, subject, "'%s' is not a whole number", gt_quote(text, &q));
    if (v < lo || v > hi)
        return gt_error_set(e, subject, "%ld is out of range [%ld, %ld]", v, lo, hi);
    *out = v;
    return 0;
}

int parse_real_in(const char *subject, const char *text, double lo, double hi, double *out, gt_error *e)
{
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    gt_quoted q;
    if (errno || end == text || *end != '\0' || !isfinite(v))
        return gt_error_set(e, subject, "'%s' is not a number", gt_quote(text, &q));
    if (v < lo || v > hi)
        return gt_error_set(e, subject, "%g is out of range [%g, %g]", v, lo, hi);
    *out = v;
    return 0;
}
