#include "gpu/shader_interface.h"

#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/number_parse.h"
#include "gpu/shader_compiler.h"

static const char kParam[] = "// gtlab.param ", kOutput[] = "// gtlab.output ";

/* A name of letters, digits, '_' and '.', shorter than GPU_NAME_MAX. */
static int valid_name(const char *s, size_t n)
{
    if (n == 0 || n >= GPU_NAME_MAX)
        return 0;
    for (size_t i = 0; i < n; ++i)
        if (!(s[i] == '_' || s[i] == '.' || (s[i] >= '0' && s[i] <= '9') || ((s[i] | 32) >= 'a' && (s[i] | 32) <= 'z')))
            return 0;
    return 1;
}

/* "NAME DEFAULT" after "// gtlab.param ". */
static int parse_param(const char *text, size_t n, gpu_shader_interface *s, const char *where, gt_error *e)
{
    char line[256], *space;
    snprintf(line, sizeof line, "%.*s", (int)(n < 255 ? n : 255), text);
    space = strchr(line, ' ');
    if (!space || !valid_name(line, (size_t)(space - line)))
        return gt_error_set(e, where, "gtlab.param needs a name and a default value: \"%s\"", line);
    *space = '\0';
    double value;
    char subject[1024];
    snprintf(subject, sizeof subject, "%s: gtlab.param %.63s", where, line);
    if (parse_real_in(subject, space + 1, -FLT_MAX, FLT_MAX, &value, e) != 0)
        return -1;
    if (s->param_count == GPU_MAX_PARAMS)
        return gt_error_set(e, where, "more than %d gtlab.param lines", GPU_MAX_PARAMS);
    snprintf(s->param_name[s->param_count], GPU_NAME_MAX, "%.63s", line);
    s->param_value[s->param_count++] = (float)value;
    return 0;
}

static int parse_output(const char *text, size_t n, gpu_shader_interface *s, const char *where, gt_error *e)
{
    if (!valid_name(text, n))
        return gt_error_set(e, where, "gtlab.output needs one channel name (letters, digits, '_', '.')");
    if (s->output_count == GPU_MAX_OUTPUTS)
        return gt_error_set(e, where, "more than %d gtlab.output lines", GPU_MAX_OUTPUTS);
    snprintf(s->output_name[s->output_count++], GPU_NAME_MAX, "%.*s", (int)n, text);
    return 0;
}

/* One line: a declaration, or nothing to read. */
static int parse_line(const char *line, size_t n, gpu_shader_interface *s, const char *where, gt_error *e)
{
    while (n > 0 && (line[n - 1] == ' ' || line[n - 1] == '\r' || line[n - 1] == '\t'))
        --n;
    size_t p = sizeof kParam - 1, o = sizeof kOutput - 1;
    if (n >= p && strncmp(line, kParam, p) == 0)
        return parse_param(line + p, n - p, s, where, e);
    if (n >= o && strncmp(line, kOutput, o) == 0)
        return parse_output(line + o, n - o, s, where, e);
    return 0;
}

int gpu_shader_interface_parse(const char *source, const char *name, gpu_shader_interface *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    int number = 1;
    for (const char *line = source; *line; ++number) {
        size_t n = strcspn(line, "\n");
        char where[512];
        snprintf(where, sizeof where, "%s:%d", name, number);
        if (parse_line(line, n, out, where, e) != 0)
            return -1;
        line += n + (line[n] == '\n');
    }
    if (out->output_count == 0)
        return gt_error_set(e, name, "no \"// gtlab.output CHANNEL\" line: the shader names no output (docs/shaders.md)");
    return 0;
}

/* "radius, falloff" for a message. */
static void declared(const gpu_shader_interface *s, char *list, size_t size)
{
    size_t used = 0;
    list[0] = '\0';
    for (int i = 0; i < s->param_count && used < size; ++i) {
        int n = snprintf(list + used, size - used, "%s%s", i ? ", " : "", s->param_name[i]);
        used += n > 0 ? (size_t)n : 0;
    }
}

int gpu_shader_interface_set(gpu_shader_interface *s, const char *assignment, const char *name, gt_error *e)
{
    const char *eq = strchr(assignment, '=');
    double value;
    char subject[600];
    snprintf(subject, sizeof subject, "%s: --param %.*s", name, eq ? (int)(eq - assignment) : 0, assignment);
    if (!eq)
        return gt_error_set(e, name, "--param %s: expected NAME=NUMBER", assignment);
    if (parse_real_in(subject, eq + 1, -FLT_MAX, FLT_MAX, &value, e) != 0)
        return -1;
    for (int i = 0; i < s->param_count; ++i)
        if (strlen(s->param_name[i]) == (size_t)(eq - assignment) &&
            strncmp(s->param_name[i], assignment, (size_t)(eq - assignment)) == 0) {
            s->param_value[i] = (float)value;
            return 0;
        }
    char list[1024];
    declared(s, list, sizeof list);
    return gt_error_set(e, name, "--param %.*s: the shader declares no such parameter (its gtlab.param lines: %s)",
                        (int)(eq - assignment), assignment, list[0] ? list : "none");
}

int gpu_shader_interface_load(const char *path, const char *const *params, int param_count, char **source,
                              gpu_shader_interface *out, gt_error *e)
{
    *source = NULL;
    if (gpu_read_source(path, source, e) != 0 || gpu_shader_interface_parse(*source, path, out, e) != 0)
        return -1;
    for (int i = 0; i < param_count; ++i)
        if (gpu_shader_interface_set(out, params[i], path, e) != 0)
            return -1;
    return 0;
}
