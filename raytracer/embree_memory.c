/* Embree's memory estimate and error names; see embree_memory.h. */
#include "raytracer/embree_memory.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

double embree_build_bytes(uint64_t triangles)
{
    return EMBREE_BUILD_BYTES_PER_TRIANGLE * (double)triangles;
}

double memory_available_bytes(void)
{
    FILE *f = fopen("/proc/meminfo", "r");
    if (!f)
        return NAN;
    char line[256];
    double kib = NAN;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "MemAvailable: %lf kB", &kib) == 1)
            break;
    fclose(f);
    return kib * 1024.0;
}

int embree_check_memory(const char *scene_name, uint64_t triangles, double available, gt_error *e)
{
    double need = embree_build_bytes(triangles);
    if (isnan(available) || need <= available)
        return 0;
    return gt_error_set(e, scene_name,
                        "%llu triangles need about %.1f GB to build Embree's BVH (%.0f bytes per triangle), but "
                        "only %.1f GB of memory is available: simplify the scene (gltfpack -si 0.5 halves its "
                        "triangles) or use a machine with more memory",
                        (unsigned long long)triangles, need * 1e-9, EMBREE_BUILD_BYTES_PER_TRIANGLE,
                        available * 1e-9);
}

const char *embree_error_name(enum RTCError code)
{
    switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "this CPU is not supported";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "unknown error";
    }
}
