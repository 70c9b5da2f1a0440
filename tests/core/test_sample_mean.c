/* sample_mean_se against the textbook values of a small sample, and its
 * two-pass form where one pass would cancel: a tiny spread about 1e8. */
#include <math.h>

#include "core/statistics/sample_mean.h"
#include "tests/check.h"

int main(void)
{
    double x[4] = {1.0, 2.0, 3.0, 4.0}, mean, se;
    sample_mean_se(x, 4, &mean, &se);
    CHECK(mean == 2.5);
    CHECK(fabs(se - sqrt((5.0 / 3.0) / 4.0)) < 1e-15); /* s^2 = 5/3 */
    double y[3] = {1e8 + 1.0, 1e8 + 2.0, 1e8 + 3.0};
    sample_mean_se(y, 3, &mean, &se);
    CHECK(fabs(se - sqrt(1.0 / 3.0)) < 1e-9); /* s^2 = 1 */
    sample_mean_se(x, 1, &mean, &se);
    CHECK(mean == 1.0 && isnan(se));
    /* Student's t: the table's ends, the approximation beyond it against
     * t(40) = 2.021 and t(120) = 1.980 (Abramowitz and Stegun, table 26.10),
     * decreasing towards the normal quantile. */
    CHECK(student_t_975(2) == 4.303 && student_t_975(30) == 2.042 && isinf(student_t_975(0)));
    CHECK(fabs(student_t_975(40) - 2.021) < 1e-3 && fabs(student_t_975(120) - 1.980) < 1e-3);
    for (int dof = 1; dof < 200; ++dof)
        CHECK(student_t_975(dof + 1) < student_t_975(dof) && student_t_975(dof) > 1.959963984540054);
    return check_report("core_sample_mean");
}
