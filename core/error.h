/* Errors travel as values: library code fills a gt_error and returns non-zero;
 * only the CLI prints, as the one line "gtlab: <file>: <problem>" (DESIGN.md). */
#ifndef GTLAB_CORE_ERROR_H
#define GTLAB_CORE_ERROR_H

#include <stdarg.h>

typedef struct {
    char message[1024]; /* "<file>: <problem>", no trailing newline */
} gt_error;

/* Sets e->message to "<subject>: <formatted problem>". Returns -1 so callers
 * can write `return gt_error_set(e, path, "...")`. e may be NULL. Control
 * characters (a newline quoted from a file) become '?': the message stays
 * one line. */
int gt_error_set(gt_error *e, const char *subject, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Prints "gtlab: warning: <subject>: <problem>" on stderr: for input that is
 * usable but not as the user may have meant it. One line, as errors. */
void gt_warn(const char *subject, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Input quoted in a message is cut to GT_QUOTE_MAX characters (then "...")
 * and its control characters shown as '?'. */
#define GT_QUOTE_MAX 80
typedef struct {
    char text[4 * GT_QUOTE_MAX + 4]; /* GT_QUOTE_MAX UTF-8 characters and "..." */
} gt_quoted;
/* The quotable form of text (NULL reads as ""), in q; returns q->text. */
const char *gt_quote(const char *text, gt_quoted *q);

#endif
