/* Piecewise-constant distributions in one and two dimensions: pbrt-v4's
 * PiecewiseConstant1D and PiecewiseConstant2D (Pharr, Jakob and Humphreys,
 * "Physically Based Rendering", 4th ed., sec. A.1 and A.5.2), in C, over
 * bins rather than a continuous domain: sampling returns the bin and the
 * sample's position within it in [0, 1), so the caller maps a bin onto
 * whatever measure it stands for (the environment sampler maps a texel's
 * position uniformly in phi and cos theta).
 *
 * 1-D: weights f_i >= 0 (i < n) give P(i) = f_i / sum f, and
 *   cdf_0 = 0,  cdf_{i+1} = cdf_i + f_i / sum f,   cdf_n = 1 exactly.
 * A point u in [0, 1) falls in the bin i with cdf_i <= u < cdf_{i+1} (never
 * a bin of weight 0), at offset (u - cdf_i) / (cdf_{i+1} - cdf_i).
 * 2-D (rows x columns): a marginal over rows of the row sums, and one
 * conditional per row over its columns; u[0] picks the row and u[1] the
 * column, P(r, c) = P(r) P(c | r) = f_rc / sum f.
 * Cumulative sums are doubles, summed in order: the tables are the same
 * bits on every run. The bin is found from a guide table (Chen 1974's
 * cutpoint method: guide[j] is the bin of j / n, and the search walks up
 * from guide[floor(u n)]), in O(1) expected steps and the same bin a
 * binary search finds: the one bin with cdf_i <= u < cdf_{i+1}. */
#ifndef GTLAB_CORE_SAMPLING_ENVIRONMENT_DISTRIBUTION_H
#define GTLAB_CORE_SAMPLING_ENVIRONMENT_DISTRIBUTION_H

#include "core/error.h"

typedef struct {
    int count;
    double total; /* sum of the weights; 0: nothing can be sampled */
    double *cdf;  /* count + 1 entries */
    int *guide;   /* guide[j]: the bin holding j / count (Chen's cutpoints) */
} distribution_1d;

/* Builds over weights[0 .. count-1] (finite, >= 0; a zero total is
 * allowed). Returns 0, or -1 with e when out of memory. */
int distribution_1d_init(distribution_1d *d, const double *weights, int count, gt_error *e);
void distribution_1d_free(distribution_1d *d);

/* The bin of u in [0, 1) and, if offset is not NULL, the position within it
 * in [0, 1). Only when total > 0. */
int distribution_1d_sample(const distribution_1d *d, double u, double *offset);

/* distribution_1d_sample in two steps, for callers that prefetch between
 * them (the guide entry and the CDF are each a cache miss in a large
 * table): the guide entry of u, where the search starts, and the search
 * itself from that entry's value `lo`. The same bin and offset. */
const int *distribution_1d_guide_of(const distribution_1d *d, double u);
int distribution_1d_sample_from(const distribution_1d *d, double u, int lo, double *offset);

/* P(i) = f_i / total. */
double distribution_1d_probability(const distribution_1d *d, int i);

typedef struct {
    int rows, columns;
    distribution_1d marginal;      /* over rows: the row sums */
    distribution_1d *conditional;  /* rows of them, over columns */
} distribution_2d;

/* Builds over weights[r * columns + c]. */
int distribution_2d_init(distribution_2d *d, const double *weights, int rows, int columns, gt_error *e);
void distribution_2d_free(distribution_2d *d);

/* The bin (row, column) of u in [0, 1)^2 and the offsets within it. */
void distribution_2d_sample(const distribution_2d *d, const double u[2], int *row, int *column, double offset[2]);

/* P(row, column) = f / total. */
double distribution_2d_probability(const distribution_2d *d, int row, int column);

#endif
