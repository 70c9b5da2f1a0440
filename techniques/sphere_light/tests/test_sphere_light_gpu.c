/* gtlab's generated sphere-light shaders, executed (issue 15, item 4):
 * EvaluateSphericalAreaGGX and GetNoHSquared as gtlab writes them in GLSL
 * and HLSL (sphere_light_shader.h), wrapped into a compute shader, run on
 * Vulkan over a dense grid of inputs and compared with the C they were
 * generated from (the multi-bounce functions':
 * techniques/multibounce/tests/test_multibounce_gpu.c).
 *
 * The bound (docs/decisions.md, "Shaders on Vulkan"), u = 2^-24: the C is
 * float too (sphere_light.inc compiled as C), ~60 operations with square
 * roots and divisions (Vulkan: 3 and 2.5 ulp) and the shader's own
 * visibility term. Checked: |gpu - c| <= 64 u |c| + the C's own spread
 * under input perturbations of 8 u (the function's conditioning: near the
 * rim's cancellations a few ulp of input move the value more than any
 * rounding inside). */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gpu/sample_map.h"
#include "gpu/vulkan_device.h"
#include "sphere_light/sphere_light.h"
#include "sphere_light/sphere_light_shader.h"
#include "tests/check.h"
#include "tests/gpu/sample_shader.h"

static const double kU = 1.0 / 16777216.0; /* 2^-24 */

enum { SL_NL = 19, SL_NV = 19, SL_VL = 16, SL_R = 8, SL_SAMPLES = SL_NL * SL_NV * SL_VL * SL_R, SL_IN = 6 };

/* Sample s: n.l, n.v in (0, 1), v.l over [-0.95, 0.925], R/d up to 0.64,
 * alpha over [0.03, 0.87]; l.h the half vector's (1 + v.l)/2 root. */
static void sl_inputs(float *in)
{
    for (int s = 0; s < SL_SAMPLES; ++s) {
        int a = s % SL_NL, b = s / SL_NL % SL_NV, c = s / (SL_NL * SL_NV) % SL_VL, r = s / (SL_NL * SL_NV * SL_VL);
        float *x = in + SL_IN * s;
        x[0] = (a + 1) / 20.0f, x[1] = (b + 1) / 20.0f, x[2] = -0.95f + 0.125f * c;
        x[3] = sqrtf(fmaxf(0.0f, 0.5f + 0.5f * x[2]));
        x[4] = 0.01f * (r + 1) * (r + 1), x[5] = 0.03f + 0.12f * ((r + a + b) % 8);
    }
}

static float sl_c(const float *x, const decima_sphere_constants *k)
{
    return decima_sphere_ggx(x[0], x[1], x[2], x[3], x[4], x[5], 0.04f, k, 1);
}

/* The C's own spread when each input moves by 8 u either way. */
static double sl_spread(const float *x, const decima_sphere_constants *k)
{
    double centre = sl_c(x, k), spread = 0.0;
    for (int i = 0; i < SL_IN; ++i)
        for (int sign = -1; sign <= 1; sign += 2) {
            float y[SL_IN];
            memcpy(y, x, sizeof y);
            y[i] = (float)(x[i] * (1.0 + sign * 8.0 * kU));
            spread = fmax(spread, fabs(sl_c(y, k) - centre));
        }
    return spread;
}

static const char kSlGlslBody[] = "    uint b = 6u * i;\n"
                                  "    vec3 f = EvaluateSphericalAreaGGX(v[b], v[b + 1u], v[b + 2u], v[b + 3u], v[b + 4u], v[b + 5u], "
                                  "vec3(0.04f));\n"
                                  "    r[4u * i] = f.x, r[4u * i + 1u] = f.y, r[4u * i + 2u] = f.z;\n"
                                  "    r[4u * i + 3u] = GetNoHSquared(v[b + 4u], v[b], v[b + 1u], v[b + 2u]);\n";
static const char kSlHlslBody[] = "    uint b = 6u * i;\n"
                                  "    float3 f = EvaluateSphericalAreaGGX(v[b], v[b + 1u], v[b + 2u], v[b + 3u], v[b + 4u], v[b + 5u], "
                                  "float3(0.04f, 0.04f, 0.04f));\n"
                                  "    r[4u * i] = f.x; r[4u * i + 1u] = f.y; r[4u * i + 2u] = f.z;\n"
                                  "    r[4u * i + 3u] = GetNoHSquared(v[b + 4u], v[b], v[b + 1u], v[b + 2u]);\n";

/* Worst |gpu - c| / (64 u |c| + spread) of EvaluateSphericalAreaGGX, and
 * worst |gpu - c| / (64 u) of GetNoHSquared (in [0, 1]). */
static void sl_compare(const float *in, const float *out, const decima_sphere_constants *k, double *worst_ggx,
                       double *worst_noh, double *ulps)
{
    *worst_ggx = *worst_noh = *ulps = 0.0;
    for (int s = 0; s < SL_SAMPLES; ++s) {
        const float *x = in + SL_IN * s;
        double want = sl_c(x, k), bound = 64.0 * kU * fabs(want) + sl_spread(x, k);
        for (int c = 0; c < 3; ++c) {
            *worst_ggx = fmax(*worst_ggx, fabs(out[4 * s + c] - want) / bound);
            *ulps = fmax(*ulps, fabs(out[4 * s + c] - want) / (kU * fmax(fabs(want), 1e-30)));
        }
        double noh = sphere_noh_squared_decima(x[4], x[0], x[1], x[2]);
        *worst_noh = fmax(*worst_noh, fabs(out[4 * s + 3] - noh) / (64.0 * kU));
    }
}

static void test_sphere_light(gpu_device *g, shader_language language)
{
    decima_sphere_constants k = decima_sphere_published();
    char *functions = sphere_light_shader_source(language, &k, "gtlab test");
    char *source = functions ? test_sample_shader(language, functions, language == SHADER_GLSL ? kSlGlslBody : kSlHlslBody)
                             : NULL;
    float *in = malloc(SL_IN * sizeof(float) * SL_SAMPLES), *out = malloc(4 * sizeof(float) * SL_SAMPLES);
    gt_error e = {{0}};
    const char *name = language == SHADER_GLSL ? "sphere_light.glsl" : "sphere_light.hlsl";
    CHECK(source && in && out);
    if (source && in && out) {
        sl_inputs(in);
        int rc = gpu_sample_map(g, source, name, NULL, in, SL_IN, out, 4, SL_SAMPLES, 60.0, &e);
        CHECK_MSG(rc == 0, "%s", e.message);
        double ggx = 1e30, noh = 1e30, ulps = 1e30;
        if (rc == 0)
            sl_compare(in, out, &k, &ggx, &noh, &ulps);
        printf("%s: %d samples, worst |gpu - c| = %.3g (64 u |c| + spread) for the GGX (largest relative "
               "difference %.3g u), %.3g (64 u) for (N.H)^2 (bounds 1)\n", name, SL_SAMPLES, ggx, ulps, noh);
        CHECK_MSG(ggx <= 1.0 && noh <= 1.0, "%s: %g, %g", name, ggx, noh);
    }
    free(functions), free(source), free(in), free(out);
}

int main(void)
{
    gpu_device *g = NULL;
    gt_error e = {{0}};
    CHECK_MSG(gpu_device_open(NULL, &g, &e) == 0, "%s", e.message);
    if (g) {
        test_sphere_light(g, SHADER_GLSL);
        test_sphere_light(g, SHADER_HLSL);
        gpu_device_close(g);
    }
    return check_report("sphere_light_gpu");
}
