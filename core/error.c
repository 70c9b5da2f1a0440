#include "core/error.h"

#include <stdio.h>

int gt_error_set(gt_error *e, const char *subject, const char *fmt, ...)
{
    if (!e)
        return -1;
    int n = snprintf(e->message, sizeof e->message, "%s: ", subject ? subject : "gtlab");
    if (n < 0 || (size_t)n >= sizeof e->message)
        return -1;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(e->message + n, sizeof e->message - (size_t)n, fmt, ap);
    va_end(ap);
    return -1;
}

void gt_warn(const char *subject, const char *fmt, ...)
{
    fprintf(stderr, "gtlab: warning: %s: ", subject ? subject : "gtlab");
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}
