/* Blue-noise dither textures by void-and-cluster (Ulichney 1993, "The
 * void-and-cluster method for dither array generation", Proc. SPIE 1913),
 * the kind INSIDE bakes into a 256^2 RGBA8 texture of four seeds (Gjoel,
 * GDC 2016, seed 002).
 *
 * On an n x n torus, with the energy of a binary pattern b at p
 *     E(p) = sum over q with b(q) = 1 of exp(-|p - q|^2 / (2 sigma^2)),
 * |p - q| the toroidal distance, sigma = 1.5 (Ulichney's choice):
 *   0. the initial pattern: m = n^2 / 10 ones at seeded random pixels, then
 *      move the tightest cluster (the one of highest E) to the largest void
 *      (the zero of lowest E) until the one removed is the void filled;
 *   1. ranks m-1 .. 0: from the initial pattern, remove the tightest
 *      cluster, give it the next lower rank;
 *   2. ranks m .. n^2-1: from the initial pattern, fill the largest void,
 *      give it the next rank. (Ulichney's phase III, past half, finds the
 *      tightest cluster of zeros: with a fixed filter E_zeros = sum of the
 *      filter - E, so it is the same zero of lowest E and the phases merge.)
 * The texel value is (rank + 1/2) / n^2: every value once, a flat histogram
 * on ]0, 1[. Ties break to the lowest index; energies are updated in a fixed
 * order, so the texture is a function of (n, seed) alone. Channel c of a
 * multi-channel texture is the texture of seed blue_noise_channel_seed(seed, c).
 *
 * Cost: each of the n^2 ranks scans n^2 energies: 256^2 takes about a
 * few seconds per channel, 64^2 milliseconds. */
#ifndef GTLAB_LUTS_BLUE_NOISE_H
#define GTLAB_LUTS_BLUE_NOISE_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"

#define BLUE_NOISE_SIGMA 1.5
#define BLUE_NOISE_MAX_CHANNELS 4

typedef struct {
    int size;            /* n: the texture is n x n, n in [8, 1024] */
    int channel_count;   /* 1 .. 4 */
    float *values;       /* channel_count planes of n*n values in ]0, 1[ */
} blue_noise_texture;

/* A counter-based uniform on [0, 1[ from (seed, index): SplitMix64's
 * finaliser (Steele, Lea and Flood 2014), the top 53 bits. gtlab's white
 * noise for dithering too. */
double blue_noise_uniform(uint64_t seed, uint64_t index);

uint64_t blue_noise_channel_seed(uint64_t seed, int channel);

/* The ranks 0 .. n^2-1 of one void-and-cluster array into rank[n*n]. Returns 0 or -1 with e. */
int blue_noise_ranks(int size, uint64_t seed, uint32_t *rank, gt_error *e);

/* A texture of channel_count channels. Returns 0 or -1 with e (bad size or
 * count, out of memory); free with blue_noise_free. */
int blue_noise_build(int size, int channel_count, uint64_t seed, blue_noise_texture *out, gt_error *e);
void blue_noise_free(blue_noise_texture *t);

/* Writes <stem>.exr (float channels R, G, B, A: the schema's names) and
 * <stem>.png (16-bit, or 8-bit for one channel, as INSIDE's RGBA8). */
int blue_noise_write(const blue_noise_texture *t, const char *stem, gt_error *e);

/* Builds a texture, writes it as <dir>/blue_noise_<size>.{exr,png} and
 * frees it; the stem written goes to stem (size bytes). Returns 0 or -1 with e. */
int blue_noise_make(const char *dir, int size, int channel_count, uint64_t seed, char *stem, size_t stem_size,
                    gt_error *e);

#endif
