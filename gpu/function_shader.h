/* The per-sample function contract (issue 15, item 3; docs/shaders.md): a
 * user writes only the function gtlab scores, in GLSL or HLSL, e.g.
 *
 *   float gtlab_multibounce(float visibility, float albedo)   V'_d(V_d, rho)
 *
 * (the quantity of core/plugin_abi.h's gtlab_multibounce_v1, one sample at a
 * time; helpers of its own may precede it). gtlab wraps the file into a
 * compute shader of gpu/sample_map.h's contract — one invocation per sample,
 * sample i's inputs at in[2i], in[2i + 1], its value at out[i] — and runs it.
 * Specular occlusion has its own function (gpu_function_specular_occlusion
 * below), wrapped the same way.
 *
 * GLSL files have no #version line: the wrapper writes `#version 450` and
 * `#line 1` before the file, so shaderc's line numbers are the file's. HLSL
 * files are used as written, the wrapper after them. Names starting with
 * gtlab_ are the wrapper's. */
#ifndef GTLAB_GPU_FUNCTION_SHADER_H
#define GTLAB_GPU_FUNCTION_SHADER_H

#include <stddef.h>

#include "core/error.h"
#include "gpu/vulkan_device.h"

/* A quantity's function: its name, its signature as the user writes it,
 * and its number of float arguments (sample i's at in[inputs * i + k]). */
typedef struct {
    const char *name;
    const char *signature;
    int inputs;
} gpu_function_contract;

enum { GPU_FUNCTION_MAX_INPUTS = 4 };

/* float gtlab_multibounce(float visibility, float albedo): V'_d(V_d, rho). */
extern const gpu_function_contract gpu_function_multibounce;
/* float gtlab_specular_occlusion(float ao, float beta, float roughness, float n_dot_v): V_s from the cosine AO,
 * the angle between the bent normal and the reflection vector, the perceptual roughness and n.v
 * (specular_occlusion/specular_occlusion_screen.h's per-pixel inputs). */
extern const gpu_function_contract gpu_function_specular_occlusion;

/* Whether `text` names contract c's function (a file may implement several quantities). */
int gpu_function_defines(const gpu_function_contract *c, const char *text);

/* The compute shader wrapping `text`, the function file `path` (language by
 * its extension), malloc'd. NULL with e: the file defines no c->name, has a
 * #version line (GLSL), out of memory. */
char *gpu_function_wrap(const gpu_function_contract *c, const char *text, const char *path, gt_error *e);

/* The function file's text into *text (malloc'd), checked against contract c
 * (gpu_function_wrap) before any work. Returns 0, or -1 with e. */
int gpu_function_load(const gpu_function_contract *c, const char *path, char **text, gt_error *e);

/* out[i] = c->name(in[c->inputs i + 0], ...), i < count, in as many
 * dispatches as gpu/sample_map.h allows. Returns 0, or -1 with e: a compile
 * error (shaderc's "<path>:<line>: error: ..."), a device timeout, or
 * "<path>: gtlab_multibounce(<v>, <rho>) is NaN" (or "is infinite"; the
 * sample's inputs). */
int gpu_function_eval(gpu_device *device, const gpu_function_contract *c, const char *text, const char *path,
                      const float *in, float *out, size_t count, double timeout, gt_error *e);

/* The function at the n pixels with mask[p] != 0, 0 elsewhere: its
 * argument k is planes[k][p], or constants[k] where planes[k] is NULL.
 * Returns 0, or -1 with e (gpu_function_eval's errors, out of memory). */
int gpu_function_eval_masked(gpu_device *device, const gpu_function_contract *c, const char *text, const char *path,
                             const float *const planes[], const float constants[], const float *mask, size_t n,
                             float *out, double timeout, gt_error *e);

#endif
