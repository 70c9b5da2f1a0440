/* The benchmarks' studies on a tiny view (builtin:corner, 16x16, 1 pass):
 * the figures are rates (positive), the derived rows are the quotients of the
 * measured ones, and a failing scene is an error. Timings themselves are not
 * checked. */
#include <string.h>

#include "studies/multibounce_bench.h"
#include "studies/ray_throughput.h"
#include "studies/specular_occlusion_bench.h"
#include "tests/check.h"

static void test_ray_throughput(void)
{
    ray_throughput_result r;
    gt_error e;
    CHECK(ray_throughput_measure("builtin:corner", 16, 16, 2, 1, &r, &e) == 0);
    CHECK(strcmp(r.scene, "builtin:corner") == 0 && r.repeats == 1 && r.threads == 2 && r.rays_per_pass > 0);
    for (int call = 0; call < RAW_CALL_COUNT; ++call) {
        CHECK(r.rows[call].one_thread > 0.0 && r.rows[call].one_thread <= r.raw_best_1_thread);
        CHECK(r.rows[call].threads > 0.0 && r.rows[call].threads <= r.raw_best_threads);
    }
    const ray_throughput_row *gtlab = &r.rows[RAY_THROUGHPUT_GTLAB_ROW], *ratio = &r.rows[RAY_THROUGHPUT_RATIO_ROW];
    CHECK(!gtlab->is_ratio && ratio->is_ratio);
    CHECK(ratio->one_thread == gtlab->one_thread / r.raw_best_1_thread);
    CHECK(ratio->threads == gtlab->threads / r.raw_best_threads && r.ratio_threads == ratio->threads);
    CHECK(r.speedup_gtlab == r.gtlab_ao_threads / r.gtlab_ao_1_thread);
    CHECK(ray_throughput_measure("builtin:no-such-scene", 16, 16, 1, 1, &r, &e) == -1);
}

static void test_specular_occlusion(void)
{
    specular_occlusion_bench_result r;
    gt_error e;
    CHECK(specular_occlusion_bench_run("builtin:corner", 16, 12, 2, 1, &r, &e) == 0);
    CHECK(r.width == 16 && r.height == 12);
    for (int t = 0; t < 2; ++t)
        CHECK(r.samples_per_s[t] > 0.0 && r.rays_per_s[t] > 0.0 && r.rays_per_s[t] <= r.samples_per_s[t]);
    CHECK(specular_occlusion_bench_run("builtin:no-such-scene", 16, 16, 1, 1, &r, &e) == -1);
}

static void test_multibounce(void)
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
    test_ray_throughput();
    test_specular_occlusion();
    test_multibounce();
    return check_report("studies_benchmarks");
}
