/* raytracer/embree_memory.c: the estimate of Embree's peak memory holds, for
 * the build embree_scene_build performs (robust, high quality), against
 * Embree's own accounting (rtcSetDeviceMemoryMonitorFunction) on a wavy grid
 * of 2 10^5 triangles: not below the measured peak, not more than twice it.
 * A scene too large for the memory at hand is refused in words. */
#include "raytracer/embree_memory.h"
#include "tests/check.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/types.h>

static long long current_bytes, peak_bytes;

static bool monitor(void *user, ssize_t bytes, bool post)
{
    (void)user;
    (void)post;
    current_bytes += bytes;
    if (current_bytes > peak_bytes)
        peak_bytes = current_bytes;
    return true;
}

/* A side x side grid of quads (two triangles each), heights varying. */
static unsigned build_grid(RTCDevice device, unsigned side)
{
    RTCScene s = rtcNewScene(device);
    rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    unsigned nv = (side + 1) * (side + 1), nt = 2 * side * side;
    float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, nv);
    unsigned *ix = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, nt);
    for (unsigned i = 0; i < nv; ++i) {
        unsigned x = i % (side + 1), y = i / (side + 1);
        v[3 * i] = (float)x, v[3 * i + 1] = (float)y, v[3 * i + 2] = 0.3f * sinf(0.7f * (float)x) * cosf(0.4f * (float)y);
    }
    for (unsigned q = 0; q < side * side; ++q) {
        unsigned a = q / side * (side + 1) + q % side, *t = &ix[6 * q];
        t[0] = a, t[1] = a + 1, t[2] = a + side + 1, t[3] = a + 1, t[4] = a + side + 2, t[5] = a + side + 1;
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(s, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(s);
    rtcReleaseScene(s);
    return nt;
}

static void test_estimate_against_measured_peak(void)
{
    RTCDevice device = rtcNewDevice("threads=1");
    rtcSetDeviceMemoryMonitorFunction(device, monitor, NULL);
    unsigned triangles = build_grid(device, 317);
    CHECK(rtcGetDeviceError(device) == RTC_ERROR_NONE);
    double estimate = embree_build_bytes(triangles);
    printf("%u triangles: Embree's peak %.1f bytes per triangle, estimate %.0f\n", triangles,
           (double)peak_bytes / triangles, estimate / triangles);
    CHECK(peak_bytes > 0);
    CHECK(estimate >= (double)peak_bytes);
    CHECK(estimate <= 2.0 * (double)peak_bytes);
    rtcReleaseDevice(device);
}

static void test_too_large_refused(void)
{
    gt_error e;
    CHECK(embree_check_memory("big.glb", 131000000ull, 8e9, &e) != 0);
    CHECK_MSG(strstr(e.message, "big.glb: 131000000 triangles need about 21.0 GB") &&
                  strstr(e.message, "8.0 GB of memory is available"),
              "%s", e.message);
    CHECK(embree_check_memory("small.glb", 1000, 8e9, &e) == 0);
    CHECK(embree_check_memory("unknown.glb", 131000000ull, NAN, &e) == 0);
    double available = memory_available_bytes();
    CHECK(isnan(available) || available > 0);
    CHECK(strcmp(embree_error_name(RTC_ERROR_OUT_OF_MEMORY), "out of memory") == 0);
}

int main(void)
{
    test_estimate_against_measured_peak();
    test_too_large_refused();
    return check_report("test_embree_memory");
}
