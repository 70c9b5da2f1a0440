/* gtlab's specular-occlusion shaders, executed (issue 15, item 4): GTSO's
 * cone/cone forms (exact caps and Oat and Sander's), the form normalised
 * above the horizon, Lagarde's, GTSO's two apertures and Unity HDRP's
 * spherical Gaussians, as GLSL and HLSL (specular_occlusion/specular_occlusion_shader.h:
 * four .inc files, the very text the C compiles), run on Vulkan over a dense
 * grid of (cos a_v, cos a_s, beta, n.v, ao, alpha) and compared with the C
 * (double) on the same float inputs.
 *
 * The bound (techniques/specular_occlusion/README.md, "On Vulkan"), u = 2^-24: each value
 * lies in [0, 1] and the shader computes it in float in ~40 operations,
 * acos, cos, sin, exp2, pow and square roots among them. Where the function
 * is well conditioned that is a few tens of ulp, but for acos: Vulkan
 * allows it the error of atan2(sqrt(1 - x^2), x), 4096 ulp of the result
 * plus what it inherits from sqrt(1 - x^2) (1 - x^2 off by up to 2 u moves
 * y = sin a by min(sqrt(2 u), u / y), and the angle by |x| times that), and
 * lavapipe's acos is off by up to 1.6e-4 (2600 ulp of 1). Near the case
 * boundaries of the cap intersection (tangent caps), the mirror's step and
 * a thin reflection cone (cap = 2 pi (1 - cos a_s) cancels), moreover, a few
 * ulp of input move the value by more than any rounding inside. So the
 * bound is rounding plus conditioning, to first order:
 *   |gpu - c| <= 64 u + sum over inputs of the C's change when the input moves by 8 u
 *                     + sum over the acos calls of its change when that acos moves by its allowance
 *                     + the same for each sqrt moved by 16 u (relative: Vulkan's 1 / inversesqrt
 *                       and its argument's rounding; the SG form's L_1 - L_2 cancels),
 * the last two measured on a copy of the same .inc text compiled here with a
 * perturbed acos and sqrt (without the perturbation it equals the library's C bit
 * for bit: checked). */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gpu/sample_map.h"
#include "gpu/vulkan_device.h"
#include "specular_occlusion/specular_occlusion.h"
#include "specular_occlusion/specular_occlusion_sg.h"
#include "specular_occlusion/specular_occlusion_shader.h"
#include "tests/check.h"
#include "tests/gpu/sample_shader.h"

static const double kU = 1.0 / 16777216.0; /* 2^-24 */

enum { N_AV = 17, N_R = 17, N_BETA = 33, N_NV = 4, SAMPLES = N_AV * N_R * N_BETA * N_NV };
enum { IN_COS_AV, IN_COS_AS, IN_BETA, IN_N_DOT_V, IN_AO, IN_ALPHA, IN_COS_BETA, INPUTS };
enum { OUT_EXACT, OUT_OAT, OUT_HORIZON, OUT_LAGARDE, OUT_COS_AV, OUT_COS_AS, OUT_SG, OUTPUTS };

static const char *const kNames[OUTPUTS] = {"cone-exact", "cone-oat", "cone-horizon", "lagarde", "cos a_v", "cos a_s", "sg"};

/* Sample s: cos a_v over [0, 1] and its cosine AO 1 - cos^2 a_v; perceptual
 * roughness over [0, 1] as GTSO's alpha = max(r^2, 1e-4) and its exp2
 * aperture (a mirror's cos a_s = 1 in float at the smallest); beta over
 * [0, pi]; n.v in (0, 1). */
static void so_inputs(float *in)
{
    for (int s = 0; s < SAMPLES; ++s) {
        int a = s % N_AV, r = s / N_AV % N_R, b = s / (N_AV * N_R) % N_BETA, n = s / (N_AV * N_R * N_BETA);
        float *x = in + INPUTS * s;
        double roughness = r / (N_R - 1.0), alpha = fmax(roughness * roughness, 1e-4);
        x[IN_COS_AV] = (float)(a / (N_AV - 1.0));
        x[IN_AO] = 1.0f - x[IN_COS_AV] * x[IN_COS_AV];
        x[IN_ALPHA] = (float)alpha;
        x[IN_COS_AS] = (float)so_reflection_cos_exp2(alpha);
        x[IN_BETA] = (float)(M_PI * b / (N_BETA - 1.0));
        x[IN_N_DOT_V] = (n + 0.5f) / N_NV;
        x[IN_COS_BETA] = cosf(x[IN_BETA]);
    }
}

/* The functions compared: the library's, or the test's copy below. */
typedef struct {
    double (*cone_cone)(double, double, double, int);
    double (*above_horizon)(double, double, double, double);
    double (*lagarde)(double, double, double);
    double (*visibility_cos)(double);
    double (*reflection_cos)(double);
    double (*sg)(double, double, double, double);
} so_functions;

static const so_functions kLibrary = {so_cone_cone, so_cone_cone_above_horizon, so_lagarde, so_visibility_cos_cosine,
                                      so_reflection_cos_exp2, so_sg_occlusion};

/* Output k of f at the inputs x. */
static double so_eval(const so_functions *f, int k, const float *x)
{
    switch (k) {
    case OUT_EXACT: return f->cone_cone(x[IN_COS_AV], x[IN_COS_AS], x[IN_BETA], 1);
    case OUT_OAT: return f->cone_cone(x[IN_COS_AV], x[IN_COS_AS], x[IN_BETA], 0);
    case OUT_HORIZON: return f->above_horizon(x[IN_COS_AV], x[IN_COS_AS], x[IN_BETA], x[IN_N_DOT_V]);
    case OUT_LAGARDE: return f->lagarde(x[IN_N_DOT_V], x[IN_AO], x[IN_ALPHA]);
    case OUT_COS_AV: return f->visibility_cos(x[IN_AO]);
    case OUT_COS_AS: return f->reflection_cos(x[IN_ALPHA]);
    default: return f->sg(x[IN_COS_AV], x[IN_COS_BETA], x[IN_N_DOT_V], x[IN_ALPHA]);
    }
}

static double so_c(int k, const float *x) { return so_eval(&kLibrary, k, x); }

/* ---- The .inc text again, as C, with one acos call moved ---- */

static int g_moved_call = -1, g_calls; /* which acos call of an evaluation moves, and a counter */
static double g_sign;

/* Vulkan's allowance for acos(x) = a: 4096 ulp (float) of a, plus the error
 * inherited from y = sqrt(1 - x^2). */
static double acos_allowance(double x, double a)
{
    float af = (float)a;
    double y = sqrt(fmax(0.0, 1.0 - x * x)), inherited = y > 0.0 ? fmin(sqrt(2.0 * kU), kU / y) : sqrt(2.0 * kU);
    return 4096.0 * (nextafterf(af, INFINITY) - af) + fabs(x) * inherited;
}

static double moved_acos(double x)
{
    double a = acos(x);
    return g_calls++ == g_moved_call ? a + g_sign * acos_allowance(x, a) : a;
}

/* sqrt moved by 16 u (relative): Vulkan's 1 / inversesqrt (~5 ulp) and the
 * rounding of its argument, a sum of up to three products. */
static double moved_sqrt(double x)
{
    double r = sqrt(x);
    return g_calls++ == g_moved_call ? r * (1.0 + g_sign * 16.0 * kU) : r;
}

#define acos moved_acos
#define sqrt moved_sqrt
#define sg_sphere_integral moved_sg_sphere_integral
#define so_sg_lobe_sharpness moved_sg_lobe_sharpness
#define so_sg_cone_sharpness moved_sg_cone_sharpness
#define so_sg_product_sharpness moved_sg_product_sharpness
#define so_sg_inner_product moved_sg_inner_product
#define so_sg_occlusion moved_sg_occlusion
#define spherical_cap_solid_angle moved_cap_solid_angle
#define spherical_cap_intersection moved_cap_intersection
#define so_visibility_cos_cosine moved_visibility_cos_cosine
#define so_reflection_cos_exp2 moved_reflection_cos_exp2
#define so_cap_intersection_oat moved_cap_intersection_oat
#define so_cone_cone moved_cone_cone
#define so_cone_cone_above_horizon moved_cone_cone_above_horizon
#define so_lagarde moved_lagarde
#define acos_clamped moved_acos_clamped
#define so_clamp01 moved_clamp01
#define so_smoothstep01 moved_smoothstep01
#include "core/optics/shared_math_c.h"
#include "core/optics/spherical_caps.inc"
#include "specular_occlusion/specular_occlusion.inc"
#include "core/optics/spherical_gaussian.inc"
#include "specular_occlusion/specular_occlusion_sg.inc"
#undef acos
#undef sqrt
#undef so_sg_occlusion
#undef spherical_cap_solid_angle
#undef spherical_cap_intersection
#undef so_visibility_cos_cosine
#undef so_reflection_cos_exp2
#undef so_cap_intersection_oat
#undef so_cone_cone
#undef so_cone_cone_above_horizon
#undef so_lagarde

static const so_functions kMoved = {moved_cone_cone, moved_cone_cone_above_horizon, moved_lagarde,
                                    moved_visibility_cos_cosine, moved_reflection_cos_exp2, moved_sg_occlusion};

/* Output k of the copy, acos call `call` moved by `sign` allowances (-1: none). */
static double so_moved(int k, const float *x, int call, double sign)
{
    g_moved_call = call, g_sign = sign, g_calls = 0;
    return so_eval(&kMoved, k, x);
}

/* The conditioning part of the bound: the C's change when each input moves
 * by 8 u, summed over the inputs, plus its change when each acos call moves
 * by its allowance, summed over the calls. *same: the unmoved copy equals c. */
static double so_spread(int k, const float *x, int *same)
{
    enum { MAX_CALLS = 16 };
    double centre = so_c(k, x), spread = 0.0;
    *same = so_moved(k, x, -1, 0.0) == centre;
    for (int i = 0; i < INPUTS; ++i) {
        double worst = 0.0;
        for (int sign = -1; sign <= 1; sign += 2) {
            float y[INPUTS];
            memcpy(y, x, sizeof y);
            y[i] = (float)(x[i] * (1.0 + sign * 8.0 * kU));
            worst = fmax(worst, fabs(so_c(k, y) - centre));
        }
        spread += worst;
    }
    for (int call = 0; call < MAX_CALLS; ++call)
        spread += fmax(fabs(so_moved(k, x, call, 1.0) - centre), fabs(so_moved(k, x, call, -1.0) - centre));
    return spread;
}

static const char kGlslBody[] = "    uint b = 7u * i, o = 7u * i;\n"
                                "    r[o] = so_cone_cone(v[b], v[b + 1u], v[b + 2u], 1);\n"
                                "    r[o + 1u] = so_cone_cone(v[b], v[b + 1u], v[b + 2u], 0);\n"
                                "    r[o + 2u] = so_cone_cone_above_horizon(v[b], v[b + 1u], v[b + 2u], v[b + 3u]);\n"
                                "    r[o + 3u] = so_lagarde(v[b + 3u], v[b + 4u], v[b + 5u]);\n"
                                "    r[o + 4u] = so_visibility_cos_cosine(v[b + 4u]);\n"
                                "    r[o + 5u] = so_reflection_cos_exp2(v[b + 5u]);\n"
                                "    r[o + 6u] = so_sg_occlusion(v[b], v[b + 6u], v[b + 3u], v[b + 5u]);\n";

/* Per output: the worst |gpu - c| / bound, the largest |gpu - c| where the
 * bound is below 1e-3 (away from steps and tangencies) and the mean; the
 * number of samples where the moved copy unmoved differs from the C. */
static int so_compare(const float *in, const float *out, double worst[OUTPUTS], double diff[OUTPUTS],
                      double mean[OUTPUTS])
{
    int differ = 0;
    for (int k = 0; k < OUTPUTS; ++k)
        worst[k] = diff[k] = mean[k] = 0.0;
    for (int s = 0; s < SAMPLES; ++s)
        for (int k = 0; k < OUTPUTS; ++k) {
            const float *x = in + INPUTS * s;
            int same;
            double d = fabs(out[OUTPUTS * s + k] - so_c(k, x)), bound = 64.0 * kU + so_spread(k, x, &same);
            worst[k] = fmax(worst[k], d / bound);
            diff[k] = bound < 1e-3 ? fmax(diff[k], d) : diff[k];
            mean[k] += d / SAMPLES;
            differ += !same;
        }
    return differ;
}

static void test_language(gpu_device *g, shader_language language, const float *in, float *out)
{
    char *functions = specular_occlusion_shader_source(language, "gtlab test");
    char *source = functions ? test_sample_shader(language, functions, kGlslBody) : NULL;
    gt_error e = {{0}};
    const char *name = language == SHADER_GLSL ? "specular_occlusion.glsl" : "specular_occlusion.hlsl";
    CHECK(source != NULL);
    int rc = source ? gpu_sample_map(g, source, name, NULL, in, INPUTS, out, OUTPUTS, SAMPLES, 60.0, &e) : -1;
    CHECK_MSG(rc == 0, "%s", e.message);
    if (rc == 0) {
        double worst[OUTPUTS], diff[OUTPUTS], mean[OUTPUTS];
        int differ = so_compare(in, out, worst, diff, mean);
        CHECK_MSG(differ == 0, "the test's copy of the .inc differs from the C at %d points", differ);
        for (int k = 0; k < OUTPUTS; ++k) {
            printf("%s, %s: %d samples, worst %.3g of the bound; |gpu - c| %.3g at most where the bound < 1e-3, "
                   "%.3g on average\n", name, kNames[k], SAMPLES, worst[k], diff[k], mean[k]);
            CHECK_MSG(worst[k] <= 1.0, "%s, %s: %g", name, kNames[k], worst[k]);
        }
    }
    free(functions), free(source);
}

int main(void)
{
    gpu_device *g = NULL;
    gt_error e = {{0}};
    float *in = malloc(sizeof(float) * INPUTS * SAMPLES), *out = malloc(sizeof(float) * OUTPUTS * SAMPLES);
    CHECK(in && out);
    CHECK_MSG(gpu_device_open(NULL, &g, &e) == 0, "%s", e.message);
    if (g && in && out) {
        so_inputs(in);
        test_language(g, SHADER_GLSL, in, out);
        test_language(g, SHADER_HLSL, in, out);
    }
    gpu_device_close(g);
    free(in), free(out);
    return check_report("test_gpu_specular_occlusion");
}
