/* The sphere-light study's numbers on a small sweep and a small fit:
 * invariants only (shortfalls and shares in range, percentiles ordered, the
 * Newton step better on average than Karis's point, errors consistent). */
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "tests/check.h"
#include "studies/sphere_light.h"

static void test_noh_sweep(const char *dir)
{
    sphere_noh_sweep sweep = {4, 4, 4, 4, 64};
    sphere_noh_stats st;
    gt_error e;
    CHECK(sphere_noh_study(&sweep, dir, &st, &e) == 0);
    CHECK(st.configurations == 256);
    CHECK(st.r_inside >= 0 && st.r_inside < st.configurations);
    CHECK(!st.rows[NOH_KARIS].has_baseline && st.rows[NOH_STEP1].has_baseline);
    for (int m = 0; m < NOH_METHODS; ++m) {
        const sphere_noh_row *r = &st.rows[m];
        CHECK_MSG(r->mean >= -1e-6 && r->mean <= r->worst && r->p99 <= r->worst, "%s", r->method);
        CHECK(r->share_worse >= 0.0 && r->share_better >= 0.0 && r->share_worse + r->share_better <= 1.0);
    }
    CHECK(st.rows[NOH_STEP1].mean < st.rows[NOH_KARIS].mean);
}

static void test_fit(void)
{
    sphere_fit_settings s = {128, 64, 64, 1, 1};
    static sphere_fit_outcome o;
    gt_error e;
    CHECK(sphere_fit_study(&s, &o, &e) == 0);
    CHECK(o.constants[0].published == 0.25 && o.constants[2].published == 3.0);
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j)
        CHECK(o.constants[j].value == o.fit.value[j]);
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m) {
        const sphere_light_errors *x = &o.held_out[m].errors;
        CHECK_MSG(x->mean_abs >= 0.0 && x->rms >= x->mean_abs && x->mean_abs_stderr >= 0.0, "%s",
                  o.held_out[m].method);
    }
    CHECK(o.mean_reference_rel_stderr > 0.0);
}

int main(void)
{
    char dir[4096];
    const char *tmp = getenv("GTLAB_TEST_TMP");
    snprintf(dir, sizeof dir, "%s/sphere_light_study", tmp ? tmp : "/tmp");
    mkdir(dir, 0755);
    test_noh_sweep(dir);
    test_fit();
    return check_report("test_sphere_light_study");
}
