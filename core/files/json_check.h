/* The gate in front of every JSON parser gtlab uses (tinygltf's nlohmann
 * json for glTF, cJSON for camera JSON): one pass over the text, without
 * recursion and with a fixed-size stack, that accepts exactly the JSON texts
 * of RFC 8259 (an optional UTF-8 byte-order mark first, as its section 8.1
 * allows) whose arrays and objects nest at most `max_depth` deep and whose
 * numbers are finite doubles. Whatever it accepts, both parsers parse (the
 * json fuzz target checks this); whatever it refuses gets one error in
 * gtlab's words with the line and column, e.g.
 *   "invalid UTF-8 in a JSON string at line 1, column 631"
 * instead of a parser's exception text, and never reaches a recursive
 * parser, so deep nesting cannot overflow the stack. */
#ifndef GTLAB_CORE_FILES_JSON_CHECK_H
#define GTLAB_CORE_FILES_JSON_CHECK_H

#include <stddef.h>

#include "core/error.h"

/* Deepest nesting of arrays and objects gtlab reads. Real glTF nests about
 * 6 deep (extensions and extras a few more); the recursive parsers behind
 * the gate survive thousands. */
#define JSON_MAX_DEPTH 256

typedef struct {
    int max_depth;            /* at most JSON_MAX_DEPTH */
    size_t max_number_length; /* characters in one number; 0: no limit */
} json_limits;

/* What glTF files may hold. */
static const json_limits json_limits_gltf = {JSON_MAX_DEPTH, 0};
/* cJSON reads at most 63 characters of a number (its parse_number buffer). */
static const json_limits json_limits_cjson = {JSON_MAX_DEPTH, 63};

/* Returns 0 when text[0, length) is one JSON value within the limits, or -1
 * with e = "<what>: <problem> at line L, column C" (columns count
 * characters). NUL bytes are not JSON: text need not be NUL-terminated. */
int json_check(const char *text, size_t length, json_limits limits, const char *what, gt_error *e);

/* The length of a leading UTF-8 byte-order mark (3), or 0: JSON parsers that
 * do not skip one (cJSON) are handed the text after it. */
size_t json_bom_length(const char *text, size_t length);

#endif
