/* `gtlab bench multibounce`'s study (multibounce_bench.h) on a tiny view
 * (builtin:corner, 16x16, 1 pass), as the other benchmarks' tests check
 * theirs (techniques/throughput/, techniques/ao/): the figures are rates (positive), a path casts at
 * least one ray, and a failing scene is an error. Timings themselves are
 * not checked. */
#include "multibounce/multibounce_bench.h"
#include "tests/check.h"

static void test_multibounce_bench(void)
{
    multibounce_settings settings = {0};
    settings.bounces = 2;
    multibounce_benchmark b;
    gt_error e;
    CHECK(multibounce_parse_albedos("0.2,0.8", &settings, &e) == 0);
    CHECK(multibounce_bench_run("builtin:corner", 16, 16, &settings, 2, 2, 1, &b, &e) == 0);
    CHECK(b.spp == 2 && b.threads == 2 && b.raw_rays > 0);
    for (int t = 0; t < 2; ++t)
        CHECK(b.paths_per_s[t] > 0.0 && b.rays_per_s[t] >= b.paths_per_s[t]);
    CHECK(multibounce_bench_run("builtin:no-such-scene", 16, 16, &settings, 2, 1, 1, &b, &e) == -1);
}

int main(void)
{
    test_multibounce_bench();
    return check_report("multibounce_bench");
}
