/* Writers of the atmosphere LUTs; see atmosphere_luts_writers.h. */
#include "atmosphere/atmosphere_luts_writers.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/atomic_file.h"
#include "core/files/exr_io.h"
#include "core/image.h"
#include "core/reference_schema.h"

static const char *const FILE_NAMES[ATMOSPHERE_TABLES] = {"atmosphere_inscatter", "atmosphere_sun", "atmosphere_sky"};
static const char *const ARRAY_NAMES[ATMOSPHERE_TABLES] = {"ATMOSPHERE_INSCATTER", "ATMOSPHERE_SUN", "ATMOSPHERE_SKY"};

static const int *table_sizes(const atmosphere_luts *luts, int table)
{
    return table == ATMOSPHERE_TABLE_INSCATTER ? luts->sizes.inscatter
                                               : table == ATMOSPHERE_TABLE_SUN ? luts->sizes.sun : luts->sizes.sky;
}

static size_t table_texels(const atmosphere_luts *luts, int table)
{
    const int *n = table_sizes(luts, table);
    return (size_t)n[0] * n[1] * n[2] * n[3];
}

static int per_texel(int table) { return table == ATMOSPHERE_TABLE_INSCATTER ? 6 : 3; }

/* The channel names of a table, per_texel(table) of them. */
static void channel_names(int table, const char *names[6])
{
    const char *r[3] = CH_ATMOSPHERE_INSCATTER_RAYLEIGH, *m[3] = CH_ATMOSPHERE_INSCATTER_MIE;
    const char *sun[3] = CH_ATMOSPHERE_SUN, *sky[3] = CH_ATMOSPHERE_SKY;
    for (int c = 0; c < 3; ++c) {
        names[c] = table == ATMOSPHERE_TABLE_INSCATTER ? r[c] : table == ATMOSPHERE_TABLE_SUN ? sun[c] : sky[c];
        names[3 + c] = m[c];
    }
}

void atmosphere_luts_exr_name(atmosphere_lut_parametrization kind, int table, char *name, size_t size)
{
    if (kind == ATMOSPHERE_PARAM_LINEAR)
        snprintf(name, size, "%s.exr", FILE_NAMES[table]);
    else
        snprintf(name, size, "%s_%s.exr", FILE_NAMES[table], atmosphere_lut_parametrization_tag(kind));
}

static int write_table_exr(const char *path, const atmosphere_luts *luts, int table, gt_error *e)
{
    const int *n = table_sizes(luts, table);
    const char *names[6];
    char sizes[64], description[4096];
    image img;
    channel_names(table, names);
    snprintf(sizes, sizeof sizes, "%d %d %d %d", n[0], n[1], n[2], n[3]);
    atmosphere_luts_description(luts, description, sizeof description);
    if (image_init(&img, n[0] * n[1], n[2] * n[3]) != 0)
        return gt_error_set(e, path, "out of memory");
    int rc = image_set_attribute(&img, ATTR_LUT, description) == 0 &&
                     image_set_attribute(&img, ATTR_LUT_SIZES, sizes) == 0 &&
                     image_set_attribute(&img, ATTR_LUT_PARAMETRIZATION,
                                         atmosphere_lut_parametrization_tag(luts->parametrization)) == 0
                 ? 0
                 : -1;
    for (int c = 0; c < per_texel(table) && rc == 0; ++c) {
        float *plane = image_add_channel(&img, names[c]);
        rc = plane ? 0 : -1;
        for (size_t t = 0; plane && t < table_texels(luts, table); ++t)
            plane[t] = luts->table[table][t * per_texel(table) + c];
    }
    rc = rc == 0 ? exr_write(path, &img, e) : gt_error_set(e, path, "out of memory");
    image_free(&img);
    return rc;
}

int atmosphere_luts_write_exr(const char *dir, const atmosphere_luts *luts, gt_error *e)
{
    char path[4096], name[128];
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        atmosphere_luts_exr_name(luts->parametrization, table, name, sizeof name);
        snprintf(path, sizeof path, "%s/%s", dir, name);
        if (write_table_exr(path, luts, table, e) != 0)
            return -1;
    }
    return 0;
}

static int axes_in_range(const int n[4])
{
    int ok = 1;
    for (int a = 0; a < 4; ++a)
        ok &= n[a] >= 1 && n[a] <= ATMOSPHERE_LUT_MAX_AXIS;
    return ok;
}

/* Table `table` of luts from its file: the parametrization and sizes its
 * attributes name, the texels from its channels. */
static int read_table_exr(const char *path, atmosphere_luts *luts, int table, gt_error *e)
{
    image img;
    const char *names[6];
    if (exr_read(path, &img, e) != 0)
        return -1;
    const char *tag = image_get_attribute(&img, ATTR_LUT_PARAMETRIZATION);
    const char *sizes = image_get_attribute(&img, ATTR_LUT_SIZES);
    int *n = table == ATMOSPHERE_TABLE_INSCATTER ? luts->sizes.inscatter
                                                 : table == ATMOSPHERE_TABLE_SUN ? luts->sizes.sun : luts->sizes.sky;
    int rc = 0;
    if (atmosphere_lut_parametrization_from_tag(tag) != (int)luts->parametrization)
        rc = gt_error_set(e, path, "%s is \"%s\", not \"%s\"", ATTR_LUT_PARAMETRIZATION, tag ? tag : "(absent)",
                          atmosphere_lut_parametrization_tag(luts->parametrization));
    else if (!sizes || sscanf(sizes, "%d %d %d %d", &n[0], &n[1], &n[2], &n[3]) != 4 || !axes_in_range(n) ||
             img.width != n[0] * n[1] || img.height != n[2] * n[3])
        rc = gt_error_set(e, path, "%s \"%s\" does not match the image's %dx%d", ATTR_LUT_SIZES, sizes ? sizes : "",
                          img.width, img.height);
    channel_names(table, names);
    for (int c = 0; c < per_texel(table) && rc == 0; ++c)
        if (!image_channel_data(&img, names[c]))
            rc = gt_error_set(e, path, "no channel %s", names[c]);
    if (rc == 0 && !(luts->table[table] = malloc(sizeof(float) * (size_t)per_texel(table) * table_texels(luts, table))))
        rc = gt_error_set(e, path, "out of memory");
    for (int c = 0; c < per_texel(table) && rc == 0; ++c) {
        const float *plane = image_channel_data(&img, names[c]);
        for (size_t t = 0; t < table_texels(luts, table); ++t)
            luts->table[table][t * per_texel(table) + c] = plane[t];
    }
    image_free(&img);
    return rc;
}

int atmosphere_luts_read_exr(const char *dir, atmosphere_lut_parametrization kind, atmosphere_luts *luts, gt_error *e)
{
    char path[4096], name[128];
    *luts = (atmosphere_luts){.model = atmosphere_model_default(), .max_altitude = ATMOSPHERE_LUT_MAX_ALTITUDE,
                              .parametrization = kind};
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        atmosphere_luts_exr_name(kind, table, name, sizeof name);
        snprintf(path, sizeof path, "%s/%s", dir, name);
        if (read_table_exr(path, luts, table, e) != 0) {
            atmosphere_luts_free(luts);
            return -1;
        }
    }
    return 0;
}

/* A growing text buffer. */
typedef struct {
    char *text;
    size_t len, capacity;
} text_buffer;

static void append(text_buffer *b, const char *format, double x, double y, double z)
{
    if (b->text && b->len < b->capacity)
        b->len += (size_t)snprintf(b->text + b->len, b->capacity - b->len, format, x, y, z);
}

static size_t capacity_for(const atmosphere_luts *luts)
{
    size_t floats = 0;
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table)
        floats += table_texels(luts, table) * per_texel(table);
    return floats * 32 + 16384;
}

/* The values of table/channel group `first` (0: all 3 or 6 per texel in C; a
 * species' 3 as texels in shaders) through `texel`, 4 a line. */
static void append_values(text_buffer *b, const atmosphere_luts *luts, int table, int first, int count,
                          const char *texel)
{
    size_t n = table_texels(luts, table);
    for (size_t t = 0; t < n; ++t) {
        const float *v = luts->table[table] + t * per_texel(table) + first;
        for (int k = 0; k < count; k += 3)
            append(b, texel, v[k], v[k + 1], v[k + 2]), append(b, t + 1 == n && k + 3 >= count ? "" : ", ", 0, 0, 0);
        append(b, t % 4 == 3 ? "\n" : "", 0, 0, 0);
    }
}

static void append_sizes(text_buffer *b, const atmosphere_luts *luts)
{
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        const int *n = table_sizes(luts, table);
        b->len += (size_t)snprintf(b->text + b->len, b->capacity - b->len, "#define %s_SIZES %d, %d, %d, %d\n",
                                   ARRAY_NAMES[table], n[0], n[1], n[2], n[3]);
    }
    b->len += (size_t)snprintf(b->text + b->len, b->capacity - b->len, "#define ATMOSPHERE_MAX_ALTITUDE %.1f\n",
                               luts->max_altitude);
}

int atmosphere_luts_write_c_header(const char *path, const atmosphere_luts *luts, gt_error *e)
{
    char description[4096];
    text_buffer b = {malloc(capacity_for(luts)), 0, capacity_for(luts)};
    if (!b.text)
        return gt_error_set(e, path, "out of memory");
    atmosphere_luts_description(luts, description, sizeof description);
    b.len = (size_t)snprintf(b.text, b.capacity, "/* Generated by gtlab. %s */\n", description);
    append_sizes(&b, luts);
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        b.len += (size_t)snprintf(b.text + b.len, b.capacity - b.len, "static const float %s[%zu] = {\n",
                                  ARRAY_NAMES[table], table_texels(luts, table) * per_texel(table));
        append_values(&b, luts, table, 0, per_texel(table), "%.9g, %.9g, %.9g");
        append(&b, "\n};\n", 0, 0, 0);
    }
    int rc = atomic_write_text(path, b.text, e);
    free(b.text);
    return rc;
}

/* The shaders' dialect of atmosphere/atmosphere_luts.inc (tables 0..3: in-scatter
 * Rayleigh and Mie, sun, sky; %s: the language's texel type, 4 times). */
static const char SHADER_DIALECT[] =
    "\n/* The lookups below are techniques/atmosphere/atmosphere_luts.inc, the very text of gtlab's\n"
    " * atmosphere_lut_*, behind these definitions. */\n"
    "#define ATMO_LUT_SHADER\n#define ATMO_FN\n#define atmo_floor floor\n#define atmo_float(i) float(i)\n"
    "#define atmo_int(x) int(x)\n#define atmo_table int\n#define atmo_value %s\n"
    "struct atmo_axis\n{\n    int i0, i1;\n    float w;\n};\n"
    "int atmo_size(int t, int axis)\n{\n    int k = t < 2 ? axis : (t - 1) * 4 + axis;\n"
    "    return ATMO_SIZE_TABLE[k];\n}\n"
    "float atmo_max(int t, int axis)\n{\n    return axis == 0 ? %.9g : axis == 1 ? %.9g : ATMOSPHERE_MAX_ALTITUDE;\n}\n"
    "%s atmo_texel(int t, int s, int v, int y, int w)\n{\n"
    "    int i = ((w * atmo_size(t, 2) + y) * atmo_size(t, 1) + v) * atmo_size(t, 0) + s;\n"
    "    if (t == 0)\n        return ATMOSPHERE_INSCATTER_RAYLEIGH[i];\n"
    "    if (t == 1)\n        return ATMOSPHERE_INSCATTER_MIE[i];\n"
    "    if (t == 2)\n        return ATMOSPHERE_SUN[i];\n"
    "    return ATMOSPHERE_SKY[i];\n}\n";

typedef struct {
    const char *array_open; /* name, count */
    const char *texel;      /* 3 %.9g */
    const char *array_close;
    const char *value;      /* the texel type */
    const char *sizes;      /* the size table's declaration, 12 %d */
    const char *saturate;
} shader_words;

static const shader_words HLSL = {"static const float3 %s[%zu] = {\n", "float3(%.9g, %.9g, %.9g)", "\n};\n", "float3",
                                  "static const int ATMO_SIZE_TABLE[12] = {%d, %d, %d, %d, %d, %d, %d, %d, %d, %d, %d, %d};\n",
                                  "#define atmo_saturate saturate\n"};
static const shader_words GLSL = {"const vec3 %s[%zu] = vec3[](\n", "vec3(%.9g, %.9g, %.9g)", "\n);\n", "vec3",
                                  "const int ATMO_SIZE_TABLE[12] = int[](%d, %d, %d, %d, %d, %d, %d, %d, %d, %d, %d, %d);\n",
                                  "#define atmo_saturate(x) clamp(x, 0.0f, 1.0f)\n"};

static void shader_array(text_buffer *b, const atmosphere_luts *luts, const shader_words *w, const char *name,
                         int table, int first)
{
    b->len += (size_t)snprintf(b->text + b->len, b->capacity - b->len, w->array_open, name, table_texels(luts, table));
    append_values(b, luts, table, first, 3, w->texel);
    append(b, w->array_close, 0, 0, 0);
}

int atmosphere_luts_write_shader(const char *path, int glsl, const atmosphere_luts *luts, gt_error *e)
{
    const shader_words *w = glsl ? &GLSL : &HLSL;
    size_t capacity = capacity_for(luts) + strlen(atmosphere_luts_inc_text);
    text_buffer b = {malloc(capacity), 0, capacity};
    char description[4096];
    if (!b.text)
        return gt_error_set(e, path, "out of memory");
    const int *i = luts->sizes.inscatter, *s = luts->sizes.sun, *k = luts->sizes.sky;
    atmosphere_luts_description(luts, description, sizeof description);
    b.len = (size_t)snprintf(b.text, b.capacity, "/* Generated by gtlab. %s */\n", description);
    append_sizes(&b, luts);
    b.len += (size_t)snprintf(b.text + b.len, b.capacity - b.len, w->sizes, i[0], i[1], i[2], i[3], s[0], s[1], s[2],
                              s[3], k[0], k[1], k[2], k[3]);
    shader_array(&b, luts, w, "ATMOSPHERE_INSCATTER_RAYLEIGH", ATMOSPHERE_TABLE_INSCATTER, 0);
    shader_array(&b, luts, w, "ATMOSPHERE_INSCATTER_MIE", ATMOSPHERE_TABLE_INSCATTER, 3);
    shader_array(&b, luts, w, "ATMOSPHERE_SUN", ATMOSPHERE_TABLE_SUN, 0);
    shader_array(&b, luts, w, "ATMOSPHERE_SKY", ATMOSPHERE_TABLE_SKY, 0);
    b.len += (size_t)snprintf(b.text + b.len, b.capacity - b.len, SHADER_DIALECT, w->value, ATMOSPHERE_LUT_THETA_S_MAX,
                              ATMOSPHERE_LUT_THETA_V_MAX, w->value);
    b.len += (size_t)snprintf(b.text + b.len, b.capacity - b.len, "%s\n%s", w->saturate, atmosphere_luts_inc_text);
    int rc = atomic_write_text(path, b.text, e);
    free(b.text);
    return rc;
}

int atmosphere_luts_write_all(const char *dir, const atmosphere_luts *luts, gt_error *e)
{
    char path[4096];
    if (luts->parametrization != ATMOSPHERE_PARAM_LINEAR) /* the files' lookup (atmosphere_luts.inc) is linear */
        return gt_error_set(e, dir, "atmosphere LUTs: the C header and shaders hold the linear parametrization's "
                            "lookup; %s's tables are written as EXR only (atmosphere_luts_write_exr)",
                            atmosphere_lut_parametrization_name(luts->parametrization));
    if (atmosphere_luts_write_exr(dir, luts, e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/atmosphere_luts.h", dir);
    if (atmosphere_luts_write_c_header(path, luts, e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/atmosphere_luts.hlsl", dir);
    if (atmosphere_luts_write_shader(path, 0, luts, e) != 0)
        return -1;
    snprintf(path, sizeof path, "%s/atmosphere_luts.glsl", dir);
    return atmosphere_luts_write_shader(path, 1, luts, e);
}
