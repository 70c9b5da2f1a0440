#include "gpu/vulkan_device_handles.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

enum { MAX_DEVICES = 16 };

static int create_instance(VkInstance *instance, gt_error *e)
{
    VkApplicationInfo app = {.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                             .pApplicationName = "gtlab",
                             .apiVersion = VK_API_VERSION_1_1};
    VkInstanceCreateInfo info = {.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, .pApplicationInfo = &app};
    VkResult r = vkCreateInstance(&info, NULL, instance);
    if (r != VK_SUCCESS)
        return gt_error_set(e, "vulkan", "cannot create an instance (VkResult %d): no Vulkan driver installed? "
                                         "(Debian: mesa-vulkan-drivers gives the CPU device lavapipe)",
                            (int)r);
    return 0;
}

/* The first queue family of d with compute, or -1. */
static int compute_family(VkPhysicalDevice d)
{
    VkQueueFamilyProperties families[32];
    uint32_t count = 32;
    vkGetPhysicalDeviceQueueFamilyProperties(d, &count, families);
    for (uint32_t i = 0; i < count; ++i)
        if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT)
            return (int)i;
    return -1;
}

/* Higher is preferred: discrete, integrated, virtual, CPU. */
static int type_rank(VkPhysicalDeviceType type)
{
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    default: return 1;
    }
}

/* Does the name contain `wanted` (case-insensitive; NULL or "" matches all)? */
static int name_matches(const char *name, const char *wanted)
{
    if (!wanted || !*wanted)
        return 1;
    for (size_t n = strlen(wanted); *name; ++name)
        if (strncasecmp(name, wanted, n) == 0)
            return 1;
    return 0;
}

/* "llvmpipe (LLVM 15.0.6, 256 bits), ..." for a message, into list. */
static void list_names(VkPhysicalDevice *devices, uint32_t count, char *list, size_t size)
{
    size_t used = 0;
    list[0] = '\0';
    for (uint32_t i = 0; i < count && used < size; ++i) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(devices[i], &p);
        int n = snprintf(list + used, size - used, "%s%s", i ? ", " : "", p.deviceName);
        used += n > 0 ? (size_t)n : 0;
    }
}

/* The best device named `wanted` with a compute queue, into g. */
static int pick_device(gpu_device *g, const char *wanted, gt_error *e)
{
    VkPhysicalDevice devices[MAX_DEVICES];
    uint32_t count = MAX_DEVICES;
    VkResult r = vkEnumeratePhysicalDevices(g->instance, &count, devices);
    if ((r != VK_SUCCESS && r != VK_INCOMPLETE) || count == 0)
        return gt_error_set(e, "vulkan", "no Vulkan device (Debian: mesa-vulkan-drivers gives the CPU device lavapipe)");
    int best = -1, best_rank = 0;
    for (uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(devices[i], &p);
        int rank = type_rank(p.deviceType);
        if (name_matches(p.deviceName, wanted) && compute_family(devices[i]) >= 0 && rank > best_rank)
            best = (int)i, best_rank = rank;
    }
    if (best < 0) {
        char list[1024];
        list_names(devices, count, list, sizeof list);
        return gt_error_set(e, "vulkan", "no device%s%s with a compute queue among: %s", wanted ? " named " : "",
                            wanted ? wanted : "", list);
    }
    g->physical = devices[best];
    g->queue_family = (uint32_t)compute_family(g->physical);
    return 0;
}

/* The logical device with one compute queue, and its command pool. */
static int create_device(gpu_device *g, gt_error *e)
{
    float priority = 1.0f;
    VkDeviceQueueCreateInfo queue = {.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                     .queueFamilyIndex = g->queue_family,
                                     .queueCount = 1,
                                     .pQueuePriorities = &priority};
    /* Robust buffer access where the device has it: a shader's access past
     * a buffer's end is dropped (reads give 0) instead of touching memory. */
    VkPhysicalDeviceFeatures supported, enabled = {0};
    vkGetPhysicalDeviceFeatures(g->physical, &supported);
    enabled.robustBufferAccess = supported.robustBufferAccess;
    VkDeviceCreateInfo info = {.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                               .queueCreateInfoCount = 1,
                               .pQueueCreateInfos = &queue,
                               .pEnabledFeatures = &enabled};
    VkResult r = vkCreateDevice(g->physical, &info, NULL, &g->device);
    if (r != VK_SUCCESS)
        return gt_error_set(e, "vulkan", "%s: cannot create the device (VkResult %d)", g->name, (int)r);
    vkGetDeviceQueue(g->device, g->queue_family, 0, &g->queue);
    VkCommandPoolCreateInfo pool = {.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                    .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                    .queueFamilyIndex = g->queue_family};
    r = vkCreateCommandPool(g->device, &pool, NULL, &g->pool);
    if (r != VK_SUCCESS)
        return gt_error_set(e, "vulkan", "%s: cannot create a command pool (VkResult %d)", g->name, (int)r);
    return 0;
}

int gpu_device_open(const char *name, gpu_device **out, gt_error *e)
{
    *out = NULL;
    gpu_device *g = calloc(1, sizeof *g);
    if (!g)
        return gt_error_set(e, "vulkan", "out of memory");
    if (create_instance(&g->instance, e) != 0) {
        free(g);
        return -1;
    }
    if (pick_device(g, name, e) != 0) {
        gpu_device_close(g);
        return -1;
    }
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(g->physical, &p);
    snprintf(g->name, sizeof g->name, "%s", p.deviceName);
    vkGetPhysicalDeviceMemoryProperties(g->physical, &g->memory);
    if (create_device(g, e) != 0) {
        gpu_device_close(g);
        return -1;
    }
    *out = g;
    return 0;
}

const char *gpu_device_name(const gpu_device *device) { return device->name; }

void gpu_device_close(gpu_device *g)
{
    if (!g || g->busy)
        return;
    if (g->pool)
        vkDestroyCommandPool(g->device, g->pool, NULL);
    if (g->device)
        vkDestroyDevice(g->device, NULL);
    if (g->instance)
        vkDestroyInstance(g->instance, NULL);
    free(g);
}
