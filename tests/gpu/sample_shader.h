/* The compute shader that wraps generated functions for gpu/sample_map.h
 * (its bindings: count, inputs v[], outputs r[]): `functions`, then `body`
 * once per sample i < count. Shared by the tests that run gtlab's generated
 * GLSL and HLSL against the C (techniques/multibounce/tests/test_multibounce_gpu.c,
 * techniques/specular_occlusion/tests/test_gpu_specular_occlusion.c). */
#ifndef GTLAB_TESTS_GPU_SAMPLE_SHADER_H
#define GTLAB_TESTS_GPU_SAMPLE_SHADER_H

#include <stdio.h>

#include "gpu/sample_map.h"
#include "realtime/shader_language.h"

/* The source (malloc'd; NULL if out of memory). */
static inline char *test_sample_shader(shader_language language, const char *functions, const char *body)
{
    char *text = NULL;
    int rc = language == SHADER_GLSL
                 ? asprintf(&text,
                            "#version 450\n%s\nlayout(local_size_x = %d) in;\n"
                            "layout(std140, binding = 0) uniform Params { uint count; };\n"
                            "layout(std430, binding = 1) readonly buffer In { float v[]; };\n"
                            "layout(std430, binding = 2) writeonly buffer Out { float r[]; };\n"
                            "void main()\n{\n    uint i = gl_GlobalInvocationID.x;\n    if (i >= count)\n"
                            "        return;\n%s}\n",
                            functions, GPU_SAMPLE_GROUP, body)
                 : asprintf(&text,
                            "%s\n[[vk::binding(0)]] cbuffer Params { uint count; };\n"
                            "[[vk::binding(1)]] StructuredBuffer<float> v;\n"
                            "[[vk::binding(2)]] RWStructuredBuffer<float> r;\n"
                            "[numthreads(%d, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID)\n{\n"
                            "    uint i = id.x;\n    if (i >= count)\n        return;\n%s}\n",
                            functions, GPU_SAMPLE_GROUP, body);
    return rc < 0 ? NULL : text;
}

#endif
