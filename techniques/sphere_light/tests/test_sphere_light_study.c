/* The sphere-light study's numbers on a small sweep and a small fit:
 * invariants only (shortfalls and shares in range, percentiles ordered, the
 * Newton step better on average than Karis's point, errors consistent).
 * The LTC's scores: the held-out samples regenerated are the fit's (Karis's
 * errors on them equal the fit's, bit for bit), each paired difference
 * equals the difference of the two means (an identity), and the N-gon's
 * error vanishes when the N-gon is the reference's own 1024-gon. */
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "ltc/ltc_fit.h"
#include "ltc/ltc_sphere.h"
#include "sphere_light/sphere_light_fit.h"
#include "sphere_light/sphere_light_study.h"
#include "tests/check.h"

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

static void test_ltc_scores(const sphere_fit_settings *s, const sphere_fit_outcome *o)
{
    sphere_light_sample *test = NULL;
    ltc_table t;
    gt_error e;
    CHECK(sphere_fit_held_out_samples(s, &test, &e) == 0 && ltc_fit_table(&t, 8, 1, &e) == 0);
    sphere_light_errors karis;
    sphere_light_measure(SPHERE_MODEL_KARIS, NULL, test, (size_t)s->test, &karis);
    CHECK(karis.mean_abs == o->held_out[SPHERE_FIT_KARIS].errors.mean_abs);
    sphere_ltc_result r;
    sphere_ltc_score(&t, test, s->test, o, &r);
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m)
        CHECK_NEAR(r.paired[m], o->held_out[m].errors.mean_abs - r.held_out.mean_abs, 1e-12);
    CHECK(r.held_out.mean_abs > 0.0 && r.held_out.rms >= r.held_out.mean_abs);
    CHECK(r.ngon_mean >= 0.0 && r.ngon_max >= r.ngon_mean);
    for (int i = 0; i < s->test; ++i)
        CHECK(sphere_ltc_ngon_error(&t, &test[i], LTC_MAX_SIDES) == 0.0);
    ltc_table_free(&t);
    free(test);
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
    test_ltc_scores(&s, &o);
}

int main(void)
{
    char dir[4096];
    const char *tmp = getenv("GTLAB_TEST_TMP");
    snprintf(dir, sizeof dir, "%s/sphere_light_study", tmp ? tmp : "/tmp");
    mkdir(dir, 0755);
    test_noh_sweep(dir);
    test_fit();
    return check_report("sphere_light_study");
}
