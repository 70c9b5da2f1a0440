/* The DFG table's interpolation study (dfg_interpolation.h): pseudo-random
 * points, their exact values by quadrature, and each table's lookup
 * against them. */
#include "dfg/dfg_interpolation.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>

#include "core/sampling/splitmix64.h"

/* The study's points (as floats, the lookup's argument type) and the exact
 * values at them: uv[2k], uv[2k+1]; exact[3k + c]. */
static void study_points(int points, unsigned seed, int threads, float *uv, double *exact)
{
    unsigned long long state = (unsigned long long)seed * 0x2545f4914f6cdd1dull + 1u;
    for (int k = 0; k < 2 * points; ++k)
        uv[k] = (float)splitmix64_uniform01(&state);
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
    for (int k = 0; k < points; ++k)
        dfg_integrate(uv[2 * k], uv[2 * k + 1], exact + 3 * k);
}

static int inside_centres(float u, int n) { return u >= 0.5f / n && u <= 1.0f - 0.5f / n; }

/* The errors of one table at the study's points. */
static void measure_table(const dfg_lut *lut, int points, const float *uv, const double *exact,
                          dfg_interpolation_result *out)
{
    double sum[3] = {0}, interior_sum[3] = {0};
    int interior = 0;
    for (int k = 0; k < points; ++k) {
        float got[3];
        dfg_lut_sample(lut, uv[2 * k], uv[2 * k + 1], got);
        int in = inside_centres(uv[2 * k], lut->size) && inside_centres(uv[2 * k + 1], lut->size);
        interior += in;
        for (int c = 0; c < DFG_CHANNELS; ++c) {
            double e = fabs(got[c] - exact[3 * k + c]);
            out->max_error[c] = fmax(out->max_error[c], e), sum[c] += e * e;
            if (in)
                out->interior_max_error[c] = fmax(out->interior_max_error[c], e), interior_sum[c] += e * e;
        }
    }
    out->interior_points = interior;
    for (int c = 0; c < DFG_CHANNELS; ++c) {
        out->rms_error[c] = sqrt(sum[c] / points);
        out->interior_rms_error[c] = interior ? sqrt(interior_sum[c] / interior) : 0.0;
    }
}

int dfg_interpolation_study(const int *sizes, int count, int points, unsigned seed, int threads,
                            dfg_interpolation_result *results)
{
    float *uv = malloc(sizeof *uv * 2 * (size_t)points);
    double *exact = malloc(sizeof *exact * 3 * (size_t)points);
    int rc = uv && exact && points > 0 ? 0 : -1;
    if (rc == 0)
        study_points(points, seed, threads, uv, exact);
    for (int s = 0; s < count && rc == 0; ++s) {
        dfg_lut lut;
        results[s] = (dfg_interpolation_result){.size = sizes[s]};
        double start = omp_get_wtime();
        rc = dfg_lut_build_any_size(&lut, sizes[s], threads);
        results[s].build_seconds = omp_get_wtime() - start;
        if (rc == 0)
            measure_table(&lut, points, uv, exact, &results[s]);
        dfg_lut_free(&lut);
    }
    free(uv);
    free(exact);
    return rc;
}
