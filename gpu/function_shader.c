/* The per-sample function contract's wrapper (gpu/function_shader.h). */
#define _GNU_SOURCE
#include "gpu/function_shader.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gpu/sample_map.h"
#include "gpu/shader_compiler.h"

static const char kGlslHead[] = "#version 450\n#line 1\n";
/* After the user's function; %d is GPU_SAMPLE_GROUP. */
static const char kGlslMain[] = "\nlayout(local_size_x = %d) in;\n"
                                "layout(std140, binding = 0) uniform GtlabCount { uint gtlab_count; };\n"
                                "layout(std430, binding = 1) readonly buffer GtlabIn { float gtlab_in[]; };\n"
                                "layout(std430, binding = 2) writeonly buffer GtlabOut { float gtlab_out[]; };\n"
                                "void main()\n{\n    uint i = gl_GlobalInvocationID.x;\n"
                                "    if (i < gtlab_count)\n"
                                "        gtlab_out[i] = gtlab_multibounce(gtlab_in[2u * i], gtlab_in[2u * i + 1u]);\n"
                                "}\n";
static const char kHlslMain[] = "\n[[vk::binding(0)]] cbuffer GtlabCount { uint gtlab_count; };\n"
                                "[[vk::binding(1)]] StructuredBuffer<float> gtlab_in;\n"
                                "[[vk::binding(2)]] RWStructuredBuffer<float> gtlab_out;\n"
                                "[numthreads(%d, 1, 1)]\nvoid main(uint3 gtlab_id : SV_DispatchThreadID)\n{\n"
                                "    uint i = gtlab_id.x;\n    if (i < gtlab_count)\n"
                                "        gtlab_out[i] = gtlab_multibounce(gtlab_in[2u * i], gtlab_in[2u * i + 1u]);\n"
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

char *gpu_function_wrap(const char *text, const char *path, gt_error *e)
{
    int glsl = gpu_source_language_of(path) == GPU_SOURCE_GLSL;
    if (!strstr(text, GPU_FUNCTION_MULTIBOUNCE))
        return gt_error_set(e, path, "defines no %s (the contract: float %s(float visibility, float albedo); "
                            "docs/shaders.md)", GPU_FUNCTION_MULTIBOUNCE, GPU_FUNCTION_MULTIBOUNCE), NULL;
    if (glsl && has_version_line(text))
        return gt_error_set(e, path, "a function file has no #version line (gtlab writes #version 450)"), NULL;
    char main_text[sizeof kGlslMain + sizeof kHlslMain], *source = NULL;
    snprintf(main_text, sizeof main_text, glsl ? kGlslMain : kHlslMain, GPU_SAMPLE_GROUP);
    if (asprintf(&source, "%s%s%s", glsl ? kGlslHead : "", text, main_text) < 0)
        return gt_error_set(e, path, "out of memory"), NULL;
    return source;
}

/* A NaN found by the dispatch ("... NaN in output outputs at element I") as
 * the sample that gave it: -1 with e rewritten, 0 for any other error. */
static int name_nan(const char *path, const float *in, size_t offset, gt_error *e)
{
    const char *at = strstr(e->message, "NaN in output");
    const char *element = at ? strstr(at, "at element ") : NULL;
    if (!element)
        return 0;
    size_t i = offset + (size_t)strtoull(element + strlen("at element "), NULL, 10);
    return gt_error_set(e, path, "%s(%.9g, %.9g) is NaN", GPU_FUNCTION_MULTIBOUNCE, (double)in[2 * i],
                        (double)in[2 * i + 1]);
}

/* A compile error shaderc places past the file's last line is in the
 * wrapper's call: the file's function does not have the contract's signature. */
static void name_signature_error(const char *text, const char *path, gt_error *e)
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
    gt_error_set(e, path, "gtlab cannot call float %s(float visibility, float albedo) (the contract's signature, "
                 "docs/shaders.md): %s", GPU_FUNCTION_MULTIBOUNCE, shaderc);
}

int gpu_function_eval(gpu_device *device, const char *text, const char *path, const float *in, float *out,
                      size_t count, double timeout, gt_error *e)
{
    char *source = gpu_function_wrap(text, path, e);
    if (!source)
        return -1;
    const size_t chunk = (size_t)GPU_SAMPLE_GROUP * 65535u;
    int rc = 0;
    for (size_t first = 0; first < count && rc == 0; first += chunk) {
        size_t n = count - first < chunk ? count - first : chunk;
        rc = gpu_sample_map(device, source, path, NULL, in + 2 * first, 2, out + first, 1, n, timeout, e);
        if (rc != 0 && name_nan(path, in, first, e) == 0)
            name_signature_error(text, path, e);
    }
    free(source);
    return rc;
}
