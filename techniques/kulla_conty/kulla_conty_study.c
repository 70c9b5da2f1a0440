/* The Kulla-Conty study; see kulla_conty_study.h. */
#include "kulla_conty/kulla_conty_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/progress.h"
#include "kulla_conty/kulla_conty_quality.h"
#include "luts/dfg_lut.h"
#include "luts/lut_writers.h"

enum { WRITTEN_SIZE = 32 }; /* the table the study writes */

kulla_conty_request kulla_conty_default_request(study_quality quality)
{
    static const int sizes[] = {4, 8, 16, 32, 64, 128, 256};
    const kulla_conty_quality *q = kulla_conty_quality_of(quality);
    int count = sizeof sizes / sizeof sizes[0]; /* a size_count past the list (a table edit) takes all of it */
    count = q->size_count < count ? q->size_count : count;
    kulla_conty_request rq = {WRITTEN_SIZE, {0}, count, q->roughness_points, q->mu_points};
    memcpy(rq.sizes, sizes, sizeof sizes[0] * (size_t)count);
    return rq;
}

int kulla_conty_write_table(const char *dir, int size, int threads, double *bound, gt_error *e)
{
    kulla_conty_lut lut;
    if (kulla_conty_lut_build(&lut, size, threads) != 0)
        return gt_error_set(e, "kulla-conty", "cannot build a %d-entry table (sizes %d to %d)", size,
                            KULLA_CONTY_MIN_SIZE, KULLA_CONTY_MAX_SIZE);
    char base[64], identifier[64];
    snprintf(base, sizeof base, "kulla_conty_eavg_%d", size);
    snprintf(identifier, sizeof identifier, "KULLA_CONTY_EAVG_%d", size);
    int rc = lut_write_table(dir, base, identifier, lut.average_albedo, size, 1, kulla_conty_lut_description(), e);
    if (bound)
        *bound = lut.max_error_estimate;
    kulla_conty_lut_free(&lut);
    return rc;
}

/* The test points: exact E_avg at each roughness, exact E at each (mu, r). */
typedef struct {
    int roughness_count, mu_count;
    double *roughness, *average, *albedo; /* albedo[k * mu_count + m] = E(mu_m, r_k) */
} exact_points;

static double test_roughness(int k, int count) { return (k + 0.37) / count; }

static int exact_points_compute(const kulla_conty_request *rq, int threads, exact_points *p)
{
    int k_count = rq->roughness_points, m_count = rq->mu_points;
    *p = (exact_points){k_count, m_count, malloc(sizeof(double) * (size_t)k_count),
                        malloc(sizeof(double) * (size_t)k_count), malloc(sizeof(double) * (size_t)k_count * m_count)};
    if (!p->roughness || !p->average || !p->albedo)
        return -1;
#pragma omp parallel for num_threads(threads > 0 ? threads : 1) schedule(dynamic)
    for (int k = 0; k < k_count; ++k) {
        p->roughness[k] = test_roughness(k, k_count);
        p->average[k] = kulla_conty_average_albedo(p->roughness[k], NULL);
        for (int m = 0; m < m_count; ++m) {
            double e[DFG_CHANNELS];
            dfg_integrate((m + 0.5) / m_count, p->roughness[k], e);
            p->albedo[k * m_count + m] = e[DFG_ALBEDO];
        }
    }
    return 0;
}

static void exact_points_free(exact_points *p)
{
    free(p->roughness), free(p->average), free(p->albedo);
}

/* The white furnace of the compensated BRDF at E(mu_o) = albedo, exact E_avg
 * = average and the lobe's E_avg = used: E + (1 - E)(1 - average)/(1 - used). */
static double furnace_error(double albedo, double average, double used)
{
    return fabs(albedo + (1.0 - albedo) * (1.0 - average) / (1.0 - used) - 1.0);
}

/* Worst furnace error over the grid with the lobe's E_avg taken from `used`. */
static double max_furnace_error(const exact_points *p, const double *used)
{
    double worst = 0.0;
    for (int k = 0; k < p->roughness_count; ++k)
        for (int m = 0; m < p->mu_count; ++m)
            worst = fmax(worst, furnace_error(p->albedo[k * p->mu_count + m], p->average[k], used[k]));
    return worst;
}

static int score_size(int size, int threads, const exact_points *p, kulla_conty_size_row *row)
{
    kulla_conty_lut lut;
    double *used = malloc(sizeof(double) * (size_t)p->roughness_count);
    if (!used || kulla_conty_lut_build(&lut, size, threads) != 0) {
        free(used);
        return -1;
    }
    double worst = 0.0, squares = 0.0;
    for (int k = 0; k < p->roughness_count; ++k) {
        used[k] = kulla_conty_lut_sample(&lut, (float)p->roughness[k]);
        double d = fabs(used[k] - p->average[k]);
        worst = fmax(worst, d), squares += d * d;
    }
    *row = (kulla_conty_size_row){size, worst, sqrt(squares / p->roughness_count), max_furnace_error(p, used)};
    kulla_conty_lut_free(&lut);
    free(used);
    return 0;
}

static void loss_rows(kulla_conty_result *out)
{
    for (int i = 0; i < KULLA_CONTY_LOSS_ROWS; ++i) {
        double r = (i + 1.0) / KULLA_CONTY_LOSS_ROWS, average = kulla_conty_average_albedo(r, NULL);
        out->loss[i] = (kulla_conty_loss_row){r, average, 1.0 - average};
    }
}

int kulla_conty_study(const study_context *ctx, const kulla_conty_request *rq, kulla_conty_result *out,
                      gt_error *e)
{
    double start = seconds_now();
    *out = (kulla_conty_result){.request = *rq};
    char dir[4096];
    if (study_make_dir(ctx, KULLA_CONTY_DIR, dir, sizeof dir, e) != 0 ||
        kulla_conty_write_table(dir, rq->size, ctx->threads, &out->max_error_estimate, e) != 0)
        return -1;
    exact_points p;
    int rc = exact_points_compute(rq, ctx->threads, &p);
    for (int i = 0; rc == 0 && i < rq->size_count; ++i)
        rc = score_size(rq->sizes[i], ctx->threads, &p, &out->by_size[i]);
    exact_points_free(&p);
    if (rc != 0)
        return gt_error_set(e, "kulla-conty", "out of memory");
    loss_rows(out);
    out->seconds = seconds_now() - start;
    return 0;
}
