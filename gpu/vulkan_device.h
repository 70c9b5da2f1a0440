/* A Vulkan device that runs compute shaders: the instance, one physical
 * device with a compute queue, its logical device, the queue and a command
 * pool. Where only Mesa's CPU driver is installed (lavapipe, "llvmpipe" in
 * vulkaninfo) that is the device: it runs everywhere, CI included. A name
 * substring picks among several (a future `--device`); without one a
 * discrete GPU is preferred, then an integrated one, then any other. */
#ifndef GTLAB_GPU_VULKAN_DEVICE_H
#define GTLAB_GPU_VULKAN_DEVICE_H

#include "core/error.h"

typedef struct gpu_device gpu_device;

/* Opens the device whose name contains `name` (case-insensitive; NULL or ""
 * for the preferred one). Returns 0, or -1 with e = "vulkan: <problem>"
 * (no loader or driver, no device with a compute queue, no device named
 * so: the message lists the devices there are). */
int gpu_device_open(const char *name, gpu_device **out, gt_error *e);

/* The device's name, as vulkaninfo prints it. */
const char *gpu_device_name(const gpu_device *device);

/* Closes the device. A device whose dispatch timed out (still busy) is only
 * forgotten: waiting for it would hang; the process's exit reclaims it. */
void gpu_device_close(gpu_device *device);

#endif
