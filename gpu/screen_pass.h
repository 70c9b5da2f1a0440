/* The binding contract of a screen-space shader (docs/shaders.md; template
 * shaders/template_screen_space.glsl): one invocation per pixel, workgroups
 * of 8 x 8 (local_size_x = local_size_y = 8), descriptor set 0:
 *   binding 0  uniform Gtlab (std140): the camera, the image size, the frame
 *              (gpu_screen_globals below, member for member)
 *   binding 1  uniform Params: the shader's gtlab.param floats, in order
 *              (gpu/shader_interface.h)
 *   binding 2  readonly storage buffer float gbuffer[]: GPU_GB_CHANNELS
 *              planes of width x height floats, plane c at c * width * height,
 *              pixel (x, y) (y down) at y * width + x; a channel the EXR lacks
 *              is zeros and its bit (1 << c) of Gtlab.present is clear
 *   binding 3  storage buffer float outputs[]: the shader's gtlab.output
 *              planes, plane k at k * width * height
 * Frames 0 .. frames-1 are dispatched in turn (Gtlab.frame), each into
 * zeroed outputs, and the output is their mean: a static camera's temporal
 * accumulation. */
#ifndef GTLAB_GPU_SCREEN_PASS_H
#define GTLAB_GPU_SCREEN_PASS_H

#include <stdint.h>

#include "core/error.h"
#include "core/image.h"
#include "gpu/shader_compiler.h"
#include "gpu/vulkan_device.h"

#define GPU_SCREEN_GROUP 8

/* The G-buffer planes, in binding 2's order. */
typedef enum {
    GPU_GB_DEPTH,  /* depth.Z: distance along the camera axis */
    GPU_GB_N_X,    /* N.X, N.Y, N.Z: world-space shading normal */
    GPU_GB_N_Y,
    GPU_GB_N_Z,
    GPU_GB_P_X,    /* P.X, P.Y, P.Z: world-space position */
    GPU_GB_P_Y,
    GPU_GB_P_Z,
    GPU_GB_ALBEDO_R, /* albedo.R, .G, .B */
    GPU_GB_ALBEDO_G,
    GPU_GB_ALBEDO_B,
    GPU_GB_ROUGHNESS, /* roughness.Y: perceptual */
    GPU_GB_MASK,   /* mask.A: 1 where a surface was hit */
    GPU_GB_BENT_X, /* bent.X, .Y, .Z: the AO reference's bent normal */
    GPU_GB_BENT_Y,
    GPU_GB_BENT_Z,
    GPU_GB_CHANNELS
} gpu_gbuffer_channel;

/* The EXR channel of each plane (core/reference_schema.h). */
extern const char *const gpu_gbuffer_channel_names[GPU_GB_CHANNELS];

/* Binding 0, std140 (80 bytes). View space as realtime/screen_space.h:
 * pixel (x, y) at depth d is d (sx, sy, -1), sx = (2 (x + 0.5) / width - 1)
 * tan_half_yfov aspect, sy = (1 - 2 (y + 0.5) / height) tan_half_yfov. */
typedef struct {
    float right[4], up[4], forward[4]; /* world-space camera basis (w unused) */
    float tan_half_yfov, aspect;
    int32_t width, height;
    int32_t frame, frames;
    int32_t present; /* bit c: G-buffer plane c came from the EXR */
    int32_t reserved;
} gpu_screen_globals;

typedef struct {
    gpu_screen_globals globals; /* frame is set per dispatch */
    const float *planes[GPU_GB_CHANNELS]; /* width x height each; NULL: absent */
} gpu_screen_input;

/* Points in->planes at img's channels (the present bits with them) and sets
 * the size; depth.Z, N.X/Y/Z and mask.A are required. The camera is the
 * caller's. Returns 0, or -1 with e = "<what>: missing channel ...". */
int gpu_screen_input_from_image(const image *img, const char *what, gpu_screen_input *in, gt_error *e);

/* Runs the shader over in->globals.frames frames and writes the mean of
 * its `outputs` planes to out (outputs x width x height floats). Returns 0,
 * or -1 with e set (nothing useful in out). seconds (may be NULL): the
 * device's wall time per frame, the mean over the frames. */
int gpu_screen_pass(gpu_device *device, const gpu_spirv *shader, const char *what, const gpu_screen_input *in,
                    const float *params, int param_count, int outputs, float *out, double timeout, double *seconds,
                    gt_error *e);

/* Where a pass's time goes (gpu_screen_pass_timed). */
typedef struct {
    double setup_seconds;    /* once: packing the G-buffer, buffers and their upload, pipeline, descriptor set */
    double frame_seconds;    /* per frame (mean): the Gtlab block and the cleared outputs uploaded, the
                                dispatch, the read-back, the NaN check, the accumulation */
    double dispatch_seconds; /* per frame (mean): the device's wall time, submission to fence */
} gpu_screen_timing;

/* gpu_screen_pass, its time measured into *timing. */
int gpu_screen_pass_timed(gpu_device *device, const gpu_spirv *shader, const char *what, const gpu_screen_input *in,
                          const float *params, int param_count, int outputs, float *out, double timeout,
                          gpu_screen_timing *timing, gt_error *e);

#endif
