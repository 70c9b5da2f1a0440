#include "core/error.h"

#include <stdio.h>
#include <string.h>

/* Control characters (and DEL) become '?'; UTF-8 is left alone. */
static void make_printable(char *text)
{
    for (unsigned char *c = (unsigned char *)text; *c; ++c)
        if (*c < 0x20 || *c == 0x7f)
            *c = '?';
}

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
    make_printable(e->message);
    return -1;
}

void gt_warn(const char *subject, const char *fmt, ...)
{
    char problem[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(problem, sizeof problem, fmt, ap);
    va_end(ap);
    make_printable(problem);
    fprintf(stderr, "gtlab: warning: %s: %s\n", subject ? subject : "gtlab", problem);
}

const char *gt_quote(const char *text, gt_quoted *q)
{
    const size_t room = sizeof q->text - 4; /* for "..." and the NUL */
    size_t bytes = 0, characters = 0;
    text = text ? text : "";
    /* Count characters, not bytes: a cut never splits a UTF-8 sequence. */
    while (text[bytes] && characters < GT_QUOTE_MAX && bytes < room) {
        ++bytes;
        while (((unsigned char)text[bytes] & 0xC0) == 0x80 && bytes < room)
            ++bytes;
        ++characters;
    }
    memcpy(q->text, text, bytes);
    strcpy(q->text + bytes, text[bytes] ? "..." : "");
    make_printable(q->text);
    return q->text;
}
