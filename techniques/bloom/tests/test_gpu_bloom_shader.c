/* gtlab's generated bloom kernels, executed (issue 15, item 4): the bloom
 * study (bloom/bloom_study.h, at a small size) writes bloom_9tap.glsl and
 * bloom_9tap.hlsl, three constant arrays of 9 (x, y, weight) taps; a compute
 * shader around each file reads every constant back on Vulkan, and each is
 * compared with the fit's own double (bloom_result's taps) it was printed
 * from.
 *
 * The bound (docs/decisions.md, "Shaders on Vulkan"), u = 2^-24: the file
 * prints each value with 9 decimals (%.9f: off by <= 5e-10) and the shader
 * compiler rounds that decimal to float (<= u of it, and 2^-53 more when it
 * goes through double first):
 *   |gpu - c| <= 5e-10 + 1.01 u (|c| + 5e-10). */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bloom/bloom_study.h"
#include "gpu/sample_map.h"
#include "gpu/shader_compiler.h"
#include "gpu/vulkan_device.h"
#include "tests/check.h"
#include "tests/gpu/sample_shader.h"

static const double kU = 1.0 / 16777216.0; /* 2^-24 */

enum { VALUES = BLOOM_FITS * BLOOM_FIT_TAPS * 3 };

/* Every constant of the three arrays, in the order of bloom_result's fits:
 * r[27 f + 3 k + c], c = x, y, weight. */
static const char kBody[] = "    for (uint k = 0u; k < 9u; ++k)\n"
                            "        for (uint c = 0u; c < 3u; ++c)\n"
                            "        {\n"
                            "            r[3u * k + c] = BLOOM_9TAP_JIMENEZ13[k][c];\n"
                            "            r[27u + 3u * k + c] = BLOOM_9TAP_JIMENEZ13_WEIGHTS_HELD[k][c];\n"
                            "            r[54u + 3u * k + c] = BLOOM_9TAP_GAUSSIAN[k][c];\n"
                            "        }\n";

/* The fit's value behind r[v]. */
static double fit_value(const bloom_result *r, int v)
{
    const bloom_tap *t = &r->targets[v / 27].fit.taps[v % 27 / 3];
    return v % 3 == 0 ? t->x : v % 3 == 1 ? t->y : t->w;
}

/* Worst |gpu - c| / bound over the constants. */
static double worst_of(const bloom_result *r, const float *out, double *largest)
{
    double worst = 0.0;
    *largest = 0.0;
    for (int v = 0; v < VALUES; ++v) {
        double c = fit_value(r, v), d = fabs(out[v] - c);
        worst = fmax(worst, d / (5e-10 + 1.01 * kU * (fabs(c) + 5e-10)));
        *largest = fmax(*largest, d);
    }
    return worst;
}

static void run_file(gpu_device *g, const bloom_result *r, const char *path)
{
    char *functions = NULL, *source = NULL;
    gt_error e = {{0}};
    float in[1] = {0.0f}, out[VALUES];
    int rc = gpu_read_source(path, &functions, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    shader_language language = strstr(path, ".glsl") ? SHADER_GLSL : SHADER_HLSL;
    source = rc == 0 ? test_sample_shader(language, functions, kBody) : NULL;
    if (source) {
        rc = gpu_sample_map(g, source, path, NULL, in, 1, out, VALUES, 1, 60.0, &e);
        CHECK_MSG(rc == 0, "%s", e.message);
        double largest = 0.0, worst = rc == 0 ? worst_of(r, out, &largest) : 1e30;
        printf("%s: %d constants, worst |gpu - c| = %.3g of the bound (largest %.3g)\n", path, VALUES, worst, largest);
        CHECK_MSG(worst <= 1.0, "%s: %g of the bound", path, worst);
    }
    free(functions), free(source);
}

int main(void)
{
    char dir[4096], path[4200];
    snprintf(dir, sizeof dir, "%s/test_gpu_bloom_shader_files", check_tmp_dir());
    mkdir(dir, 0755); /* may exist */
    study_context ctx = {dir, QUALITY_PREVIEW, 2, NULL, NULL, 0};
    bloom_request rq = {96, 54, 2, 3, 1};
    static bloom_result r;
    gpu_device *g = NULL;
    gt_error e = {{0}};
    CHECK_MSG(bloom_study(&ctx, &rq, &r, &e) == 0, "%s", e.message);
    CHECK_MSG(gpu_device_open(NULL, &g, &e) == 0, "%s", e.message);
    for (int glsl = 1; g && glsl >= 0; --glsl) {
        snprintf(path, sizeof path, "%s/%s/bloom_9tap.%s", dir, BLOOM_DIR, glsl ? "glsl" : "hlsl");
        run_file(g, &r, path);
    }
    gpu_device_close(g);
    return check_report("test_gpu_bloom_shader");
}
