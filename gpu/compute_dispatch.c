#define _POSIX_C_SOURCE 199309L
#include "gpu/compute_dispatch.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "gpu/sampled_texture.h"
#include "gpu/spirv_bindings.h"
#include "gpu/vulkan_device_handles.h"

enum { MAX_BINDINGS = 32 };

/* Everything one dispatch creates, released together. */
typedef struct {
    VkBuffer buffer[MAX_BINDINGS];
    VkDeviceMemory memory[MAX_BINDINGS];
    gpu_texture texture[MAX_BINDINGS]; /* the texture kinds' */
    VkSampler sampler[MAX_BINDINGS];   /* the sampler kinds' */
    VkDescriptorSetLayout set_layout;
    VkPipelineLayout layout;
    VkShaderModule module;
    VkPipeline pipeline;
    VkDescriptorPool pool;
    VkDescriptorSet set;
    VkCommandBuffer commands;
    VkFence fence;
} dispatch_objects;

/* A host-visible, coherent memory type allowed by bits, or -1. */
static int host_memory_type(const gpu_device *g, uint32_t bits)
{
    return gpu_memory_type(g, bits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
}

static VkDescriptorType descriptor_type(gpu_buffer_kind kind)
{
    switch (kind) {
    case GPU_UNIFORM: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case GPU_TEXTURE_R32F: return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case GPU_SAMPLER_POINT_CLAMP: return VK_DESCRIPTOR_TYPE_SAMPLER;
    case GPU_TEXTURE_R32F_POINT_CLAMP: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    default: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    }
}

/* What the shader must declare at a binding of this kind. */
static gpu_declared_kind declared_kind(gpu_buffer_kind kind)
{
    switch (kind) {
    case GPU_UNIFORM: return GPU_DECLARED_UNIFORM;
    case GPU_TEXTURE_R32F: return GPU_DECLARED_SAMPLED_IMAGE;
    case GPU_SAMPLER_POINT_CLAMP: return GPU_DECLARED_SAMPLER;
    case GPU_TEXTURE_R32F_POINT_CLAMP: return GPU_DECLARED_COMBINED_IMAGE_SAMPLER;
    default: return GPU_DECLARED_STORAGE;
    }
}

/* A texture or sampler binding's objects in place of a buffer. */
static int make_image_binding(gpu_device *g, dispatch_objects *o, int k, const gpu_buffer *b, const char *what,
                              gt_error *e)
{
    if (b->kind == GPU_TEXTURE_R32F)
        return gpu_texture_create(g, b, what, &o->texture[k], e);
    if (b->kind == GPU_SAMPLER_POINT_CLAMP)
        return gpu_point_clamp_sampler(g, what, &o->sampler[k], e);
    return gpu_texture_create(g, b, what, &o->texture[k], e) != 0 ? -1
                                                                  : gpu_point_clamp_sampler(g, what, &o->sampler[k], e);
}

/* Buffer k's data into its memory. */
static int upload(gpu_device *g, dispatch_objects *o, int k, const gpu_buffer *b, const char *what, gt_error *e)
{
    void *mapped;
    if (vkMapMemory(g->device, o->memory[k], 0, b->size, 0, &mapped) != VK_SUCCESS)
        return gt_error_set(e, what, "cannot map buffer %s", b->name);
    memcpy(mapped, b->data, b->size);
    vkUnmapMemory(g->device, o->memory[k]);
    return 0;
}

/* Buffer k (binding k) in host-visible memory, holding its data. */
static int make_buffer(gpu_device *g, dispatch_objects *o, int k, const gpu_buffer *b, const char *what, gt_error *e)
{
    if (b->kind >= GPU_TEXTURE_R32F)
        return make_image_binding(g, o, k, b, what, e);
    VkBufferCreateInfo info = {.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                               .size = b->size,
                               .usage = b->kind == GPU_UNIFORM  ? VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT
                                        : b->kind == GPU_OUTPUT ? VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                                      VK_BUFFER_USAGE_TRANSFER_DST_BIT
                                                                : VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                               .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
    if (b->size == 0 || vkCreateBuffer(g->device, &info, NULL, &o->buffer[k]) != VK_SUCCESS)
        return gt_error_set(e, what, "cannot create buffer %s of %zu bytes", b->name, b->size);
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(g->device, o->buffer[k], &req);
    int type = host_memory_type(g, req.memoryTypeBits);
    VkMemoryAllocateInfo alloc = {.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                                  .allocationSize = req.size,
                                  .memoryTypeIndex = (uint32_t)type};
    if (type < 0 || vkAllocateMemory(g->device, &alloc, NULL, &o->memory[k]) != VK_SUCCESS)
        return gt_error_set(e, what, "cannot allocate %zu bytes of host-visible device memory", b->size);
    if (vkBindBufferMemory(g->device, o->buffer[k], o->memory[k], 0) != VK_SUCCESS)
        return gt_error_set(e, what, "cannot bind buffer %s", b->name);
    return b->kind == GPU_OUTPUT ? 0 : upload(g, o, k, b, what, e); /* outputs: cleared by the device */
}

static int make_buffers(gpu_device *g, dispatch_objects *o, const gpu_dispatch *d, gt_error *e)
{
    if (d->buffer_count < 0 || d->buffer_count > MAX_BINDINGS)
        return gt_error_set(e, d->what, "%d buffers (at most %d)", d->buffer_count, MAX_BINDINGS);
    for (int k = 0; k < d->buffer_count; ++k)
        if (make_buffer(g, o, k, &d->buffers[k], d->what, e) != 0)
            return -1;
    return 0;
}

static const char *kind_name(gpu_declared_kind kind)
{
    static const char *const names[] = {"uniform block", "storage buffer", "sampled image (Texture2D)",
                                        "sampler (SamplerState)", "combined image sampler (sampler2D)",
                                        "storage image or other resource"};
    return kind >= 0 && kind <= GPU_DECLARED_OTHER ? names[kind] : "?";
}

/* Every binding the shader declares is one of d's, of the same kind: else
 * the driver would be handed a pipeline its layout does not describe. */
static int check_bindings(const gpu_dispatch *d, gt_error *e)
{
    gpu_declared_binding b[GPU_MAX_DECLARED];
    int n = gpu_spirv_bindings(d->shader->words, d->shader->count, b);
    if (n < 0)
        return gt_error_set(e, d->what, "the compiled shader is not a SPIR-V module");
    for (int i = 0; i < n; ++i) {
        if (b[i].set != 0 || b[i].binding >= (uint32_t)d->buffer_count)
            return gt_error_set(e, d->what, "the shader declares set %u, binding %u; gtlab binds set 0, bindings 0 to %d "
                                "(docs/shaders.md)", b[i].set, b[i].binding, d->buffer_count - 1);
        const gpu_buffer *buffer = &d->buffers[b[i].binding];
        gpu_declared_kind want = declared_kind(buffer->kind);
        if (b[i].kind != want)
            return gt_error_set(e, d->what, "binding %u is declared as a %s; gtlab binds the %s %s there "
                                "(docs/shaders.md)", b[i].binding, kind_name(b[i].kind), kind_name(want), buffer->name);
    }
    return 0;
}

/* The set layout of the contract, the pipeline layout, the shader module
 * and the compute pipeline. */
static int make_pipeline(gpu_device *g, dispatch_objects *o, const gpu_dispatch *d, gt_error *e)
{
    VkDescriptorSetLayoutBinding b[MAX_BINDINGS];
    for (int k = 0; k < d->buffer_count; ++k)
        b[k] = (VkDescriptorSetLayoutBinding){.binding = (uint32_t)k,
                                              .descriptorType = descriptor_type(d->buffers[k].kind),
                                              .descriptorCount = 1,
                                              .stageFlags = VK_SHADER_STAGE_COMPUTE_BIT};
    VkDescriptorSetLayoutCreateInfo set = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                           .bindingCount = (uint32_t)d->buffer_count,
                                           .pBindings = b};
    VkPipelineLayoutCreateInfo layout = {.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                         .setLayoutCount = 1,
                                         .pSetLayouts = &o->set_layout};
    VkShaderModuleCreateInfo module = {.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                       .codeSize = d->shader->count * sizeof(uint32_t),
                                       .pCode = d->shader->words};
    if (vkCreateDescriptorSetLayout(g->device, &set, NULL, &o->set_layout) != VK_SUCCESS ||
        vkCreatePipelineLayout(g->device, &layout, NULL, &o->layout) != VK_SUCCESS ||
        vkCreateShaderModule(g->device, &module, NULL, &o->module) != VK_SUCCESS)
        return gt_error_set(e, d->what, "cannot create the pipeline layout or shader module");
    VkComputePipelineCreateInfo pipeline = {
        .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage = {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                  .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                  .module = o->module,
                  .pName = d->shader->entry},
        .layout = o->layout};
    VkResult r = vkCreateComputePipelines(g->device, VK_NULL_HANDLE, 1, &pipeline, NULL, &o->pipeline);
    return r == VK_SUCCESS ? 0 : gt_error_set(e, d->what, "cannot create the compute pipeline (VkResult %d)", (int)r);
}

/* Binding k's descriptor write: its buffer, or its image view and sampler. */
static void describe(const dispatch_objects *o, int k, gpu_buffer_kind kind, VkDescriptorBufferInfo *info,
                     VkDescriptorImageInfo *image, VkWriteDescriptorSet *w)
{
    memset(w, 0, sizeof *w);
    w->sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w->dstSet = o->set;
    w->dstBinding = (uint32_t)k;
    w->descriptorCount = 1;
    w->descriptorType = descriptor_type(kind);
    if (kind >= GPU_TEXTURE_R32F) {
        *image = (VkDescriptorImageInfo){o->sampler[k], o->texture[k].view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        w->pImageInfo = image;
    } else {
        *info = (VkDescriptorBufferInfo){o->buffer[k], 0, VK_WHOLE_SIZE};
        w->pBufferInfo = info;
    }
}

/* The descriptor set pointing each binding at its buffer. */
static int make_descriptors(gpu_device *g, dispatch_objects *o, const gpu_dispatch *d, gt_error *e)
{
    VkDescriptorPoolSize sizes[5] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, MAX_BINDINGS},
                                     {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, MAX_BINDINGS},
                                     {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, MAX_BINDINGS},
                                     {VK_DESCRIPTOR_TYPE_SAMPLER, MAX_BINDINGS},
                                     {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, MAX_BINDINGS}};
    VkDescriptorPoolCreateInfo pool = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                       .maxSets = 1,
                                       .poolSizeCount = 5,
                                       .pPoolSizes = sizes};
    VkDescriptorSetAllocateInfo alloc = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                         .descriptorSetCount = 1,
                                         .pSetLayouts = &o->set_layout};
    if (vkCreateDescriptorPool(g->device, &pool, NULL, &o->pool) != VK_SUCCESS ||
        (alloc.descriptorPool = o->pool, vkAllocateDescriptorSets(g->device, &alloc, &o->set)) != VK_SUCCESS)
        return gt_error_set(e, d->what, "cannot allocate the descriptor set");
    VkDescriptorBufferInfo info[MAX_BINDINGS];
    VkDescriptorImageInfo image[MAX_BINDINGS];
    VkWriteDescriptorSet write[MAX_BINDINGS];
    for (int k = 0; k < d->buffer_count; ++k)
        describe(o, k, d->buffers[k].kind, &info[k], &image[k], &write[k]);
    vkUpdateDescriptorSets(g->device, (uint32_t)d->buffer_count, write, 0, NULL);
    return 0;
}

/* Commands zeroing every output before the dispatch reads or writes it. */
static void clear_outputs(dispatch_objects *o, const gpu_dispatch *d)
{
    for (int k = 0; k < d->buffer_count; ++k)
        if (d->buffers[k].kind == GPU_OUTPUT)
            vkCmdFillBuffer(o->commands, o->buffer[k], 0, VK_WHOLE_SIZE, 0);
    VkMemoryBarrier barrier = {.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                               .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                               .dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
    vkCmdPipelineBarrier(o->commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1,
                         &barrier, 0, NULL, 0, NULL);
}

/* The command buffer: clear the outputs, bind, dispatch, make the writes
 * visible to the host. */
static int record(gpu_device *g, dispatch_objects *o, const gpu_dispatch *d, gt_error *e)
{
    VkCommandBufferAllocateInfo alloc = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                         .commandPool = g->pool,
                                         .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                         .commandBufferCount = 1};
    VkCommandBufferBeginInfo begin = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO}; /* submitted per frame */
    if (vkAllocateCommandBuffers(g->device, &alloc, &o->commands) != VK_SUCCESS ||
        vkBeginCommandBuffer(o->commands, &begin) != VK_SUCCESS)
        return gt_error_set(e, d->what, "cannot record a command buffer");
    clear_outputs(o, d);
    vkCmdBindPipeline(o->commands, VK_PIPELINE_BIND_POINT_COMPUTE, o->pipeline);
    vkCmdBindDescriptorSets(o->commands, VK_PIPELINE_BIND_POINT_COMPUTE, o->layout, 0, 1, &o->set, 0, NULL);
    vkCmdDispatch(o->commands, d->groups[0], d->groups[1], d->groups[2]);
    VkMemoryBarrier barrier = {.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                               .srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT,
                               .dstAccessMask = VK_ACCESS_HOST_READ_BIT};
    vkCmdPipelineBarrier(o->commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &barrier, 0, NULL, 0, NULL);
    return vkEndCommandBuffer(o->commands) == VK_SUCCESS ? 0 : gt_error_set(e, d->what, "cannot record a command buffer");
}

static double now_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int make_fence(gpu_device *g, dispatch_objects *o, const gpu_dispatch *d, gt_error *e)
{
    VkFenceCreateInfo fence = {.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    return vkCreateFence(g->device, &fence, NULL, &o->fence) == VK_SUCCESS
               ? 0
               : gt_error_set(e, d->what, "cannot create a fence");
}

/* Submits and waits for the fence at most d->timeout seconds. */
static int submit(gpu_device *g, dispatch_objects *o, const gpu_dispatch *d, double *seconds, gt_error *e)
{
    VkSubmitInfo info = {.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1,
                         .pCommandBuffers = &o->commands};
    if (vkResetFences(g->device, 1, &o->fence) != VK_SUCCESS ||
        vkQueueSubmit(g->queue, 1, &info, o->fence) != VK_SUCCESS)
        return gt_error_set(e, d->what, "cannot submit the dispatch");
    double start = now_seconds();
    VkResult r = vkWaitForFences(g->device, 1, &o->fence, VK_TRUE, (uint64_t)(d->timeout * 1e9));
    if (seconds)
        *seconds = now_seconds() - start;
    if (r == VK_TIMEOUT) {
        g->busy = 1;
        return gt_error_set(e, d->what, "device timeout after %g s (an endless loop?) on %s", d->timeout, g->name);
    }
    return r == VK_SUCCESS ? 0 : gt_error_set(e, d->what, "the device failed the dispatch (VkResult %d)", (int)r);
}

long gpu_first_non_finite(const float *values, size_t count)
{
    for (size_t i = 0; i < count; ++i)
        if (!isfinite(values[i]))
            return (long)i;
    return -1;
}

/* Copies the outputs back; the first NaN or infinity in any is an error. */
static int read_back(gpu_device *g, dispatch_objects *o, const gpu_dispatch *d, gt_error *e)
{
    for (int k = 0; k < d->buffer_count; ++k) {
        gpu_buffer *b = &d->buffers[k];
        void *mapped;
        if (b->kind != GPU_OUTPUT)
            continue;
        if (vkMapMemory(g->device, o->memory[k], 0, b->size, 0, &mapped) != VK_SUCCESS)
            return gt_error_set(e, d->what, "cannot map output %s", b->name);
        memcpy(b->data, mapped, b->size);
        vkUnmapMemory(g->device, o->memory[k]);
        long bad = gpu_first_non_finite(b->data, b->size / sizeof(float));
        if (bad >= 0)
            return gt_error_set(e, d->what, "%s in output %s at element %ld", isnan(((const float *)b->data)[bad]) ? "NaN" : "infinity",
                                b->name, bad);
    }
    return 0;
}

static void release(gpu_device *g, dispatch_objects *o)
{
    if (g->busy)
        return; /* the device may still use them */
    vkDestroyFence(g->device, o->fence, NULL);
    vkDestroyDescriptorPool(g->device, o->pool, NULL);
    vkDestroyPipeline(g->device, o->pipeline, NULL);
    vkDestroyShaderModule(g->device, o->module, NULL);
    vkDestroyPipelineLayout(g->device, o->layout, NULL);
    vkDestroyDescriptorSetLayout(g->device, o->set_layout, NULL);
    if (o->commands)
        vkFreeCommandBuffers(g->device, g->pool, 1, &o->commands);
    for (int k = 0; k < MAX_BINDINGS; ++k) {
        vkDestroyBuffer(g->device, o->buffer[k], NULL);
        vkFreeMemory(g->device, o->memory[k], NULL);
        gpu_texture_destroy(g, &o->texture[k]);
        vkDestroySampler(g->device, o->sampler[k], NULL);
    }
}

/* A dispatch built once and run per frame. */
struct gpu_dispatch_session {
    gpu_device *device;
    const gpu_dispatch *dispatch;
    dispatch_objects objects;
};

int gpu_dispatch_open(gpu_device *g, const gpu_dispatch *d, gpu_dispatch_session **out, gt_error *e)
{
    *out = NULL;
    if (g->busy)
        return gt_error_set(e, d->what, "the device %s is still busy with a dispatch that timed out", g->name);
    gpu_dispatch_session *s = calloc(1, sizeof *s);
    if (!s)
        return gt_error_set(e, d->what, "out of memory");
    s->device = g, s->dispatch = d;
    dispatch_objects *o = &s->objects;
    if (check_bindings(d, e) != 0 || make_buffers(g, o, d, e) != 0 || make_pipeline(g, o, d, e) != 0 ||
        make_descriptors(g, o, d, e) != 0 || record(g, o, d, e) != 0 || make_fence(g, o, d, e) != 0) {
        gpu_dispatch_close(s);
        return -1;
    }
    *out = s;
    return 0;
}

/* The uniform blocks from their data again: they change between frames
 * (the frame index); inputs do not, outputs are cleared by the device. */
static int upload_frame(gpu_dispatch_session *s, gt_error *e)
{
    const gpu_dispatch *d = s->dispatch;
    for (int k = 0; k < d->buffer_count; ++k)
        if (d->buffers[k].kind == GPU_UNIFORM && upload(s->device, &s->objects, k, &d->buffers[k], d->what, e) != 0)
            return -1;
    return 0;
}

int gpu_dispatch_frame(gpu_dispatch_session *s, double *seconds, gt_error *e)
{
    if (s->device->busy)
        return gt_error_set(e, s->dispatch->what, "the device %s is still busy with a dispatch that timed out",
                            s->device->name);
    return upload_frame(s, e) != 0 || submit(s->device, &s->objects, s->dispatch, seconds, e) != 0 ||
                   read_back(s->device, &s->objects, s->dispatch, e) != 0
               ? -1
               : 0;
}

void gpu_dispatch_close(gpu_dispatch_session *s)
{
    if (!s)
        return;
    release(s->device, &s->objects);
    free(s);
}

int gpu_dispatch_run(gpu_device *g, const gpu_dispatch *d, double *seconds, gt_error *e)
{
    gpu_dispatch_session *s;
    if (gpu_dispatch_open(g, d, &s, e) != 0)
        return -1;
    int rc = gpu_dispatch_frame(s, seconds, e);
    gpu_dispatch_close(s);
    return rc;
}
