/* The two independent half-references of a gtlab reference render: the
 * means of its even-index and of its odd-index samples (core/statistics/mc_film.h
 * keeps both sums), for every Monte Carlo quantity of the file. Each half
 * has the noise of a render of half the samples, and the two halves are
 * independent: scoring one against the other gives the reference's noise
 * floor (DESIGN.md), and scoring an approximation fed by one half against
 * the other keeps the two sides' noise uncorrelated. */
#ifndef GTLAB_METRICS_REFERENCE_HALVES_H
#define GTLAB_METRICS_REFERENCE_HALVES_H

#include "core/error.h"
#include "core/image.h"

/* halves[0] (even samples) and halves[1] (odd samples), each an image of
 * img's size with one channel per quantity, named as the quantity; pixels
 * outside the surfaces (mask.A == 0 in img, if it has mask.A) hold 0, as in
 * the written means.
 * `what` names img in errors (not a gtlab reference, out of memory).
 * Returns 0 with both halves to be freed, or -1 with e and nothing to free. */
int reference_halves_split(const image *img, const char *what, image halves[2], gt_error *e);

#endif
