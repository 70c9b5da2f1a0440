/* The bloom study's kernels as texel weights at any phase (bloom_study.h):
 * Jimenez's 13 taps; the Gaussian of matching variance sampled at the texel
 * centres within 3 texels of the pixel centre per axis (the 6 x 6 footprint
 * at phase 0: the fit's target) or at all 8 x 8 of the grid (the ideal
 * Gaussian, truncated where it is below 3 % of its peak: the reference off
 * half resolution and in the pyramids, since the 6-texel window jumps with
 * the phase), each normalised. */
#ifndef GTLAB_BLOOM_BLOOM_KERNELS_H
#define GTLAB_BLOOM_BLOOM_KERNELS_H

#include "bloom/bloom_downsample.h"
#include "core/error.h"

enum { BLOOM_TARGET_JIMENEZ = 0, BLOOM_TARGET_GAUSSIAN_6, BLOOM_TARGET_GAUSSIAN };

/* sigma such that the normalised weights at 1/2, 3/2, 5/2 have variance `variance` (bisection). */
double bloom_gaussian_sigma(double variance);

/* The target's grid of weights at a phase (bloom_texel_weights' layout). */
void bloom_target_grid(int target, double sigma, double phase_x, double phase_y, double grid[BLOOM_GRID][BLOOM_GRID]);

/* A downsample by texel weights: the target's grid at each output pixel's phase. */
void bloom_target_downsample(int target, double sigma, const float *src, int sw, int sh, float *dst, int dw, int dh);

#endif
