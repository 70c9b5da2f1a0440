/* JSON files read whole and doubles written exactly (json_file.h). */
#include "core/files/json_file.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/input_file.h"
#include "core/files/json_check.h"
#include "core/files/json_unique_keys.h"

cJSON *json_file_read_object(const char *path, size_t max_size, const char *too_large, const char *kind,
                             gt_error *e)
{
    char *text;
    size_t length;
    if (input_file_read(path, max_size, too_large, &text, &length, e) != 0)
        return NULL;
    cJSON *root = NULL;
    if (json_check(text, length, json_limits_cjson, path, e) == 0) {
        const size_t bom = json_bom_length(text, length);
        root = cJSON_ParseWithLengthOpts(text + bom, length - bom + 1, NULL, 1);
        if (!cJSON_IsObject(root) || json_check_unique_keys(root, path, e) != 0) {
            if (!cJSON_IsObject(root))
                gt_error_set(e, path, "not a JSON object (%s expected)", kind);
            cJSON_Delete(root);
            root = NULL;
        }
    }
    free(text);
    return root;
}

/* The strings standing for the doubles cJSON cannot print exactly. */
static const char *special_name(double x)
{
    if (isnan(x))
        return "nan";
    if (isinf(x))
        return x > 0 ? "inf" : "-inf";
    return x == 0.0 && signbit(x) ? "-0" : NULL;
}

cJSON *json_exact_number(double x)
{
    const char *name = special_name(x);
    char digits[32];
    if (name)
        return cJSON_CreateString(name);
    snprintf(digits, sizeof digits, "%.17g", x); /* printed as is: a JSON number */
    return cJSON_CreateRaw(digits);
}

int json_exact_value(const cJSON *item, double *x)
{
    static const char *const names[] = {"nan", "inf", "-inf", "-0"};
    const double values[] = {NAN, INFINITY, -INFINITY, -0.0};
    *x = NAN;
    if (cJSON_IsNumber(item)) /* read from a file */
        return *x = item->valuedouble, 0;
    if (cJSON_IsRaw(item)) { /* made by json_exact_number, not yet written */
        char *end;
        *x = strtod(item->valuestring, &end);
        return *end == 0 && end != item->valuestring ? 0 : (*x = NAN, -1);
    }
    for (int i = 0; cJSON_IsString(item) && i < 4; ++i)
        if (strcmp(item->valuestring, names[i]) == 0)
            return *x = values[i], 0;
    return -1;
}

static cJSON *field_item(const char *base, const json_field *f)
{
    const char *at = base + f->offset, *text;
    switch (f->kind) {
    case JSON_FIELD_TEXT_ARRAY: return cJSON_CreateString(at);
    case JSON_FIELD_TEXT_POINTER:
        text = *(const char *const *)at;
        return text ? cJSON_CreateString(text) : cJSON_CreateNull();
    case JSON_FIELD_DOUBLE: return json_exact_number(*(const double *)at);
    default: return cJSON_CreateNumber(*(const int *)at);
    }
}

void json_fields_add(cJSON *o, const void *base, const json_field *fields, size_t count)
{
    for (size_t i = 0; o && i < count; ++i)
        cJSON_AddItemToObject(o, fields[i].name, field_item(base, &fields[i]));
}

static int read_field(const cJSON *item, char *base, const json_field *f)
{
    char *at = base + f->offset;
    switch (f->kind) {
    case JSON_FIELD_TEXT_ARRAY:
        return cJSON_IsString(item) ? (snprintf(at, f->size, "%s", item->valuestring), 0) : -1;
    case JSON_FIELD_TEXT_POINTER:
        if (!cJSON_IsString(item) && !cJSON_IsNull(item))
            return -1;
        *(const char **)at = cJSON_IsString(item) ? item->valuestring : NULL;
        return 0;
    case JSON_FIELD_DOUBLE: return json_exact_value(item, (double *)at);
    default: return cJSON_IsNumber(item) ? (*(int *)at = item->valueint, 0) : -1;
    }
}

int json_fields_read(const cJSON *o, void *base, const json_field *fields, size_t count)
{
    for (size_t i = 0; i < count; ++i)
        if (read_field(cJSON_GetObjectItemCaseSensitive(o, fields[i].name), base, &fields[i]) != 0)
            return -1;
    return 0;
}
