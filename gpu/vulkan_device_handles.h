/* The Vulkan handles of a gpu_device, for gpu/'s own sources (the public
 * header keeps the type opaque so no caller needs <vulkan/vulkan.h>). */
#ifndef GTLAB_GPU_VULKAN_DEVICE_HANDLES_H
#define GTLAB_GPU_VULKAN_DEVICE_HANDLES_H

#include <vulkan/vulkan.h>

#include "gpu/vulkan_device.h"

struct gpu_device {
    VkInstance instance;
    VkPhysicalDevice physical;
    VkDevice device;
    VkQueue queue;
    uint32_t queue_family;
    VkCommandPool pool;
    VkPhysicalDeviceMemoryProperties memory;
    char name[VK_MAX_PHYSICAL_DEVICE_NAME_SIZE];
    int busy; /* a dispatch timed out: the device may still be running it */
};

#endif
