/* `gtlab bench rays` and the throughput stage's study on a tiny view
 * (builtin:corner, 16x16, 1 pass): the figures are rates (positive), each raw
 * call at most the best, the derived rows are the quotients of the measured
 * ones, and a failing scene is an error. Timings themselves are not checked. */
#include <string.h>

#include "tests/check.h"
#include "throughput/ray_throughput_study.h"

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

int main(void)
{
    test_ray_throughput();
    return check_report("throughput_study");
}
