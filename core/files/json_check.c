/* The JSON gate (json_check.h): RFC 8259's grammar, scanned by one loop
 * whose only memory is a fixed array of the open containers, so neither
 * deep nesting nor a long text can exhaust the stack. Strings are checked
 * as the Unicode standard (15.0, table 3-7, "well-formed UTF-8 byte
 * sequences") defines UTF-8: no overlong forms, no surrogates, nothing above
 * U+10FFFF; \u escapes must pair their UTF-16 surrogates. Numbers follow
 * RFC 8259 section 6 and must be finite as doubles (nlohmann json refuses
 * 1e400 as "number overflow"). */
#include "core/files/json_check.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const unsigned char *begin, *p, *end;
    json_limits limits;
    int depth;
    unsigned char open[JSON_MAX_DEPTH]; /* '[' or '{' for each open container */
    const unsigned char *at;            /* where the problem is */
    char problem[128];
} json_scan;

static int fail(json_scan *s, const unsigned char *at, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int fail(json_scan *s, const unsigned char *at, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s->problem, sizeof s->problem, fmt, ap);
    va_end(ap);
    s->at = at;
    return -1;
}

/* "found 'x'", "found byte 0xC3" or "found the end of the text", for p. */
static void describe(const json_scan *s, const unsigned char *p, char *out, size_t size)
{
    if (p == s->end)
        snprintf(out, size, "the end of the text");
    else if (*p >= 0x20 && *p < 0x7f)
        snprintf(out, size, "'%c'", *p);
    else
        snprintf(out, size, "byte 0x%02X", *p);
}

static int fail_expected(json_scan *s, const char *expected)
{
    char found[32];
    describe(s, s->p, found, sizeof found);
    return fail(s, s->p, "expected %s, found %s", expected, found);
}

static void skip_space(json_scan *s)
{
    while (s->p < s->end && (*s->p == ' ' || *s->p == '\t' || *s->p == '\n' || *s->p == '\r'))
        ++s->p;
}

/* ---------------------------------------------------------------- strings */

/* The length of the well-formed UTF-8 sequence at p (p < end), or 0. */
static size_t utf8_sequence(const unsigned char *p, const unsigned char *end)
{
    const unsigned char c = p[0];
    unsigned char lo = 0x80, hi = 0xBF; /* the range of the second byte */
    size_t n;
    if (c < 0x80)
        return 1;
    if (c >= 0xC2 && c <= 0xDF)
        n = 2;
    else if (c >= 0xE0 && c <= 0xEF)
        n = 3, lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    else if (c >= 0xF0 && c <= 0xF4)
        n = 4, lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    else
        return 0;
    if ((size_t)(end - p) < n || p[1] < lo || p[1] > hi)
        return 0;
    for (size_t k = 2; k < n; ++k)
        if (p[k] < 0x80 || p[k] > 0xBF)
            return 0;
    return n;
}

static int hex_digit(unsigned char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if ((c | 0x20) >= 'a' && (c | 0x20) <= 'f')
        return (c | 0x20) - 'a' + 10;
    return -1;
}

/* The UTF-16 code unit of "\uXXXX" at p, or -1. */
static long unicode_escape(const unsigned char *p, const unsigned char *end)
{
    if (end - p < 6 || p[0] != '\\' || p[1] != 'u')
        return -1;
    long unit = 0;
    for (int k = 2; k < 6; ++k) {
        const int d = hex_digit(p[k]);
        if (d < 0)
            return -1;
        unit = 16 * unit + d;
    }
    return unit;
}

/* One escape sequence at s->p (a backslash); a high surrogate must be
 * followed by the escape of a low one. */
static int scan_escape(json_scan *s)
{
    const unsigned char *at = s->p;
    if (s->end - s->p >= 2 && s->p[1] != 'u' && s->p[1] != '\0' && strchr("\"\\/bfnrt", s->p[1])) {
        s->p += 2;
        return 0;
    }
    const long unit = unicode_escape(s->p, s->end);
    if (unit < 0)
        return fail(s, at, "invalid escape in a JSON string");
    s->p += 6;
    if (unit >= 0xDC00 && unit <= 0xDFFF)
        return fail(s, at, "unpaired UTF-16 surrogate (a \\u escape) in a JSON string");
    if (unit < 0xD800 || unit > 0xDBFF)
        return 0;
    const long low = unicode_escape(s->p, s->end);
    if (low < 0xDC00 || low > 0xDFFF)
        return fail(s, at, "unpaired UTF-16 surrogate (a \\u escape) in a JSON string");
    s->p += 6;
    return 0;
}

static int scan_string(json_scan *s)
{
    const unsigned char *start = s->p++;
    while (s->p < s->end) {
        const unsigned char c = *s->p;
        if (c == '"') {
            ++s->p;
            return 0;
        }
        if (c == '\\') {
            if (scan_escape(s) != 0)
                return -1;
            continue;
        }
        if (c < 0x20)
            return fail(s, s->p, "control character (byte 0x%02X) in a JSON string", c);
        const size_t n = utf8_sequence(s->p, s->end);
        if (n == 0)
            return fail(s, s->p, "invalid UTF-8 in a JSON string");
        s->p += n;
    }
    return fail(s, start, "JSON string never closed; it starts");
}

/* ---------------------------------------------------------------- numbers */

static const unsigned char *skip_digits(const unsigned char *p, const unsigned char *end)
{
    while (p < end && *p >= '0' && *p <= '9')
        ++p;
    return p;
}

/* Whether the number text[0, n) is finite as a double. Without an exponent
 * and with at most 300 characters it is below 1e300. */
static int number_is_finite(const unsigned char *text, size_t n, int *out_of_memory)
{
    if (n <= 300 && !memchr(text, 'e', n) && !memchr(text, 'E', n))
        return 1;
    char small[64], *copy = n < sizeof small ? small : malloc(n + 1);
    if (!copy)
        return *out_of_memory = 1, 0;
    memcpy(copy, text, n);
    copy[n] = '\0';
    const double v = strtod(copy, NULL);
    if (copy != small)
        free(copy);
    return isfinite(v);
}

static int scan_number(json_scan *s)
{
    const unsigned char *start = s->p, *p = s->p, *end = s->end;
    if (p < end && *p == '-')
        ++p;
    if (p < end && *p == '0')
        ++p;
    else if (p < end && *p >= '1' && *p <= '9')
        p = skip_digits(p, end);
    else
        return fail(s, start, "invalid number (a digit must follow '-')");
    if (p < end && *p == '.') {
        const unsigned char *q = skip_digits(p + 1, end);
        if (q == p + 1)
            return fail(s, start, "invalid number (a digit must follow the decimal point)");
        p = q;
    }
    if (p < end && (*p == 'e' || *p == 'E')) {
        p += p + 1 < end && (p[1] == '+' || p[1] == '-') ? 2 : 1;
        const unsigned char *q = skip_digits(p, end);
        if (q == p)
            return fail(s, start, "invalid number (its exponent has no digits)");
        p = q;
    }
    const size_t n = (size_t)(p - start);
    if (s->limits.max_number_length && n > s->limits.max_number_length)
        return fail(s, start, "number of %zu characters (at most %zu are read)", n, s->limits.max_number_length);
    int out_of_memory = 0;
    if (!number_is_finite(start, n, &out_of_memory))
        return fail(s, start, out_of_memory ? "out of memory reading a number" : "number too large for a double");
    s->p = p;
    return 0;
}

static int scan_literal(json_scan *s)
{
    static const char *const words[] = {"true", "false", "null"};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; ++i) {
        const size_t n = strlen(words[i]);
        if ((size_t)(s->end - s->p) >= n && memcmp(s->p, words[i], n) == 0) {
            s->p += n;
            return 0;
        }
    }
    return fail_expected(s, "a JSON value (true, false or null?)");
}

/* ---------------------------------------------------------------- structure */

static int scan_member_name(json_scan *s)
{
    skip_space(s);
    if (s->p == s->end || *s->p != '"')
        return fail_expected(s, "a member name (a string)");
    if (scan_string(s) != 0)
        return -1;
    skip_space(s);
    if (s->p == s->end || *s->p != ':')
        return fail_expected(s, "':' after a member name");
    ++s->p;
    return 0;
}

/* Opens an array or object at s->p. *want_value: whether a value comes
 * next (0 when the container was empty and is closed already). */
static int open_container(json_scan *s, int *want_value)
{
    const unsigned char kind = *s->p, close = kind == '{' ? '}' : ']';
    if (s->depth >= s->limits.max_depth)
        return fail(s, s->p, "JSON nests deeper than %d arrays and objects", s->limits.max_depth);
    s->open[s->depth++] = kind;
    ++s->p;
    skip_space(s);
    if (s->p < s->end && *s->p == close) {
        --s->depth;
        ++s->p;
        *want_value = 0;
        return 0;
    }
    *want_value = 1;
    return kind == '{' ? scan_member_name(s) : 0;
}

static int scan_value(json_scan *s, int *want_value)
{
    if (s->p == s->end)
        return fail(s, s->p, s->depth ? "JSON text ends early: an array or object is not closed"
                                      : "JSON text ends where a value was expected");
    const unsigned char c = *s->p;
    *want_value = 0;
    if (c == '{' || c == '[')
        return open_container(s, want_value);
    if (c == '"')
        return scan_string(s);
    if (c == '-' || (c >= '0' && c <= '9'))
        return scan_number(s);
    return scan_literal(s);
}

/* After a value inside a container: ',' and the next element or member,
 * or the container's end. */
static int scan_after_value(json_scan *s, int *want_value)
{
    const unsigned char kind = s->open[s->depth - 1], close = kind == '{' ? '}' : ']';
    if (s->p == s->end)
        return fail(s, s->p, "JSON text ends early: an array or object is not closed");
    if (*s->p == close) {
        --s->depth;
        ++s->p;
        *want_value = 0;
        return 0;
    }
    if (*s->p != ',')
        return fail_expected(s, kind == '{' ? "',' or '}' after an object member"
                                            : "',' or ']' after an array element");
    ++s->p;
    *want_value = 1;
    return kind == '{' ? scan_member_name(s) : 0;
}

static int scan(json_scan *s)
{
    int want_value = 1;
    for (;;) {
        skip_space(s);
        if (want_value) {
            if (scan_value(s, &want_value) != 0)
                return -1;
        } else if (s->depth > 0) {
            if (scan_after_value(s, &want_value) != 0)
                return -1;
        } else {
            return s->p == s->end ? 0 : fail_expected(s, "nothing after the JSON value");
        }
    }
}

/* ---------------------------------------------------------------- entry */

/* Line and column (1-based; columns count characters, not UTF-8
 * continuation bytes) of position at. */
static void line_and_column(const json_scan *s, size_t *line, size_t *column)
{
    *line = 1;
    *column = 1;
    for (const unsigned char *p = s->begin; p < s->at; ++p) {
        if (*p == '\n')
            ++*line, *column = 1;
        else if ((*p & 0xC0) != 0x80)
            ++*column;
    }
}

size_t json_bom_length(const char *text, size_t length)
{
    return length >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
}

int json_check(const char *text, size_t length, json_limits limits, const char *what, gt_error *e)
{
    json_scan s;
    s.begin = (const unsigned char *)text;
    s.p = s.begin + json_bom_length(text, length);
    s.end = s.begin + length;
    s.limits = limits;
    if (s.limits.max_depth > JSON_MAX_DEPTH || s.limits.max_depth < 1)
        s.limits.max_depth = JSON_MAX_DEPTH;
    s.depth = 0;
    if (scan(&s) == 0)
        return 0;
    size_t line, column;
    line_and_column(&s, &line, &column);
    return gt_error_set(e, what, "%s at line %zu, column %zu", s.problem, line, column);
}
