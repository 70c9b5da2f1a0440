/* gtlab's generated best-fit normals HLSL, executed (issue 15, item 4):
 * best_fit_normals/best_fit_normals_writers.c writes a small table's <base>.hlsl (the
 * talk's CompressNormalToUnsignedGBuffer over `Texture2D<float>
 * bestFitNormals; SamplerState pointClamp;`, and DecodeGBufferNormal); the
 * test wraps the two into a compute shader, binds the table as a sampled
 * R32F texture and a nearest, clamp-to-edge sampler (gpu/compute_dispatch.h)
 * and compares with the C (bfn_table_lookup, rgb8_encode, rgb8_decode) over
 * special and uniformly random unit normals.
 *
 * Bindings: the generated file declares its texture and sampler without a
 * binding (an engine assigns them); shaderc then puts both at binding 0, the
 * wrapper's uniform block's. The wrapper's text, not the generated file,
 * annotates them: it opens with
 *   #define Texture2D [[vk::binding(3)]] Texture2D
 *   #define SamplerState [[vk::binding(4)]] SamplerState
 * (a macro is not expanded again inside its own expansion).
 *
 * Which texel: the C picks floor(u N) (clamped) for the coordinate u in
 * double; the device picks the texel of its float u within its sub-texel
 * precision (Vulkan guarantees subTexelPrecisionBits >= 4). A sample whose
 * u N (or v N) lies within 2^-4 texel of a texel boundary may so read either
 * neighbour: there both texels' results are accepted (the count is printed);
 * elsewhere the texel must be the C's.
 *
 * The encode's bound, u = 2^-24: the shader computes p_i = (n_i s) / (m s) t
 * (s the normalisation, the same for every component, so it cancels but for
 * rounding): two products or divisions (<= 5 u relative each, Vulkan's
 * division is within 2.5 ulp), a division (5 u), the product with t (u):
 * 16 u relative on |p_i| <= 1; then * 0.5 (exact) + 0.5 (half an ulp of
 * [0.5, 1]: u / 2): |gpu - c| <= 8.5 u, taken as 9 u.
 * The decode of the C's codes k_i: x_i = k_i / 255 * 2 - 1 is within
 * 2.5 u * 2 + u / 2 = 5.5 u of the exact (a division, a doubling, a
 * subtraction rounding once); a vector moved by |dx| <= 5.5 sqrt(3) u turns
 * x / |x| by <= 2 |dx| / |x|; the normalisation's own rounding (dot,
 * inversesqrt within 2 ulp, product) adds <= 7.5 u per component:
 * |gpu - c| <= u (11 sqrt(3) / |x| + 7.5), taken with 8. */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/sampling/splitmix64.h"
#include "gpu/compute_dispatch.h"
#include "gpu/sample_map.h"
#include "gpu/shader_compiler.h"
#include "gpu/vulkan_device.h"
#include "best_fit_normals/best_fit_normals.h"
#include "best_fit_normals/best_fit_normals_writers.h"
#include "best_fit_normals/normal_encoding.h"
#include "tests/check.h"

static const double kU = 1.0 / 16777216.0; /* 2^-24 */
static const double kSubTexel = 1.0 / 16.0; /* Vulkan's least subTexelPrecisionBits, 4 */

enum { BFN_N = 32, SAMPLES = 1 << 14, IN_STRIDE = 6, OUT_STRIDE = 6, SPECIAL = 14 };

/* ---- Inputs: unit normals (float) and the C's codes ---- */

static const float kSpecial[SPECIAL][3] = {
    {1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0.70710678f, 0.70710678f, 0}, {0.57735027f, -0.57735027f, 0.57735027f},
    {0.6f, 0.8f, 0}, {0.48f, 0.6f, 0.64f}, {-0.64f, 0.48f, 0.6f}, {0.6f, 0.6f, 0.52915026f}, {0, 0.6f, -0.8f},
    {0.36f, 0.48f, -0.8f}, {-0.8f, 0.36f, 0.48f}, {0.1f, 0.2f, -0.9746794f}, {0.9999f, 0.01f, 0.00994987f}};

/* Sample s's normal: a special one, else uniform on the sphere. */
static void normal_of(int s, unsigned long long *state, float n[3])
{
    if (s < SPECIAL) {
        memcpy(n, kSpecial[s], sizeof(float) * 3);
        return;
    }
    double z = 2.0 * splitmix64_uniform01(state) - 1.0, phi = 2.0 * M_PI * splitmix64_uniform01(state);
    double r = sqrt(fmax(0.0, 1.0 - z * z));
    n[0] = (float)(r * cos(phi)), n[1] = (float)(r * sin(phi)), n[2] = (float)z;
}

static void inputs(const best_fit_table *table, float *in)
{
    unsigned long long state = 15;
    for (int s = 0; s < SAMPLES; ++s) {
        float *x = in + (size_t)s * IN_STRIDE;
        normal_of(s, &state, x);
        double n[3] = {x[0], x[1], x[2]};
        int code[3];
        rgb8_encode(RGB8_BEST_FIT_POINT, table, n, code);
        for (int i = 0; i < 3; ++i)
            x[3 + i] = (float)code[i];
    }
}

/* ---- The shader ---- */

static const char kWrapper[] =
    "#define Texture2D [[vk::binding(3)]] Texture2D\n"
    "#define SamplerState [[vk::binding(4)]] SamplerState\n"
    "%s\n"
    "[[vk::binding(0)]] cbuffer Params { uint count; };\n"
    "[[vk::binding(1)]] StructuredBuffer<float> v;\n"
    "[[vk::binding(2)]] RWStructuredBuffer<float> r;\n"
    "[numthreads(%d, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID)\n{\n"
    "    uint i = id.x;\n    if (i >= count)\n        return;\n"
    "    float3 c = CompressNormalToUnsignedGBuffer(float3(v[6u * i], v[6u * i + 1u], v[6u * i + 2u]));\n"
    "    float3 d = DecodeGBufferNormal(float3(v[6u * i + 3u], v[6u * i + 4u], v[6u * i + 5u]) / 255.0);\n"
    "    r[6u * i] = c.x; r[6u * i + 1u] = c.y; r[6u * i + 2u] = c.z;\n"
    "    r[6u * i + 3u] = d.x; r[6u * i + 4u] = d.y; r[6u * i + 5u] = d.z;\n}\n";

/* The generated file wrapped; NULL with a failed check. */
static char *wrapped_source(const char *path)
{
    char *functions = NULL, *source = NULL;
    gt_error e = {{0}};
    int rc = gpu_read_source(path, &functions, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    if (rc == 0 && asprintf(&source, kWrapper, functions, GPU_SAMPLE_GROUP) < 0)
        source = NULL;
    free(functions);
    return source;
}

/* Runs the compiled shader with the table at bindings texture_at and
 * sampler_at (3 and 4 as declared; swapped to provoke the binding error). */
static int run(gpu_device *g, const gpu_spirv *spirv, const float *table, const float *in, float *out, int swapped,
               gt_error *e)
{
    uint32_t params[4] = {SAMPLES, 0, 0, 0};
    gpu_texture_r32f texture = {BFN_N, BFN_N, table};
    gpu_buffer texture_binding = {"bestFitNormals", GPU_TEXTURE_R32F, &texture, sizeof texture};
    gpu_buffer sampler_binding = {"pointClamp", GPU_SAMPLER_POINT_CLAMP, NULL, 0};
    gpu_buffer buffers[5] = {{"count", GPU_UNIFORM, params, sizeof params},
                             {"inputs", GPU_INPUT, (void *)in, sizeof(float) * IN_STRIDE * SAMPLES},
                             {"outputs", GPU_OUTPUT, out, sizeof(float) * OUT_STRIDE * SAMPLES},
                             swapped ? sampler_binding : texture_binding,
                             swapped ? texture_binding : sampler_binding};
    gpu_dispatch d = {spirv, "best_fit_normals.hlsl", buffers, 5, {SAMPLES / GPU_SAMPLE_GROUP, 1, 1}, 60.0};
    return gpu_dispatch_run(g, &d, NULL, e);
}

/* ---- The comparison ---- */

/* The distance (texels) of x from the nearest texel boundary. */
static double boundary_distance(double x)
{
    return fabs(x - floor(x + 0.5));
}

/* The texel indices a coordinate x (texel units) may read: one, or both
 * neighbours within the sub-texel band of a boundary; clamped to [0, N). */
static int candidates(double x, int index[2])
{
    int lo = (int)floor(x - kSubTexel), hi = (int)floor(x + kSubTexel);
    index[0] = lo < 0 ? 0 : (lo >= BFN_N ? BFN_N - 1 : lo);
    index[1] = hi < 0 ? 0 : (hi >= BFN_N ? BFN_N - 1 : hi);
    return index[0] == index[1] ? 1 : 2;
}

/* The table coordinates (u, v) of n: the two smaller |components| a >= b,
 * u = a, v = b / a (best_fit_normals/best_fit_normals.h). */
static void coordinates(const double n[3], double *u, double *v)
{
    double x = fabs(n[0]), y = fabs(n[1]), z = fabs(n[2]), m = fmax(x, fmax(y, z));
    double a = z < m ? (y < m ? y : x) : x, b = z < m ? z : y;
    *u = fmax(a, b), *v = fmax(a, b) > 0.0 ? fmin(a, b) / fmax(a, b) : 0.0;
}

typedef struct {
    double encode_worst, decode_worst; /* of the bound */
    double off_texel_distance;         /* the largest distance (texels) from a boundary of a neighbour read */
    int ambiguous, off_texel, c_texel_mismatch;
} bfn_stats;

/* |gpu - c| / bound of the encode reading texel `texel`. */
static double encode_error_at(const float *table, const double n[3], const float *gpu, int texel)
{
    double m = fmax(fabs(n[0]), fmax(fabs(n[1]), fabs(n[2]))), t = table[texel], worst = 0.0;
    for (int i = 0; i < 3; ++i)
        worst = fmax(worst, fabs(gpu[i] - (n[i] / m * t * 0.5 + 0.5)) / (9.0 * kU));
    return worst;
}

/* The least |gpu - c| / bound over the candidate texels, the C's texel
 * c_texel first (a neighbour holding the same scale is not counted as read);
 * *texel: the one that gave it. */
static double encode_error(const float *table, const double n[3], const float *gpu, int c_texel, int *texel)
{
    double u, v, best = encode_error_at(table, n, gpu, c_texel);
    int is[2], js[2];
    coordinates(n, &u, &v);
    int ni = candidates(u * BFN_N, is), nj = candidates(v * BFN_N, js);
    *texel = c_texel;
    for (int a = 0; a < ni; ++a)
        for (int b = 0; b < nj; ++b) {
            double worst = encode_error_at(table, n, gpu, js[b] * BFN_N + is[a]);
            if (worst < best)
                best = worst, *texel = js[b] * BFN_N + is[a];
        }
    return best;
}

static double decode_error(const float *in, const float *gpu)
{
    int code[3] = {(int)in[3], (int)in[4], (int)in[5]};
    double d[3], x[3], worst = 0.0;
    rgb8_decode(code, d);
    for (int i = 0; i < 3; ++i)
        x[i] = bfn_code_value(code[i]);
    double bound = kU * (11.0 * sqrt(3.0) / sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) + 8.0);
    for (int i = 0; i < 3; ++i)
        worst = fmax(worst, fabs(gpu[i] - d[i]) / bound);
    return worst;
}

static bfn_stats compare(const float *table, const float *in, const float *out)
{
    bfn_stats st = {0.0, 0.0, 0.0, 0, 0, 0};
    for (int s = 0; s < SAMPLES; ++s) {
        const float *x = in + (size_t)s * IN_STRIDE, *y = out + (size_t)s * OUT_STRIDE;
        double n[3] = {x[0], x[1], x[2]}, u, v;
        int texel = -1, is[2], js[2];
        coordinates(n, &u, &v);
        /* the C's own lookup reads the texel at floor(u N), floor(v N) */
        int c_texel = (int)fmin(BFN_N - 1, floor(v * BFN_N)) * BFN_N + (int)fmin(BFN_N - 1, floor(u * BFN_N));
        st.encode_worst = fmax(st.encode_worst, encode_error(table, n, y, c_texel, &texel));
        st.decode_worst = fmax(st.decode_worst, decode_error(x, y + 3));
        st.ambiguous += candidates(u * BFN_N, is) * candidates(v * BFN_N, js) > 1;
        st.c_texel_mismatch += bfn_table_lookup(table, BFN_N, 0, n) != table[c_texel];
        if (texel != c_texel) {
            double du = boundary_distance(u * BFN_N), dv = boundary_distance(v * BFN_N);
            st.off_texel_distance = fmax(st.off_texel_distance, texel % BFN_N != c_texel % BFN_N ? du : dv);
            ++st.off_texel;
        }
    }
    return st;
}

/* ---- Tests ---- */

static void test_encode_decode(gpu_device *g, const float *table, const gpu_spirv *spirv)
{
    best_fit_table bt = {table, BFN_N};
    float *in = malloc(sizeof(float) * IN_STRIDE * SAMPLES), *out = malloc(sizeof(float) * OUT_STRIDE * SAMPLES);
    gt_error e = {{0}};
    CHECK(in && out);
    if (in && out) {
        inputs(&bt, in);
        int rc = run(g, spirv, table, in, out, 0, &e);
        CHECK_MSG(rc == 0, "%s", e.message);
        bfn_stats st = rc == 0 ? compare(table, in, out) : (bfn_stats){1e30, 1e30, 0.0, 0, 0, 0};
        printf("best-fit normals (HLSL, %d x %d table): %d normals, worst encode %.3g and decode %.3g of the bound; "
               "%d within 1/16 texel of a boundary, %d read the neighbour texel (at most %.3g texel from the "
               "boundary)\n", BFN_N, BFN_N, SAMPLES, st.encode_worst, st.decode_worst, st.ambiguous, st.off_texel,
               st.off_texel_distance);
        CHECK_MSG(st.encode_worst <= 1.0, "encode: %g of the bound", st.encode_worst);
        CHECK_MSG(st.decode_worst <= 1.0, "decode: %g of the bound", st.decode_worst);
        CHECK_MSG(st.c_texel_mismatch == 0, "%d C lookups off floor(u N)", st.c_texel_mismatch);
    }
    free(in), free(out);
}

/* The texture and sampler at each other's bindings: one clear line. */
static void test_swapped_bindings(gpu_device *g, const float *table, const gpu_spirv *spirv)
{
    float *in = calloc(IN_STRIDE * SAMPLES, sizeof(float)), *out = malloc(sizeof(float) * OUT_STRIDE * SAMPLES);
    gt_error e = {{0}};
    CHECK(in && out);
    if (in && out) {
        CHECK(run(g, spirv, table, in, out, 1, &e) != 0);
        CHECK_MSG(strstr(e.message, "best_fit_normals.hlsl: binding 3 is declared as a sampled image (Texture2D); "
                                    "gtlab binds the sampler (SamplerState) pointClamp there"),
                  "%s", e.message);
    }
    free(in), free(out);
}

/* A GLSL sampler2D (the combined kind) over a 5 x 3 texture of distinct
 * texels, read at every texel centre and outside [0, 1]: the texel of
 * row y = floor(v H), column x = floor(u W), clamped, exactly. */
static void test_combined_glsl(gpu_device *g)
{
    enum { W = 5, H = 3, POINTS = 64 };
    float texels[W * H], uv[2 * POINTS], got[POINTS];
    for (int t = 0; t < W * H; ++t)
        texels[t] = (float)(t * t) + 0.25f;
    for (int p = 0; p < POINTS; ++p) /* centres of a 8 x 8 grid over [-0.5, 1.5)^2: inside and clamped */
        uv[2 * p] = (float)(-0.5 + ((p % 8) + 0.5) / 4.0), uv[2 * p + 1] = (float)(-0.5 + ((p / 8) + 0.5) / 4.0);
    const char *source = "#version 450\nlayout(local_size_x = 64) in;\n"
                         "layout(std140, binding = 0) uniform Params { uint count; };\n"
                         "layout(std430, binding = 1) readonly buffer In { vec2 uv[]; };\n"
                         "layout(std430, binding = 2) writeonly buffer Out { float r[]; };\n"
                         "layout(binding = 3) uniform sampler2D t;\n"
                         "void main() { uint i = gl_GlobalInvocationID.x; if (i < count) r[i] = "
                         "textureLod(t, uv[i], 0.0).r; }\n";
    gpu_spirv spirv;
    gt_error e = {{0}};
    uint32_t params[4] = {POINTS, 0, 0, 0};
    gpu_texture_r32f texture = {W, H, texels};
    gpu_buffer buffers[4] = {{"count", GPU_UNIFORM, params, sizeof params},
                             {"uv", GPU_INPUT, uv, sizeof uv},
                             {"r", GPU_OUTPUT, got, sizeof got},
                             {"t", GPU_TEXTURE_R32F_POINT_CLAMP, &texture, sizeof texture}};
    gpu_dispatch d = {&spirv, "combined.glsl", buffers, 4, {1, 1, 1}, 60.0};
    int compiled = gpu_compile_compute(source, d.what, GPU_SOURCE_GLSL, NULL, &spirv, &e) == 0;
    int rc = compiled ? gpu_dispatch_run(g, &d, NULL, &e) : -1;
    CHECK_MSG(rc == 0, "%s", e.message);
    int wrong = 0;
    for (int p = 0; rc == 0 && p < POINTS; ++p) {
        int x = (int)fmin(W - 1, fmax(0, floor(uv[2 * p] * W)));
        int y = (int)fmin(H - 1, fmax(0, floor(uv[2 * p + 1] * H)));
        wrong += got[p] != texels[y * W + x];
    }
    CHECK_MSG(wrong == 0, "%d of %d sampler2D reads off the texel", wrong, POINTS);
    if (compiled)
        gpu_spirv_free(&spirv);
}

int main(void)
{
    gpu_device *g = NULL;
    gt_error e = {{0}};
    float *table = bfn_table_build(BFN_N, BFN_ERROR_ANGLE, 1);
    char path[4096];
    CHECK(table);
    int rc = table ? bfn_table_write_all(check_tmp_dir(), "test_gpu_bfn", table, BFN_N, "test table", &e) : -1;
    CHECK_MSG(rc == 0, "%s", e.message);
    snprintf(path, sizeof path, "%s/test_gpu_bfn.hlsl", check_tmp_dir());
    char *source = rc == 0 ? wrapped_source(path) : NULL;
    gpu_spirv spirv;
    CHECK_MSG(gpu_device_open(NULL, &g, &e) == 0, "%s", e.message);
    if (g && source) {
        rc = gpu_compile_compute(source, path, GPU_SOURCE_HLSL, NULL, &spirv, &e);
        CHECK_MSG(rc == 0, "%s", e.message);
        if (rc == 0) {
            test_encode_decode(g, table, &spirv);
            test_swapped_bindings(g, table, &spirv);
            gpu_spirv_free(&spirv);
        }
        test_combined_glsl(g);
    }
    gpu_device_close(g);
    free(source), free(table);
    return check_report("test_gpu_bfn_shader");
}
