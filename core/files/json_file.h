/* JSON files gtlab writes and reads back (a `gtlab all` stage's part of the
 * report, report/report_part.h), and any JSON file read whole:
 *
 *   reading   the file must be a regular file of at most max_size bytes
 *             (core/files/input_file.h), pass the JSON gate (json_check.h),
 *             be an object and repeat no key (json_unique_keys.h); every
 *             refusal is one line naming the file;
 *   numbers   cJSON prints a double with 15 significant digits when they
 *             read back to within a relative DBL_EPSILON (not to the same
 *             bits), NaN and the infinities as null and -0 as 0. A figure
 *             that must come back exactly (a headline's error, a claim's
 *             figure, from which its interval is recomputed) is written with
 *             json_exact_number: a finite double as a number of 17
 *             significant digits (which strtod reads back to its bits),
 *             NaN, the infinities and -0 as the strings "nan", "inf",
 *             "-inf" and "-0". */
#ifndef GTLAB_CORE_FILES_JSON_FILE_H
#define GTLAB_CORE_FILES_JSON_FILE_H

#include <stddef.h>

#include <cjson/cJSON.h>

#include "core/error.h"

/* The object in the file at path (cJSON_Delete it), or NULL with e =
 * "<path>: <problem>"; too_large says what a larger file is taken for. */
cJSON *json_file_read_object(const char *path, size_t max_size, const char *too_large, const char *kind,
                             gt_error *e);

/* x as a JSON item that json_exact_value reads back to the same bits. */
cJSON *json_exact_number(double x);
/* The double an item written by json_exact_number holds: 0 and *x, or -1
 * (*x NaN) for an item that is neither a number nor one of its strings. */
int json_exact_value(const cJSON *item, double *x);

/* A struct's members as an object's, by table (a headline row, a claim's
 * record): texts held in arrays (char[size]), texts by pointer (NULL as
 * null; read back pointing into the object), doubles (exact, as above) and
 * ints (enums too). */
typedef enum { JSON_FIELD_TEXT_ARRAY, JSON_FIELD_TEXT_POINTER, JSON_FIELD_DOUBLE, JSON_FIELD_INT } json_field_kind;
typedef struct {
    const char *name;
    size_t offset;
    json_field_kind kind;
    size_t size; /* JSON_FIELD_TEXT_ARRAY: the array's size */
} json_field;

/* Adds the fields of the struct at base to o. */
void json_fields_add(cJSON *o, const void *base, const json_field *fields, size_t count);
/* Sets the fields of the struct at base from o: 0, or -1 when one is
 * missing or of the wrong type (the struct then partly set). */
int json_fields_read(const cJSON *o, void *base, const json_field *fields, size_t count);

#endif
