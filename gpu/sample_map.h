/* A function evaluated by a compute shader at many input points: the shape
 * every per-sample comparison of a shader with gtlab's C takes (its
 * generated multi-bounce and sphere-light functions, a user's function).
 *
 * The shader's bindings (gpu/compute_dispatch.h's contract):
 *   binding 0   uniform { uint count; }          the number of samples
 *   binding 1   float inputs[count * in_stride]  sample i's inputs at i * in_stride
 *   binding 2   float outputs[count * out_stride]
 * in workgroups of GPU_SAMPLE_GROUP invocations along x, one per sample
 * (invocations at or past count must return). */
#ifndef GTLAB_GPU_SAMPLE_MAP_H
#define GTLAB_GPU_SAMPLE_MAP_H

#include <stddef.h>

#include "core/error.h"
#include "gpu/shader_compiler.h"
#include "gpu/vulkan_device.h"

#define GPU_SAMPLE_GROUP 64

/* Compiles source (the language by name's extension) and runs it over
 * `count` samples. Returns 0, or -1 with e set (compile error, timeout,
 * NaN, too many samples for one dispatch). */
int gpu_sample_map(gpu_device *device, const char *source, const char *name, const char *entry, const float *in,
                   int in_stride, float *out, int out_stride, size_t count, double timeout, gt_error *e);

#endif
