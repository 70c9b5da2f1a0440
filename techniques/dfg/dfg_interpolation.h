/* The DFG table's interpolation study: the bilinear lookup's error against
 * the exact quadrature as a function of the table's size (the table, its
 * quadrature and its lookup: luts/dfg_lut.h). */
#ifndef GTLAB_DFG_INTERPOLATION_H
#define GTLAB_DFG_INTERPOLATION_H

#include "luts/dfg_lut.h"

/* Interpolation error of the bilinear lookup against dfg_integrate at
 * `points` pseudo-random (n.v, r), uniform in [0, 1]^2 (splitmix64 from
 * `seed`; the same points for every size), per channel: over the whole
 * square (what a shader sees, including the clamp-to-edge borders, where the
 * error is O(1/N)) and over the points between the first and last texel
 * centres (bilinear interpolation proper, O(1/N^2) where smooth). */
typedef struct {
    int size;
    double max_error[DFG_CHANNELS], rms_error[DFG_CHANNELS];
    double interior_max_error[DFG_CHANNELS], interior_rms_error[DFG_CHANNELS];
    int interior_points;
    double build_seconds; /* wall time of the table's build */
} dfg_interpolation_result;

/* For each of the `count` sizes (>= 2 each), builds the table and measures
 * it into results[k]. Returns 0, or -1 when out of memory or a size < 2. */
int dfg_interpolation_study(const int *sizes, int count, int points, unsigned seed, int threads,
                            dfg_interpolation_result *results);

#endif
