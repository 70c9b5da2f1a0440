#include "gpu/sample_map.h"

#include <stdint.h>

#include "gpu/compute_dispatch.h"

enum { MAX_GROUPS = 65535 }; /* Vulkan's guaranteed maxComputeWorkGroupCount */

int gpu_sample_map(gpu_device *device, const char *source, const char *name, const char *entry, const float *in,
                   int in_stride, float *out, int out_stride, size_t count, double timeout, gt_error *e)
{
    size_t groups = (count + GPU_SAMPLE_GROUP - 1) / GPU_SAMPLE_GROUP;
    if (count == 0 || groups > MAX_GROUPS || in_stride <= 0 || out_stride <= 0)
        return gt_error_set(e, name, "%zu samples: one dispatch takes 1 to %d", count, MAX_GROUPS * GPU_SAMPLE_GROUP);
    gpu_spirv spirv;
    if (gpu_compile_compute(source, name, gpu_source_language_of(name), entry, &spirv, e) != 0)
        return -1;
    uint32_t params[4] = {(uint32_t)count, 0, 0, 0}; /* std140: a 16-byte block */
    gpu_buffer buffers[3] = {{"count", GPU_UNIFORM, params, sizeof params},
                             {"inputs", GPU_INPUT, (void *)in, count * (size_t)in_stride * sizeof(float)},
                             {"outputs", GPU_OUTPUT, out, count * (size_t)out_stride * sizeof(float)}};
    gpu_dispatch d = {&spirv, name, buffers, 3, {(uint32_t)groups, 1, 1}, timeout};
    int rc = gpu_dispatch_run(device, &d, NULL, e);
    gpu_spirv_free(&spirv);
    return rc;
}
