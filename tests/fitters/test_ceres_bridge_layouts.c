/* The ways a caller can cut samples into residual blocks (one block per
 * sample, as a robust loss per sample needs; blocks of 1024; one block of
 * all) and the two linear solvers all reach the same least-squares optimum
 * with the same standard errors. The model is the multi-bounce cubic
 * y = ((a x + b) x + c) x, linear in its 3 parameters. How long each layout
 * takes is measured by `gtlab bench fit`, not here. */
#include "fitters/ceres_bridge.h"
#include "tests/check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { kSamples = 200000, kChunk = 1024 };
static const double kTruth[3] = {0.6878, -1.75585, 2.0679};

typedef struct {
    const double *x, *y;
    int count;
} chunk;

/* Residuals model(x_i) - y_i of the chunk's samples, Jacobian rows
 * (x^3, x^2, x). */
static int cubic_chunk(void *user, const double *p, double *r, double *jacobian)
{
    const chunk *c = user;
    for (int i = 0; i < c->count; ++i) {
        double x = c->x[i];
        r[i] = ((p[0] * x + p[1]) * x + p[2]) * x - c->y[i];
        if (jacobian) {
            jacobian[3 * i + 0] = x * x * x;
            jacobian[3 * i + 1] = x * x;
            jacobian[3 * i + 2] = x;
        }
    }
    return 0;
}

typedef struct {
    const char *name;
    int chunk_size;
    gt_fit_linear_solver solver;
} layout;

typedef struct {
    double p[3], se[3];
} solution;

/* Fits all samples cut into chunks of `size` (the last one shorter). */
static int fit(const double *x, const double *y, const layout *l, solution *t)
{
    gt_error e = {{0}};
    size_t chunk_count = (kSamples + (size_t)l->chunk_size - 1) / (size_t)l->chunk_size;
    chunk *chunks = malloc(chunk_count * sizeof *chunks);
    memcpy(t->p, (double[3]){1.0, -1.0, 1.0}, sizeof t->p);
    gt_fit *f = gt_fit_create(3, t->p, &e);
    int status = f ? 0 : -1;
    for (size_t k = 0; k < chunk_count && status == 0; ++k) {
        size_t first = k * (size_t)l->chunk_size;
        chunks[k].x = x + first;
        chunks[k].y = y + first;
        chunks[k].count = (int)(kSamples - first < (size_t)l->chunk_size ? kSamples - first : (size_t)l->chunk_size);
        status = gt_fit_add_block(f, chunks[k].count, cubic_chunk, &chunks[k], NULL, &e);
    }
    gt_fit_options o = gt_fit_default_options();
    o.linear_solver = l->solver;
    if (status == 0)
        status = gt_fit_solve(f, &o, NULL, &e);
    if (status == 0)
        status = gt_fit_covariance(f, NULL, t->se, NULL, &e);
    gt_fit_destroy(f);
    if (status != 0)
        fprintf(stderr, "%s: %s\n", l->name, e.message);
    free(chunks);
    return status;
}

int main(void)
{
    double *x = malloc(kSamples * sizeof *x), *y = malloc(kSamples * sizeof *y);
    for (int i = 0; i < kSamples; ++i) {
        x[i] = (i + 0.5) / kSamples;
        /* A deterministic stand-in for noise, 0.01 in amplitude. */
        y[i] = ((kTruth[0] * x[i] + kTruth[1]) * x[i] + kTruth[2]) * x[i] + 0.01 * sin(12.9898 * i);
    }
    const layout layouts[] = {
        {"1 sample a block, DENSE_NORMAL_CHOLESKY", 1, GT_FIT_DENSE_NORMAL_CHOLESKY},
        {"1 sample a block, DENSE_QR", 1, GT_FIT_DENSE_QR},
        {"1024 samples a block, DENSE_QR", kChunk, GT_FIT_DENSE_QR},
        {"all samples in 1 block, DENSE_QR", kSamples, GT_FIT_DENSE_QR},
    };
    const int count = (int)(sizeof layouts / sizeof layouts[0]);
    solution t[sizeof layouts / sizeof layouts[0]];
    for (int k = 0; k < count; ++k) {
        CHECK(fit(x, y, &layouts[k], &t[k]) == 0);
        for (int i = 0; i < 3; ++i) {
            /* Every layout reaches the same optimum, to well within an error. */
            CHECK_MSG(fabs(t[k].p[i] - t[0].p[i]) < 1e-3 * t[0].se[i], "%s: p[%d] = %.12g vs %.12g",
                      layouts[k].name, i, t[k].p[i], t[0].p[i]);
            CHECK(fabs(t[k].se[i] - t[0].se[i]) < 1e-6 * t[0].se[i]);
            CHECK(fabs(t[k].p[i] - kTruth[i]) < 1e-3);
        }
    }
    free(x);
    free(y);
    return check_report("fitters_ceres_bridge_layouts");
}
