/* The AO reference's convergence benchmark (ao_convergence.h, `gtlab bench
 * convergence`) on a tiny view; the timings themselves are not checked. */
#include <string.h>

#include "ao/ao_convergence.h"
#include "tests/check.h"

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
    test_ao_convergence();
    return check_report("studies_ao_convergence");
}
