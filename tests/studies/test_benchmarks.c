/* The benchmarks' studies on a tiny view (builtin:corner, 16x16, 1 pass):
 * the figures are rates (positive), the derived rows are the quotients of the
 * measured ones, and a failing scene is an error. Timings themselves are not
 * checked. */
#include <string.h>

#include "studies/ao_convergence.h"
#include "studies/ray_throughput.h"
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

/* gtlab bench convergence on 8x8 images: every built-in scene measured in
 * both modes, the plane exact in both (RMSE 0), the time to the target and
 * the ratio consistent with the series. */
static void test_ao_convergence(void)
{
    static ao_convergence_result r;
    ao_convergence_request rq = {8, 8, 2, 256, 64, 0.05};
    gt_error e;
    CHECK(ao_convergence_run(&rq, &r, &e) == 0);
    CHECK(r.scene_count >= 6);
    for (int i = 0; i < r.scene_count; ++i) {
        const ao_convergence_scene *s = &r.scenes[i];
        for (int m = 0; m < CONVERGENCE_MODES; ++m) {
            CHECK(s->count[m] >= 1 && s->points[m][0].spp == AO_CONVERGENCE_FIRST_SPP);
            CHECK(s->points[m][0].seconds > 0.0 && s->points[m][0].rmse >= 0.0 && s->time_to_target[m] > 0.0);
            CHECK((s->kind[m] == TARGET_AT_FIRST) == (s->points[m][0].rmse <= rq.target));
            if (strcmp(s->scene, "plane") == 0)
                CHECK_MSG(s->points[m][0].rmse == 0.0, "plane, mode %d: RMSE %g", m, s->points[m][0].rmse);
        }
        CHECK(s->speedup == s->time_to_target[CONVERGENCE_PLAIN] / s->time_to_target[CONVERGENCE_CV]);
    }
}

int main(void)
{
    test_ray_throughput();
    test_ao_convergence();
    return check_report("studies_benchmarks");
}
