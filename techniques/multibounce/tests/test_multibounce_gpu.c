/* gtlab's generated shaders, executed (issue 15, item 4): the multi-bounce
 * functions gtlab writes as GLSL and HLSL, wrapped into a compute shader,
 * run on Vulkan over a dense grid of inputs and compared with the C
 * functions they were generated from (the sphere light's:
 * techniques/sphere_light/tests/test_sphere_light_gpu.c).
 *
 * The bound (docs/decisions.md, "Shaders on Vulkan"), u = 2^-24: the C is
 * double; the shader rounds each coefficient to float and evaluates a
 * polynomial by Horner's rule in at most 10 float operations on every path
 * (rounding of the coefficient, 4 for a quadratic in the albedo, 5 for the
 * cubic; Vulkan's +, * are correctly rounded and a fused multiply-add only
 * removes roundings; max is exact and 1-Lipschitz). The classical Horner
 * bound (Higham, Accuracy and Stability, eq. 5.3) gives |gpu - c| <=
 * gamma_10 S, gamma_10 = 10u / (1 - 10u), S the same polynomial with every
 * coefficient and variable replaced by its absolute value. Checked:
 * |gpu - c| <= 11 u S at every grid point. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>

#include "gpu/sample_map.h"
#include "gpu/vulkan_device.h"
#include "multibounce/multibounce.h"
#include "multibounce/multibounce_shader.h"
#include "tests/check.h"
#include "tests/gpu/sample_shader.h"
#include "test_multibounce_models.h"

static const double kU = 1.0 / 16777216.0; /* 2^-24 */

/* ---- Multi-bounce ---- */

enum { MB_MODELS = TEST_MULTIBOUNCE_MODELS, MB_X = 257, MB_RHO = 129, MB_SAMPLES = MB_X * MB_RHO };

/* Sample s: V_d a little beyond [0, 1], three albedos over [-1/64, 1 + 1/64]. */
static void mb_inputs(float *in)
{
    for (int s = 0; s < MB_SAMPLES; ++s) {
        int i = s / MB_RHO, j = s % MB_RHO;
        in[4 * s] = (i * 2 - 4) / 512.0f;
        for (int c = 0; c < 3; ++c)
            in[4 * s + 1 + c] = ((j + 43 * c) % MB_RHO - 2) / 128.0f;
    }
}

static double abs_poly(const double *k, int degree, double rho)
{
    double v = 0.0;
    for (int d = degree; d >= 0; --d)
        v = v * fabs(rho) + fabs(k[d]);
    return v;
}

/* S: the Horner bound's polynomial of absolute values. */
static double mb_magnitude(const multibounce_model *m, double x, double rho)
{
    int degree = m->degree ? m->degree : 2;
    double a = abs_poly(m->a, degree, rho), b = abs_poly(m->b, degree, rho), c = abs_poly(m->c, degree, rho);
    return ((a * fabs(x) + b) * fabs(x) + c) * fabs(x) + fabs(x);
}

static const char kMbGlslBody[] = "    float x = v[4u * i];\n    vec3 rho = vec3(v[4u * i + 1u], v[4u * i + 2u], v[4u * i + 3u]);\n"
                                  "    vec3 m[3] = vec3[3](mb0(x, rho), mb1(x, rho), mb2(x, rho));\n"
                                  "    for (uint k = 0u; k < 3u; ++k)\n        for (uint c = 0u; c < 3u; ++c)\n"
                                  "            r[9u * i + 3u * k + c] = m[k][c];\n";
static const char kMbHlslBody[] = "    float x = v[4u * i];\n    float3 rho = float3(v[4u * i + 1u], v[4u * i + 2u], v[4u * i + 3u]);\n"
                                  "    float3 m[3] = {mb0(x, rho), mb1(x, rho), mb2(x, rho)};\n"
                                  "    for (uint k = 0u; k < 3u; ++k)\n        for (uint c = 0u; c < 3u; ++c)\n"
                                  "            r[9u * i + 3u * k + c] = m[k][c];\n";

/* Worst |gpu - c| / (u S) over the grid, every model and channel. */
static double mb_worst_ulps(const multibounce_model *m, const float *in, const float *out)
{
    double worst = 0.0;
    for (int s = 0; s < MB_SAMPLES; ++s)
        for (int k = 0; k < MB_MODELS; ++k)
            for (int c = 0; c < 3; ++c) {
                double x = in[4 * s], rho = in[4 * s + 1 + c], got = out[9 * s + 3 * k + c];
                double want = gtao_multibounce(&m[k], x, rho);
                worst = fmax(worst, fabs(got - want) / (kU * mb_magnitude(&m[k], x, rho)));
            }
    return worst;
}

static void test_multibounce(gpu_device *g, shader_language language)
{
    static const char *const names[MB_MODELS] = {"mb0", "mb1", "mb2"};
    multibounce_model m[MB_MODELS];
    multibounce_shader_function f[MB_MODELS];
    test_multibounce_models(m);
    for (int k = 0; k < MB_MODELS; ++k)
        f[k] = (multibounce_shader_function){.name = names[k], .comment = "test", .model = m[k]};
    char *functions = multibounce_shader_source(language, "// gtlab test\n", f, MB_MODELS);
    char *source = functions ? test_sample_shader(language, functions, language == SHADER_GLSL ? kMbGlslBody : kMbHlslBody)
                             : NULL;
    float *in = malloc(4 * sizeof(float) * MB_SAMPLES), *out = malloc(9 * sizeof(float) * MB_SAMPLES);
    gt_error e = {{0}};
    const char *name = language == SHADER_GLSL ? "multibounce.glsl" : "multibounce.hlsl";
    CHECK(source && in && out);
    if (source && in && out) {
        mb_inputs(in);
        int rc = gpu_sample_map(g, source, name, NULL, in, 4, out, 9, MB_SAMPLES, 60.0, &e);
        CHECK_MSG(rc == 0, "%s", e.message);
        double worst = rc == 0 ? mb_worst_ulps(m, in, out) : 1e30;
        printf("%s: %d samples x 3 models x 3 channels, worst |gpu - c| = %.3g u S (bound 11)\n", name, MB_SAMPLES,
               worst);
        CHECK_MSG(worst <= 11.0, "%s: %g u S", name, worst);
    }
    free(functions), free(source), free(in), free(out);
}

int main(void)
{
    gpu_device *g = NULL;
    gt_error e = {{0}};
    CHECK_MSG(gpu_device_open(NULL, &g, &e) == 0, "%s", e.message);
    if (g) {
        test_multibounce(g, SHADER_GLSL);
        test_multibounce(g, SHADER_HLSL);
        gpu_device_close(g);
    }
    return check_report("multibounce_gpu");
}
