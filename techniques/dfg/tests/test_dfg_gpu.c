/* The DFG table's generated lookup DFG(), executed: as its writer writes it
 * (dfg/dfg_lut_writers.c: the table as constant arrays, then the lookup's
 * text, luts/table_lookup.inc), GLSL and HLSL, run on Vulkan at
 * pseudo-random points and compared with the C lookup (dfg_lut_sample) of
 * the same table at the same float inputs, within the bound of
 * tests/gpu/lut_shader_check.h. Small tables, because lavapipe's JIT lowers a constant array indexed at
 * run time to code whose compile time grows steeply with the array and the
 * number of reads: 8 x 8 texels compile in about a second; larger ones take
 * over a minute (the production tables are for real compilers).
 *
 * The bound's weights (s_a of the bound; bilinear: L = 2): x = saturate(u) N
 * - 0.5 is two correctly rounded operations (Vulkan's +, *), <= 2 u N each
 * side: s = 4 N. */
#define _GNU_SOURCE
#include "dfg/dfg_lut_writers.h"
#include "luts/dfg_lut.h"
#include "tests/gpu/lut_shader_check.h"

enum { DFG_N = 8 };

static void dfg_c(const void *table, const float *x, float *out) { dfg_lut_sample(table, x[0], x[1], out); }

static int dfg_write(const char *path, int glsl, const void *table, gt_error *e)
{
    return glsl ? dfg_lut_write_glsl(path, "gtlab_test_dfg", table, e)
                : dfg_lut_write_hlsl(path, "gtlab_test_dfg", table, e);
}

static void test_dfg(gpu_device *g)
{
    dfg_lut lut = {DFG_N, malloc(sizeof(float) * DFG_N * DFG_N * DFG_CHANNELS), NULL, 0.0};
    float *in = malloc(sizeof(float) * 2 * SAMPLES);
    CHECK(lut.data && in);
    if (!lut.data || !in) {
        free(lut.data), free(in);
        return;
    }
    fill_table(lut.data, DFG_N * DFG_N, DFG_CHANNELS, 1);
    unsigned long long state = 2;
    for (int s = 0; s < 2 * SAMPLES; ++s)
        in[s] = axis_point(&state, 1.0, DFG_N, 1);
    double bound[DFG_CHANNELS];
    square_bounds(lut.data, DFG_N, DFG_CHANNELS, 4.0 * DFG_N, 4.0 * DFG_N, bound);
    lookup_case k = {"DFG", 2, DFG_CHANNELS,
                     "    dfg_value d = DFG(v[2u * i], v[2u * i + 1u]);\n"
                     "    r[3u * i] = d.x; r[3u * i + 1u] = d.y; r[3u * i + 2u] = d.z;\n",
                     dfg_c, &lut, bound};
    run_both(g, &k, in, "dfg", dfg_write);
    free(lut.data), free(in);
}

int main(void)
{
    gpu_device *g = NULL;
    gt_error e = {{0}};
    CHECK_MSG(gpu_device_open(NULL, &g, &e) == 0, "%s", e.message);
    if (g) {
        test_dfg(g);
        gpu_device_close(g);
    }
    return check_report("dfg_gpu");
}
