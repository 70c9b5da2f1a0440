/* Errors travel as values: library code fills a gt_error and returns non-zero;
 * only the CLI prints, as the one line "gtlab: <file>: <problem>" (DESIGN.md). */
#ifndef GTLAB_CORE_ERROR_H
#define GTLAB_CORE_ERROR_H

#include <stdarg.h>

typedef struct {
    char message[1024]; /* "<file>: <problem>", no trailing newline */
} gt_error;

/* Sets e->message to "<subject>: <formatted problem>". Returns -1 so callers
 * can write `return gt_error_set(e, path, "...")`. e may be NULL. */
int gt_error_set(gt_error *e, const char *subject, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Prints "gtlab: warning: <subject>: <problem>" on stderr: for input that is
 * usable but not as the user may have meant it. */
void gt_warn(const char *subject, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif
