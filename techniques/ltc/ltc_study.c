/* The GGX LTC table fitted and written (ltc_study.h). */
#include "ltc/ltc_study.h"

#include "core/progress.h"
#include "ltc/ltc_fit.h"
#include "ltc/ltc_ggx_writers.h"

int ltc_table_fit_and_write(const char *dir, int size, int threads, ltc_table *t, double *seconds, gt_error *e)
{
    double t0 = seconds_now();
    if (ltc_fit_table(t, size, threads, e) != 0)
        return -1;
    *seconds = seconds_now() - t0;
    if (ltc_ggx_write_all(dir, "ltc_ggx", "LTC_GGX", t, e) != 0) {
        ltc_table_free(t);
        return -1;
    }
    return 0;
}
