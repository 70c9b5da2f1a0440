/* A sampled 2-D texture of floats and a point, clamp-to-edge sampler for
 * gpu/compute_dispatch.c (the GPU_TEXTURE_* and GPU_SAMPLER_* bindings of
 * gpu/compute_dispatch.h). gpu/'s own: it needs the Vulkan handles.
 *
 * The texture is a VK_FORMAT_R32_SFLOAT image, optimal tiling, one mip
 * level, uploaded once: the floats into a host-visible staging buffer, then
 * one command buffer moves the image UNDEFINED -> TRANSFER_DST_OPTIMAL,
 * copies the buffer into it and moves it -> SHADER_READ_ONLY_OPTIMAL for
 * the compute stage; the staging buffer is freed when the copy is done. */
#ifndef GTLAB_GPU_SAMPLED_TEXTURE_H
#define GTLAB_GPU_SAMPLED_TEXTURE_H

#include "core/error.h"
#include "gpu/compute_dispatch.h"
#include "gpu/vulkan_device_handles.h"

typedef struct {
    VkImage image;
    VkDeviceMemory memory;
    VkImageView view;
} gpu_texture;

/* A memory type allowed by bits with every flag of `want`, or -1. */
int gpu_memory_type(const gpu_device *g, uint32_t bits, VkMemoryPropertyFlags want);

/* The texture of b (kind GPU_TEXTURE_R32F or GPU_TEXTURE_R32F_POINT_CLAMP,
 * data a gpu_texture_r32f), uploaded and ready to sample. Returns 0, or -1 with e set ("<what>: ..." naming b). */
int gpu_texture_create(gpu_device *g, const gpu_buffer *b, const char *what, gpu_texture *t, gt_error *e);

/* Nearest filtering, clamp to edge in u and v, normalised coordinates,
 * level 0 only. */
int gpu_point_clamp_sampler(gpu_device *g, const char *what, VkSampler *out, gt_error *e);

void gpu_texture_destroy(gpu_device *g, gpu_texture *t); /* null handles: nothing */

#endif
