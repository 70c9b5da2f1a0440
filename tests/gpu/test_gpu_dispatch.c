/* The Vulkan compute runner (gpu/): a shader in GLSL and in HLSL computes
 * an exact affine map of its input (every value a small integer, so float
 * gives it exactly); the failures each give one line: a compile error with
 * shaderc's message and line number, a device that is not there, NaN in an
 * output, an endless loop (device timeout). Needs a Vulkan device: without
 * one this test fails. */
#define _POSIX_C_SOURCE 200809L
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "gpu/compute_dispatch.h"
#include "gpu/shader_compiler.h"
#include "gpu/vulkan_device.h"
#include "tests/check.h"

enum { COUNT = 1000, GROUP = 64 };

static const char kGlsl[] = "#version 450\n"
                            "layout(local_size_x = 64) in;\n"
                            "layout(std140, binding = 0) uniform Params { float scale, offset; uint count; };\n"
                            "layout(std430, binding = 1) readonly buffer In { float x[]; };\n"
                            "layout(std430, binding = 2) writeonly buffer Out { float y[]; };\n"
                            "void main()\n{\n"
                            "    uint i = gl_GlobalInvocationID.x;\n"
                            "    if (i < count)\n"
                            "        y[i] = x[i] / scale + offset;\n"
                            "}\n";

static const char kHlsl[] = "[[vk::binding(0)]] cbuffer Params { float scale, offset; uint count; };\n"
                            "[[vk::binding(1)]] StructuredBuffer<float> x;\n"
                            "[[vk::binding(2)]] RWStructuredBuffer<float> y;\n"
                            "[numthreads(64, 1, 1)]\n"
                            "void CSMain(uint3 id : SV_DispatchThreadID)\n{\n"
                            "    if (id.x < count)\n"
                            "        y[id.x] = x[id.x] / scale + offset;\n"
                            "}\n";

typedef struct {
    float scale, offset;
    uint32_t count;
} params;

/* Runs `source` on x = 0..COUNT-1 with the given parameters, into y. */
static int run(gpu_device *g, const char *source, const char *name, const char *entry, params u, float *y,
               double timeout, gt_error *e)
{
    static float x[COUNT];
    for (int i = 0; i < COUNT; ++i)
        x[i] = (float)i;
    gpu_spirv spirv;
    if (gpu_compile_compute(source, name, gpu_source_language_of(name), entry, &spirv, e) != 0)
        return -1;
    gpu_buffer buffers[3] = {{"params", GPU_UNIFORM, &u, sizeof u}, {"x", GPU_INPUT, x, sizeof x},
                             {"y", GPU_OUTPUT, y, COUNT * sizeof(float)}};
    gpu_dispatch d = {&spirv, name, buffers, 3, {(COUNT + GROUP - 1) / GROUP, 1, 1}, timeout};
    int rc = gpu_dispatch_run(g, &d, NULL, e);
    gpu_spirv_free(&spirv);
    return rc;
}

static void test_affine(gpu_device *g, const char *source, const char *name, const char *entry)
{
    static float y[COUNT];
    gt_error e = {{0}};
    int rc = run(g, source, name, entry, (params){0.5f, -3.0f, COUNT}, y, 10.0, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    int wrong = 0;
    for (int i = 0; i < COUNT && rc == 0; ++i)
        wrong += y[i] != 2.0f * i - 3.0f;
    CHECK_MSG(wrong == 0, "%s: %d of %d values differ from 2 x - 3", name, wrong, COUNT);
}

/* An undeclared name on line 10: one line, the file, the line, shaderc's words. */
static void test_compile_error(void)
{
    char broken[sizeof kGlsl + 16];
    snprintf(broken, sizeof broken, "%s", kGlsl);
    memcpy(strstr(broken, "offset;\n"), "offsex;", 7);
    gpu_spirv spirv;
    gt_error e = {{0}};
    CHECK(gpu_compile_compute(broken, "broken.glsl", GPU_SOURCE_GLSL, NULL, &spirv, &e) != 0);
    CHECK_MSG(strncmp(e.message, "broken.glsl:10: error: ", 23) == 0 && strstr(e.message, "offsex") &&
                  strstr(e.message, "undeclared identifier") && !strchr(e.message, '\n'),
              "%s", e.message);
    CHECK(spirv.words == NULL);
    CHECK(gpu_compile_compute(kGlsl, "a.glsl", GPU_SOURCE_GLSL, "CSMain", &spirv, &e) != 0);
    CHECK_MSG(strstr(e.message, "entry point is main") != NULL, "%s", e.message);
}

static void test_no_such_device(void)
{
    gpu_device *g = NULL;
    gt_error e = {{0}};
    CHECK(gpu_device_open("no-such-device-name", &g, &e) != 0 && g == NULL);
    CHECK_MSG(strstr(e.message, "no device named no-such-device-name") != NULL, "%s", e.message);
}

/* 0 / 0 at x = 0 (the uniform's scale 0 is not known to the compiler). */
static void test_nan(gpu_device *g)
{
    static float y[COUNT];
    gt_error e = {{0}};
    CHECK(run(g, kGlsl, "nan.glsl", NULL, (params){0.0f, 0.0f, COUNT}, y, 10.0, &e) != 0);
    CHECK_MSG(strcmp(e.message, "nan.glsl: NaN in output y at element 0") == 0, "%s", e.message);
}

/* x / 1e-37 overflows a float from x = 35 (3.4e38 is the largest): an
 * infinity is refused as a NaN is (issue 41). */
static void test_infinity(gpu_device *g)
{
    static float y[COUNT];
    gt_error e = {{0}};
    CHECK(run(g, kGlsl, "inf.glsl", NULL, (params){1e-37f, 0.0f, COUNT}, y, 10.0, &e) != 0);
    CHECK_MSG(strcmp(e.message, "inf.glsl: infinity in output y at element 35") == 0, "%s", e.message);
}

/* A binding outside the dispatch's, and a storage buffer where it binds a
 * uniform block: one line each, before the driver sees the pipeline. */
static void test_wrong_binding(gpu_device *g)
{
    static float y[COUNT];
    char shader[sizeof kGlsl + 16];
    gt_error e = {{0}};
    snprintf(shader, sizeof shader, "%s", kGlsl);
    memcpy(strstr(shader, "binding = 2"), "binding = 7", 11);
    CHECK(run(g, shader, "seven.glsl", NULL, (params){1.0f, 0.0f, COUNT}, y, 10.0, &e) != 0);
    CHECK_MSG(strncmp(e.message, "seven.glsl: the shader declares set 0, binding 7; gtlab binds set 0, bindings 0 to 2",
                      84) == 0, "%s", e.message);
    snprintf(shader, sizeof shader, "%s", kGlsl);
    memcpy(strstr(shader, "binding = 0"), "binding = 1", 11);
    memcpy(strstr(shader, "binding = 1) readonly"), "binding = 0) readonly", 21);
    CHECK(run(g, shader, "swapped.glsl", NULL, (params){1.0f, 0.0f, COUNT}, y, 10.0, &e) != 0);
    CHECK_MSG(strstr(e.message, "swapped.glsl: binding 1 is declared as a uniform block; gtlab binds the storage "
                                "buffer x there") == e.message, "%s", e.message);
}

/* A loop whose exit the shader never reaches (n stays odd, count is even)
 * in 65535 x 64 invocations. llvmpipe ends any loop after 65535 iterations,
 * so there it is long, not endless: either way the fence times out. */
static const char kEndless[] = "#version 450\n"
                               "layout(local_size_x = 64) in;\n"
                               "layout(std140, binding = 0) uniform Params { float scale, offset; uint count; };\n"
                               "layout(std430, binding = 1) readonly buffer In { float x[]; };\n"
                               "layout(std430, binding = 2) buffer Out { float y[]; };\n"
                               "void main()\n{\n"
                               "    for (uint n = 1u; n != count; n += 2u)\n"
                               "        y[gl_LocalInvocationID.x] += x[n % 7u];\n"
                               "}\n";

/* In a child process, which ends with _exit: the device is still busy, and
 * the driver's exit handlers would wait for it. The child sends its message. */
static void test_timeout(void)
{
    int fds[2];
    CHECK(pipe(fds) == 0);
    pid_t child = fork();
    if (child == 0) {
        static float y[COUNT];
        static float x[COUNT];
        gpu_device *g = NULL;
        gpu_spirv spirv;
        gt_error e = {{0}};
        params u = {1.0f, 0.0f, COUNT};
        gpu_buffer buffers[3] = {{"params", GPU_UNIFORM, &u, sizeof u}, {"x", GPU_INPUT, x, sizeof x},
                                 {"y", GPU_OUTPUT, y, sizeof y}};
        gpu_dispatch d = {&spirv, "endless.glsl", buffers, 3, {65535, 1, 1}, 1.0};
        int rc = gpu_device_open(NULL, &g, &e) == 0 &&
                 gpu_compile_compute(kEndless, d.what, GPU_SOURCE_GLSL, NULL, &spirv, &e) == 0 &&
                 gpu_dispatch_run(g, &d, NULL, &e) != 0;
        ssize_t written = write(fds[1], e.message, strlen(e.message) + 1);
        _exit(rc && written > 0 ? 0 : 1);
    }
    close(fds[1]);
    char message[sizeof(gt_error)] = "";
    ssize_t got = read(fds[0], message, sizeof message - 1);
    int status = 1;
    CHECK(child > 0 && waitpid(child, &status, 0) == child && got > 0);
    CHECK_MSG(WIFEXITED(status) && WEXITSTATUS(status) == 0, "the endless shader did not time out: %s", message);
    CHECK_MSG(strncmp(message, "endless.glsl: device timeout after 1 s", 38) == 0, "%s", message);
    close(fds[0]);
}

int main(void)
{
    gpu_device *g = NULL;
    gt_error e = {{0}};
    test_compile_error();
    test_no_such_device();
    test_timeout();
    CHECK_MSG(gpu_device_open(NULL, &g, &e) == 0, "%s", e.message);
    if (g) {
        printf("device: %s\n", gpu_device_name(g));
        test_affine(g, kGlsl, "affine.glsl", NULL);
        test_affine(g, kHlsl, "affine.hlsl", "CSMain");
        test_nan(g);
        test_infinity(g);
        test_wrong_binding(g);
        gpu_device_close(g);
    }
    return check_report("test_gpu_dispatch");
}
