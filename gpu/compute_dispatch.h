/* One compute dispatch on a gpu_device: the shader's buffers copied in,
 * the outputs cleared to zeros, one vkCmdDispatch, a fence waited for with
 * a time limit, the output buffers copied back and checked for NaN.
 *
 * Buffer k is binding k of descriptor set 0: a uniform block (std140) or a
 * storage buffer (std430). A GLSL shader declares them as
 *   layout(std140, binding = 0) uniform Params { ... };
 *   layout(std430, binding = 1) readonly buffer In { float x[]; };
 * and an HLSL one as
 *   [[vk::binding(0)]] cbuffer Params { ... };
 *   [[vk::binding(1)]] StructuredBuffer<float> x;  (RWStructuredBuffer for outputs).
 *
 * A binding may instead be a sampled 2-D texture of width x height floats
 * (gpu_texture_r32f: VK_FORMAT_R32_SFLOAT, uploaded once through a staging
 * buffer, left as uploaded by every frame) or a sampler: nearest filtering (magnification and
 * minification, one mip level), clamp to edge in u and v, normalised
 * coordinates, the point sampling tables like the best-fit normals' are
 * read with. HLSL declares the two apart,
 *   [[vk::binding(3)]] Texture2D<float> t;  [[vk::binding(4)]] SamplerState s;
 * (GPU_TEXTURE_R32F and GPU_SAMPLER_POINT_CLAMP), GLSL as one
 *   layout(binding = 3) uniform sampler2D t;  (GPU_TEXTURE_R32F_POINT_CLAMP). */
#ifndef GTLAB_GPU_COMPUTE_DISPATCH_H
#define GTLAB_GPU_COMPUTE_DISPATCH_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"
#include "gpu/shader_compiler.h"
#include "gpu/vulkan_device.h"

typedef enum {
    GPU_UNIFORM, /* a uniform block, read by the shader */
    GPU_INPUT,   /* a storage buffer the shader reads */
    GPU_OUTPUT,  /* a storage buffer read back after the dispatch; its floats must not be NaN */
    GPU_TEXTURE_R32F,             /* a sampled image (HLSL Texture2D<float>): data is a gpu_texture_r32f */
    GPU_SAMPLER_POINT_CLAMP,      /* a sampler (HLSL SamplerState): no data, size 0 */
    GPU_TEXTURE_R32F_POINT_CLAMP  /* the two combined (GLSL sampler2D): data is a gpu_texture_r32f */
} gpu_buffer_kind;

typedef struct {
    const char *name; /* for messages, e.g. "ao" */
    gpu_buffer_kind kind;
    void *data;       /* size bytes: uploaded before the dispatch; an output (zeros on the device before
                         each dispatch: its data is not uploaded) is read back into it after */
    size_t size;      /* > 0 (a texture: sizeof(gpu_texture_r32f); a sampler: 0, data NULL) */
} gpu_buffer;

/* What a texture binding's data points at: row y of the texels at
 * texels[y * width], y = 0 at v = 0. */
typedef struct {
    int width, height;
    const float *texels;
} gpu_texture_r32f;

typedef struct {
    const gpu_spirv *shader;
    const char *what;     /* the shader's name in messages (its file) */
    gpu_buffer *buffers;  /* buffer k is binding k */
    int buffer_count;
    uint32_t groups[3];   /* workgroups dispatched in x, y, z */
    double timeout;       /* seconds the fence is waited for */
} gpu_dispatch;

/* Runs the dispatch. Returns 0, or -1 with e set: a binding the shader
 * declares that is not one of d's or not of its kind (gpu/spirv_bindings.h),
 * "<what>: device timeout
 * after <t> s" (the device is then left busy: gpu_device_close only forgets
 * it), "<what>: NaN in output <name> at element <i>" (or "infinity in
 * output": issue 41, an Inf reached the scores as DSSIM -nan; the outputs are
 * overwritten all the same: the caller writes nothing), a Vulkan failure.
 * seconds (may be NULL): wall time from submission to the fence. */
int gpu_dispatch_run(gpu_device *device, const gpu_dispatch *d, double *seconds, gt_error *e);

/* The same dispatch run frame after frame, built once: the buffers,
 * pipeline, descriptor set, command buffer and fence are made by
 * gpu_dispatch_open (which uploads every buffer's data); each
 * gpu_dispatch_frame uploads the uniform blocks from their data again (not
 * the inputs: they stay as uploaded), submits (the device clears the
 * outputs, then dispatches), waits and reads the outputs back, with
 * gpu_dispatch_run's errors. d and its buffers must outlive the session.
 * gpu_dispatch_run is open, one frame, close. */
typedef struct gpu_dispatch_session gpu_dispatch_session;
int gpu_dispatch_open(gpu_device *device, const gpu_dispatch *d, gpu_dispatch_session **out, gt_error *e);
int gpu_dispatch_frame(gpu_dispatch_session *s, double *seconds, gt_error *e);
void gpu_dispatch_close(gpu_dispatch_session *s); /* NULL: nothing */

/* The first NaN or infinity among count floats, or -1. */
long gpu_first_non_finite(const float *values, size_t count);

#endif
