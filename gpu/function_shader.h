/* The per-sample function contract (issue 15, item 3; docs/shaders.md): a
 * user writes only the function gtlab scores, in GLSL or HLSL, e.g.
 *
 *   float gtlab_multibounce(float visibility, float albedo)   V'_d(V_d, rho)
 *
 * (the quantity of core/plugin_abi.h's gtlab_multibounce_v1, one sample at a
 * time; helpers of its own may precede it). gtlab wraps the file into a
 * compute shader of gpu/sample_map.h's contract — one invocation per sample,
 * sample i's inputs at in[2i], in[2i + 1], its value at out[i] — and runs it.
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

#define GPU_FUNCTION_MULTIBOUNCE "gtlab_multibounce" /* float (float visibility, float albedo) */

/* The compute shader wrapping `text`, the function file `path` (language by
 * its extension), malloc'd. NULL with e: the file defines no
 * GPU_FUNCTION_MULTIBOUNCE, has a #version line (GLSL), out of memory. */
char *gpu_function_wrap(const char *text, const char *path, gt_error *e);

/* out[i] = gtlab_multibounce(in[2i], in[2i + 1]), i < count, in as many
 * dispatches as gpu/sample_map.h allows. Returns 0, or -1 with e: a compile
 * error (shaderc's "<path>:<line>: error: ..."), a device timeout, or
 * "<path>: gtlab_multibounce(<v>, <rho>) is NaN". */
int gpu_function_eval(gpu_device *device, const char *text, const char *path, const float *in, float *out,
                      size_t count, double timeout, gt_error *e);

#endif
