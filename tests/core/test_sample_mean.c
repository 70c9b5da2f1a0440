/* sample_mean_se against the textbook values of a small sample, and its
 * two-pass form where one pass would cancel: a tiny spread about 1e8. */
#include <math.h>

#include "core/sample_mean.h"
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
    return check_report("core_sample_mean");
}
