/* Will Embree's build fit in memory? A scene of a hundred million triangles
 * otherwise fails after minutes with Embree's bare "error 4". Embree's peak
 * during a high-quality robust build, its own vertex and index buffers
 * included, was measured with rtcSetDeviceMemoryMonitorFunction at 108 to
 * 124 bytes per triangle (grids of 10^5 to 4 10^6 triangles, Embree 3.13);
 * tests/raytracer/test_embree_memory.c measures it again against the
 * estimate. */
#ifndef GTLAB_RAYTRACER_EMBREE_MEMORY_H
#define GTLAB_RAYTRACER_EMBREE_MEMORY_H

#include <embree3/rtcore.h>
#include <stdint.h>

#include "core/error.h"

/* Bytes per triangle the estimate takes: the measured peak and a quarter
 * more, for thread-local allocation blocks and other Embree builds. */
#define EMBREE_BUILD_BYTES_PER_TRIANGLE 160.0

/* Embree's peak memory while building a BVH over `triangles`. */
double embree_build_bytes(uint64_t triangles);

/* The memory available to this process now (Linux MemAvailable; NAN when
 * unknown). */
double memory_available_bytes(void);

/* 0 if the build should fit in `available` bytes (NAN: unknown, so yes);
 * else -1 with e = "<scene>: <triangles> triangles need about X GB ...,
 * Y GB available: <what to do>". */
int embree_check_memory(const char *scene_name, uint64_t triangles, double available, gt_error *e);

/* Embree's device error in words ("out of memory", "unsupported CPU", ...). */
const char *embree_error_name(enum RTCError code);

#endif
