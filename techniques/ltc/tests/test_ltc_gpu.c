/* The LTC table's generated lookups LTC_INVERSE_M and LTC_MAGNITUDE_FRESNEL,
 * executed: as its writer writes them (ltc/ltc_ggx_writers.c: the table as
 * constant arrays, then the lookup's text, luts/table_lookup.inc), GLSL and
 * HLSL, run on Vulkan at pseudo-random points and compared with the C lookup
 * (ltc_table_sample) of the same table at the same float inputs, within the
 * bound of tests/gpu/lut_shader_check.h. Small tables, because lavapipe's JIT lowers a constant array indexed at
 * run time to code whose compile time grows steeply with the array and the
 * number of reads: 4 x 4 texels compile in about a second; larger ones take
 * over a minute (the production tables are for real compilers).
 *
 * The bound's weights (s_a of the bound; bilinear: L = 2): x = saturate(u) N
 * - 0.5 is two correctly rounded operations (Vulkan's +, *), <= 2 u N each
 * side: s = 4 N; the first axis adds sqrt(1 - n.v) (Vulkan: 1 /
 * inversesqrt, taken as 16 u relative as in
 * techniques/specular_occlusion/tests/test_gpu_specular_occlusion.c), times
 * N: s = 20 N. */
#define _GNU_SOURCE
#include "ltc/ltc_ggx.h"
#include "ltc/ltc_ggx_writers.h"
#include "tests/gpu/lut_shader_check.h"

enum { LTC_N = 4 };

static void ltc_c(const void *table, const float *x, float *out) { ltc_table_sample(table, x[0], x[1], out); }

static int ltc_write(const char *path, int glsl, const void *table, gt_error *e)
{
    return glsl ? ltc_ggx_write_glsl(path, "gtlab_test_ltc", table, e)
                : ltc_ggx_write_hlsl(path, "gtlab_test_ltc", table, e);
}

static void test_ltc(gpu_device *g)
{
    ltc_table t;
    float *in = malloc(sizeof(float) * 2 * SAMPLES);
    int allocated = ltc_table_alloc(&t, LTC_N) == 0;
    CHECK(allocated && in);
    if (!allocated || !in) {
        free(in);
        return;
    }
    fill_table(t.data, LTC_N * LTC_N, LTC_CHANNELS, 3);
    unsigned long long state = 4;
    for (int s = 0; s < SAMPLES; ++s) { /* n.v = 1 - u^2 at u's special points; roughness */
        float u = axis_point(&state, 1.0, LTC_N, 1);
        in[2 * s] = 1.0f - u * u, in[2 * s + 1] = axis_point(&state, 1.0, LTC_N, 1);
    }
    double bound[LTC_CHANNELS];
    square_bounds(t.data, LTC_N, LTC_CHANNELS, 20.0 * LTC_N, 4.0 * LTC_N, bound);
    lookup_case k = {"LTC", 2, LTC_CHANNELS,
                     "    dfg_value m = LTC_INVERSE_M(v[2u * i], v[2u * i + 1u]);\n"
                     "    dfg_value f = LTC_MAGNITUDE_FRESNEL(v[2u * i], v[2u * i + 1u]);\n"
                     "    r[6u * i] = m.x; r[6u * i + 1u] = m.y; r[6u * i + 2u] = m.z; r[6u * i + 3u] = m.w;\n"
                     "    r[6u * i + 4u] = f.x; r[6u * i + 5u] = f.y;\n",
                     ltc_c, &t, bound};
    run_both(g, &k, in, "ltc", ltc_write);
    ltc_table_free(&t), free(in);
}

int main(void)
{
    gpu_device *g = NULL;
    gt_error e = {{0}};
    CHECK_MSG(gpu_device_open(NULL, &g, &e) == 0, "%s", e.message);
    if (g) {
        test_ltc(g);
        gpu_device_close(g);
    }
    return check_report("ltc_gpu");
}
