/* The per-sample function contract's wrapper (gpu/function_shader.h). */
#define _GNU_SOURCE
#include "gpu/function_shader.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gpu/sample_map.h"
#include "gpu/shader_compiler.h"

const gpu_function_contract gpu_function_multibounce = {
    "gtlab_multibounce", "float gtlab_multibounce(float visibility, float albedo)", 2};
const gpu_function_contract gpu_function_specular_occlusion = {
    "gtlab_specular_occlusion", "float gtlab_specular_occlusion(float ao, float beta, float roughness, float n_dot_v)",
    4};

static const char kGlslHead[] = "#version 450\n#line 1\n";
/* After the user's function; %d is GPU_SAMPLE_GROUP, %s the call. */
static const char kGlslMain[] = "\nlayout(local_size_x = %d) in;\n"
                                "layout(std140, binding = 0) uniform GtlabCount { uint gtlab_count; };\n"
                                "layout(std430, binding = 1) readonly buffer GtlabIn { float gtlab_in[]; };\n"
                                "layout(std430, binding = 2) writeonly buffer GtlabOut { float gtlab_out[]; };\n"
                                "void main()\n{\n    uint i = gl_GlobalInvocationID.x;\n"
                                "    if (i < gtlab_count)\n"
                                "        gtlab_out[i] = %s;\n"
                                "}\n";
static const char kHlslMain[] = "\n[[vk::binding(0)]] cbuffer GtlabCount { uint gtlab_count; };\n"
                                "[[vk::binding(1)]] StructuredBuffer<float> gtlab_in;\n"
                                "[[vk::binding(2)]] RWStructuredBuffer<float> gtlab_out;\n"
                                "[numthreads(%d, 1, 1)]\nvoid main(uint3 gtlab_id : SV_DispatchThreadID)\n{\n"
                                "    uint i = gtlab_id.x;\n    if (i < gtlab_count)\n"
                                "        gtlab_out[i] = %s;\n"
                                "}\n";

/* Whether a line of `text` is a #version directive. */
static int has_version_line(const char *text)
{
    for (const char *line = text; line; line = strchr(line, '\n'), line = line ? line + 1 : NULL) {
        line += strspn(line, " \t");
        if (strncmp(line, "#version", 8) == 0)
            return 1;
    }
    return 0;
}

int gpu_function_defines(const gpu_function_contract *c, const char *text)
{
    size_t n = strlen(c->name);
    for (const char *at = strstr(text, c->name); at; at = strstr(at + n, c->name))
        if (!(isalnum((unsigned char)at[n]) || at[n] == '_'))
            return 1;
    return 0;
}

/* "name(gtlab_in[Ku * i + 0u], ...)" */
static void call_text(const gpu_function_contract *c, char *out, size_t size)
{
    int at = snprintf(out, size, "%s(", c->name);
    for (int k = 0; k < c->inputs && at > 0 && (size_t)at < size; ++k)
        at += snprintf(out + at, size - (size_t)at, "%sgtlab_in[%du * i + %du]", k ? ", " : "", c->inputs, k);
    if (at > 0 && (size_t)at < size)
        snprintf(out + at, size - (size_t)at, ")");
}

char *gpu_function_wrap(const gpu_function_contract *c, const char *text, const char *path, gt_error *e)
{
    int glsl = gpu_source_language_of(path) == GPU_SOURCE_GLSL;
    if (!gpu_function_defines(c, text))
        return gt_error_set(e, path, "defines no %s (the contract: %s; docs/shaders.md)", c->name, c->signature), NULL;
    if (glsl && has_version_line(text))
        return gt_error_set(e, path, "a function file has no #version line (gtlab writes #version 450)"), NULL;
    char call[256], main_text[sizeof kGlslMain + sizeof kHlslMain + sizeof call], *source = NULL;
    call_text(c, call, sizeof call);
    snprintf(main_text, sizeof main_text, glsl ? kGlslMain : kHlslMain, GPU_SAMPLE_GROUP, call);
    if (asprintf(&source, "%s%s%s", glsl ? kGlslHead : "", text, main_text) < 0)
        return gt_error_set(e, path, "out of memory"), NULL;
    return source;
}

/* A NaN or infinity found by the dispatch ("... NaN in output outputs at
 * element I", "infinity in output") as the sample that gave it: -1 with e
 * rewritten, 0 for any other error. */
static int name_nan(const gpu_function_contract *c, const char *path, const float *in, size_t offset, gt_error *e)
{
    const char *infinite = strstr(e->message, "infinity in output");
    const char *at = infinite ? infinite : strstr(e->message, "NaN in output");
    const char *element = at ? strstr(at, "at element ") : NULL;
    if (!element)
        return 0;
    size_t i = offset + (size_t)strtoull(element + strlen("at element "), NULL, 10);
    char args[GPU_FUNCTION_MAX_INPUTS * 24] = "";
    for (int k = 0, n = 0; k < c->inputs && k < GPU_FUNCTION_MAX_INPUTS; ++k)
        n += snprintf(args + n, sizeof args - (size_t)n, "%s%.9g", k ? ", " : "",
                      (double)in[(size_t)c->inputs * i + (size_t)k]);
    return gt_error_set(e, path, "%s(%s) is %s", c->name, args, infinite ? "infinite" : "NaN");
}

/* A compile error shaderc places past the file's last line is in the
 * wrapper's call: the file's function does not have the contract's signature. */
static void name_signature_error(const gpu_function_contract *c, const char *text, const char *path, gt_error *e)
{
    size_t n = strlen(path);
    if (strncmp(e->message, path, n) != 0 || e->message[n] != ':')
        return;
    char *end;
    long line = strtol(e->message + n + 1, &end, 10), lines = 1;
    for (const char *c = text; *c; ++c)
        lines += *c == '\n' && c[1] != '\0';
    if (end == e->message + n + 1 || strncmp(end, ": error: ", 9) != 0 || line <= lines)
        return;
    char shaderc[sizeof e->message];
    snprintf(shaderc, sizeof shaderc, "%s", end + 9);
    gt_error_set(e, path, "gtlab cannot call %s (the contract's signature, docs/shaders.md): %s", c->signature,
                 shaderc);
}

int gpu_function_load(const gpu_function_contract *c, const char *path, char **text, gt_error *e)
{
    if (gpu_read_source(path, text, e) != 0)
        return -1;
    char *wrapped = gpu_function_wrap(c, *text, path, e);
    free(wrapped);
    if (wrapped)
        return 0;
    free(*text);
    *text = NULL;
    return -1;
}

int gpu_function_eval(gpu_device *device, const gpu_function_contract *c, const char *text, const char *path,
                      const float *in, float *out, size_t count, double timeout, gt_error *e)
{
    char *source = gpu_function_wrap(c, text, path, e);
    if (!source)
        return -1;
    const size_t chunk = (size_t)GPU_SAMPLE_GROUP * 65535u;
    int rc = 0;
    for (size_t first = 0; first < count && rc == 0; first += chunk) {
        size_t n = count - first < chunk ? count - first : chunk;
        rc = gpu_sample_map(device, source, path, NULL, in + (size_t)c->inputs * first, c->inputs, out + first, 1, n,
                            timeout, e);
        if (rc != 0 && name_nan(c, path, in, first, e) == 0)
            name_signature_error(c, text, path, e);
    }
    free(source);
    return rc;
}

/* The arguments of the masked pixels, c->inputs floats each, in pixel order; their count into *count. */
static float *pack_masked(const gpu_function_contract *c, const float *const planes[], const float constants[],
                          const float *mask, size_t n, size_t *count)
{
    float *args = malloc((size_t)c->inputs * (n ? n : 1) * sizeof *args);
    *count = 0;
    for (size_t p = 0; args && p < n; ++p) {
        if (mask[p] == 0.0f)
            continue;
        for (int k = 0; k < c->inputs; ++k)
            args[(size_t)c->inputs * *count + (size_t)k] = planes[k] ? planes[k][p] : constants[k];
        ++*count;
    }
    return args;
}

int gpu_function_eval_masked(gpu_device *device, const gpu_function_contract *c, const char *text, const char *path,
                             const float *const planes[], const float constants[], const float *mask, size_t n,
                             float *out, double timeout, gt_error *e)
{
    size_t count;
    float *args = pack_masked(c, planes, constants, mask, n, &count), *values = malloc((n ? n : 1) * sizeof *values);
    int rc = !args || !values ? gt_error_set(e, path, "out of memory")
             : count == 0     ? 0
                              : gpu_function_eval(device, c, text, path, args, values, count, timeout, e);
    for (size_t p = 0, j = 0; rc == 0 && p < n; ++p)
        out[p] = mask[p] != 0.0f ? values[j++] : 0.0f;
    free(args), free(values);
    return rc;
}
