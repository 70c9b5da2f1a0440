/* `gtlab bench specular-occlusion`'s study on a tiny view (builtin:corner,
 * 16x12, 1 pass): the figures are rates (positive), one ray per sample at
 * most, and a failing scene is an error. Timings themselves are not
 * checked (the other benchmarks: techniques/throughput/tests/,
 * techniques/ao/tests/test_ao_convergence.c). */
#include "specular_occlusion/specular_occlusion_bench.h"
#include "tests/check.h"

int main(void)
{
    specular_occlusion_bench_result r;
    gt_error e;
    CHECK(specular_occlusion_bench_run("builtin:corner", 16, 12, 2, 1, &r, &e) == 0);
    CHECK(r.width == 16 && r.height == 12);
    for (int t = 0; t < 2; ++t)
        CHECK(r.samples_per_s[t] > 0.0 && r.rays_per_s[t] > 0.0 && r.rays_per_s[t] <= r.samples_per_s[t]);
    CHECK(specular_occlusion_bench_run("builtin:no-such-scene", 16, 16, 1, 1, &r, &e) == -1);
    return check_report("specular_occlusion_bench");
}
