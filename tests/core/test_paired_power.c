/* core/statistics/paired_power.h against independent answers: Student's quantiles
 * against the printed table (core/statistics/sample_mean.c's t_0.975 and the usual
 * t_0.80 values); the cases needed against the exact noncentral-t sample
 * sizes of the paired t-test (two-sided 5%, power 80%) as G*Power and
 * Cohen's tables print them, and, for small effects, against the normal
 * closed form with Guenther's correction n = ((z_a + z_b) / d)^2 + z_a^2 / 2
 * to within one case; only the ratio effect / spread matters. */
#include "core/statistics/paired_power.h"
#include "core/statistics/sample_mean.h"
#include "tests/check.h"

#include <math.h>

static void test_quantiles(void)
{
    for (int dof = 1; dof <= 30; ++dof)
        CHECK_NEAR(student_t_quantile(0.975, dof), student_t_975(dof), 6e-4); /* a 3-decimal table */
    CHECK_NEAR(student_t_quantile(0.80, 9), 0.8834, 1e-4);
    CHECK_NEAR(student_t_quantile(0.80, 30), 0.8538, 1e-4); /* table: 0.854 */
    CHECK_NEAR(student_t_quantile(0.5, 7), 0.0, 1e-12);
}

static void test_exact_sizes(void)
{
    /* effect size d_z = delta / sigma: n of the exact power computation */
    const double dz[4] = {0.5, 0.8, 1.0, 0.2};
    const int n[4] = {34, 15, 10, 199};
    for (int i = 0; i < 4; ++i)
        CHECK_MSG(paired_cases_needed(dz[i] * 0.03, 0.03, 0.8, 100000) == n[i], "d_z %g: %d", dz[i],
                  paired_cases_needed(dz[i] * 0.03, 0.03, 0.8, 100000));
    CHECK(paired_cases_needed(-0.5, 1.0, 0.8, 1000) == 34); /* the sign does not matter */
}

static void test_normal_limit(void)
{
    const double za = 1.959963984540054, zb = 0.8416212335729143;
    for (double dz = 0.05; dz <= 0.31; dz += 0.05) {
        double closed = (za + zb) * (za + zb) / (dz * dz) + za * za / 2.0;
        CHECK_NEAR(paired_cases_needed(dz, 1.0, 0.8, 1000000), closed, 1.0);
    }
}

static void test_edges(void)
{
    CHECK(paired_cases_needed(0.0, 1.0, 0.8, 1000) == -1);
    CHECK(paired_cases_needed(NAN, 1.0, 0.8, 1000) == -1);
    CHECK(paired_cases_needed(0.01, 1.0, 0.8, 100) == -1); /* needs ~78,000 */
    CHECK(paired_cases_needed(1.0, 0.0, 0.8, 100) == 2);
    CHECK(paired_cases_needed(1.0, 1.0, 1.0, 100) == -1);
    /* more power needs more cases */
    CHECK(paired_cases_needed(0.5, 1.0, 0.9, 1000) > paired_cases_needed(0.5, 1.0, 0.8, 1000));
}

int main(void)
{
    test_quantiles();
    test_exact_sizes();
    test_normal_limit();
    test_edges();
    return check_report("test_paired_power");
}
