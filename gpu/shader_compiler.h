/* GLSL or HLSL to SPIR-V, through shaderc's C API (Google's glslang front
 * ends behind one call, shaderc_compile_into_spv). gtlab writes no SPIR-V
 * itself: a shader is text, compiled here for Vulkan 1.1 as a compute
 * shader. Errors keep shaderc's own words and line number: the one line
 * "<name>:<line>: error: <shaderc's message>". glslang crashes on some
 * malformed source, so every compilation runs in a child process
 * (core/isolated_call.h): a crash there is the error "<name>: the shader
 * compiler crashed on this source (glslang, signal 11, ...)", not gtlab's. */
#ifndef GTLAB_GPU_SHADER_COMPILER_H
#define GTLAB_GPU_SHADER_COMPILER_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"

typedef enum { GPU_SOURCE_GLSL, GPU_SOURCE_HLSL } gpu_source_language;

/* The language a file's name says: ".hlsl" (any case) is HLSL, anything
 * else GLSL (".glsl", ".comp"). */
gpu_source_language gpu_source_language_of(const char *path);

/* A compiled compute shader: SPIR-V words and the entry point's name in them. */
typedef struct {
    uint32_t *words;
    size_t count;
    char entry[64];
} gpu_spirv;

/* Compiles `source` (named `name` in messages) as a compute shader with the
 * entry point `entry` (NULL: "main"; GLSL's entry point is always main, so
 * another name is an error there). `#include "f"` (or <f>) reads the file f
 * beside the including one (name's directory for the top file), in both
 * languages; a missing file is a compile error naming the line. Returns 0, or -1 with e set and *out
 * empty. */
int gpu_compile_compute(const char *source, const char *name, gpu_source_language language, const char *entry,
                        gpu_spirv *out, gt_error *e);

/* The first error line of a compiler log ("f.glsl:12: error: ..."), into e
 * as "<f.glsl:12>: error: ...": the part before ": error" is the subject.
 * Exposed for the tests; returns -1. */
int gpu_compile_error_line(const char *log, const char *name, gt_error *e);

void gpu_spirv_free(gpu_spirv *spirv);

/* A shader file's text (malloc'd, NUL-terminated). Returns 0, or -1 with
 * e = "<path>: <problem>" (unreadable, larger than 4 MiB, a NUL byte). */
int gpu_read_source(const char *path, char **text, gt_error *e);

#endif
