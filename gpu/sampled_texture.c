#include "gpu/sampled_texture.h"

#include <string.h>

int gpu_memory_type(const gpu_device *g, uint32_t bits, VkMemoryPropertyFlags want)
{
    for (uint32_t i = 0; i < g->memory.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (g->memory.memoryTypes[i].propertyFlags & want) == want)
            return (int)i;
    return -1;
}

/* Memory of a type allowed by req with `want` (else any allowed) bound
 * by the caller. */
static int allocate(gpu_device *g, const VkMemoryRequirements *req, VkMemoryPropertyFlags want, VkDeviceMemory *m)
{
    int type = gpu_memory_type(g, req->memoryTypeBits, want);
    if (type < 0 && !(want & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT))
        type = gpu_memory_type(g, req->memoryTypeBits, 0);
    VkMemoryAllocateInfo alloc = {.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                                  .allocationSize = req->size,
                                  .memoryTypeIndex = (uint32_t)type};
    return type >= 0 && vkAllocateMemory(g->device, &alloc, NULL, m) == VK_SUCCESS ? 0 : -1;
}

/* A host-visible buffer holding b's floats, the copy's source. */
static int make_staging(gpu_device *g, const gpu_texture_r32f *b, VkBuffer *buffer, VkDeviceMemory *memory)
{
    size_t size = (size_t)b->width * (size_t)b->height * sizeof(float);
    VkBufferCreateInfo info = {.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                               .size = size,
                               .usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                               .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
    VkMemoryRequirements req;
    void *mapped;
    if (vkCreateBuffer(g->device, &info, NULL, buffer) != VK_SUCCESS)
        return -1;
    vkGetBufferMemoryRequirements(g->device, *buffer, &req);
    if (allocate(g, &req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, memory) != 0 ||
        vkBindBufferMemory(g->device, *buffer, *memory, 0) != VK_SUCCESS ||
        vkMapMemory(g->device, *memory, 0, size, 0, &mapped) != VK_SUCCESS)
        return -1;
    memcpy(mapped, b->texels, size);
    vkUnmapMemory(g->device, *memory);
    return 0;
}

/* The image (R32_SFLOAT, sampled, copy destination) and its memory. */
static int make_image(gpu_device *g, const gpu_texture_r32f *b, gpu_texture *t)
{
    VkImageCreateInfo info = {.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                              .imageType = VK_IMAGE_TYPE_2D,
                              .format = VK_FORMAT_R32_SFLOAT,
                              .extent = {(uint32_t)b->width, (uint32_t)b->height, 1},
                              .mipLevels = 1,
                              .arrayLayers = 1,
                              .samples = VK_SAMPLE_COUNT_1_BIT,
                              .tiling = VK_IMAGE_TILING_OPTIMAL,
                              .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                              .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
                              .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
    VkMemoryRequirements req;
    if (vkCreateImage(g->device, &info, NULL, &t->image) != VK_SUCCESS)
        return -1;
    vkGetImageMemoryRequirements(g->device, t->image, &req);
    return allocate(g, &req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, &t->memory) == 0 &&
                   vkBindImageMemory(g->device, t->image, t->memory, 0) == VK_SUCCESS
               ? 0
               : -1;
}

/* A layout transition of the whole image as one barrier. */
static void transition(VkCommandBuffer c, VkImage image, VkImageLayout from, VkImageLayout to, VkAccessFlags src,
                       VkAccessFlags dst, VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage)
{
    VkImageMemoryBarrier barrier = {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
                                    .srcAccessMask = src,
                                    .dstAccessMask = dst,
                                    .oldLayout = from,
                                    .newLayout = to,
                                    .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                    .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                    .image = image,
                                    .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
    vkCmdPipelineBarrier(c, src_stage, dst_stage, 0, 0, NULL, 0, NULL, 1, &barrier);
}

/* The transitions and the copy, recorded into c. */
static void record_upload(VkCommandBuffer c, VkBuffer staging, const gpu_texture_r32f *b, VkImage image)
{
    VkBufferImageCopy region = {.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                .imageExtent = {(uint32_t)b->width, (uint32_t)b->height, 1}};
    transition(c, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    vkCmdCopyBufferToImage(c, staging, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    transition(c, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
}

/* One command buffer with the upload, submitted and waited for. */
static int submit_upload(gpu_device *g, VkBuffer staging, const gpu_texture_r32f *b, VkImage image)
{
    VkCommandBufferAllocateInfo alloc = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                         .commandPool = g->pool,
                                         .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                         .commandBufferCount = 1};
    VkCommandBufferBeginInfo begin = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                      .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VkCommandBuffer c = VK_NULL_HANDLE;
    if (vkAllocateCommandBuffers(g->device, &alloc, &c) != VK_SUCCESS)
        return -1;
    int ok = vkBeginCommandBuffer(c, &begin) == VK_SUCCESS;
    if (ok)
        record_upload(c, staging, b, image);
    VkSubmitInfo submit = {.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &c};
    ok = ok && vkEndCommandBuffer(c) == VK_SUCCESS &&
         vkQueueSubmit(g->queue, 1, &submit, VK_NULL_HANDLE) == VK_SUCCESS && vkQueueWaitIdle(g->queue) == VK_SUCCESS;
    vkFreeCommandBuffers(g->device, g->pool, 1, &c);
    return ok ? 0 : -1;
}

static int make_view(gpu_device *g, gpu_texture *t)
{
    VkImageViewCreateInfo info = {.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                  .image = t->image,
                                  .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                  .format = VK_FORMAT_R32_SFLOAT,
                                  .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
    return vkCreateImageView(g->device, &info, NULL, &t->view) == VK_SUCCESS ? 0 : -1;
}

int gpu_texture_create(gpu_device *g, const gpu_buffer *binding, const char *what, gpu_texture *t, gt_error *e)
{
    const gpu_texture_r32f *b = binding->data;
    memset(t, 0, sizeof *t);
    if (!b || binding->size != sizeof *b || b->width <= 0 || b->height <= 0 || !b->texels)
        return gt_error_set(e, what, "texture %s: want a gpu_texture_r32f of width, height > 0 with texels",
                            binding->name);
    VkBuffer staging = VK_NULL_HANDLE;
    VkDeviceMemory staging_memory = VK_NULL_HANDLE;
    int rc = make_image(g, b, t) == 0 && make_staging(g, b, &staging, &staging_memory) == 0 &&
                     submit_upload(g, staging, b, t->image) == 0 && make_view(g, t) == 0
                 ? 0
                 : -1;
    vkDestroyBuffer(g->device, staging, NULL);
    vkFreeMemory(g->device, staging_memory, NULL);
    return rc == 0 ? 0 : gt_error_set(e, what, "cannot create or upload the %d x %d texture %s", b->width, b->height,
                                      binding->name);
}

int gpu_point_clamp_sampler(gpu_device *g, const char *what, VkSampler *out, gt_error *e)
{
    VkSamplerCreateInfo info = {.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                                .magFilter = VK_FILTER_NEAREST,
                                .minFilter = VK_FILTER_NEAREST,
                                .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                .maxLod = 0.0f};
    return vkCreateSampler(g->device, &info, NULL, out) == VK_SUCCESS
               ? 0
               : gt_error_set(e, what, "cannot create the point, clamp-to-edge sampler");
}

void gpu_texture_destroy(gpu_device *g, gpu_texture *t)
{
    vkDestroyImageView(g->device, t->view, NULL);
    vkDestroyImage(g->device, t->image, NULL);
    vkFreeMemory(g->device, t->memory, NULL);
}
