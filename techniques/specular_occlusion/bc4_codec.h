/* BC4 block compression (one channel; Direct3D's BC4_UNORM, the alpha block
 * of DXT5): each 4x4 block is two 8-bit endpoints e0, e1 and a 3-bit index
 * per texel choosing one of eight values e0 + (e1 - e0) i / 7 (e0 > e1), or
 * of six plus 0 and 1 (e0 <= e1). The encoder is libsquish's (Debian's
 * libsquish-dev 1.15, `kBc4`), behind this plain C header. Libsquish 1.15's
 * own BC4 decoder decodes colour instead, so blocks are decoded through its
 * public DXT5 decoder, whose alpha block is the BC4 block bit for bit.
 *
 * Error bound (tests/luts): against the 8-bit value q of each texel (the
 * float rounded to the nearest 1/255), a block whose q span [lo, hi] is
 * coded by its own extremes errs by at most (hi - lo) / 14 (the nearest of
 * eight evenly spaced values); libsquish tries that code and keeps the
 * better one. Its decoder then truncates each interpolated value to 8 bits
 * (a GPU keeps the fraction): up to 1 more, so |decoded - q| <=
 * (hi - lo) / 14 + 1 in 8-bit units, plus 1/2 of the 8-bit rounding of the
 * float itself. */
#ifndef GTLAB_SPECULAR_OCCLUSION_BC4_CODEC_H
#define GTLAB_SPECULAR_OCCLUSION_BC4_CODEC_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { BC4_BLOCK_BYTES = 8 };

/* Bytes of the blocks of a width x height image (partial blocks at the
 * edges count whole). */
size_t bc4_storage_bytes(int width, int height);
/* values[y * width + x] in [0, 1] (clamped) -> blocks, row-major by block. */
void bc4_encode(const float *values, int width, int height, unsigned char *blocks);
/* blocks -> decoded[y * width + x] in [0, 1] (8-bit values / 255). */
void bc4_decode(const unsigned char *blocks, int width, int height, float *decoded);

#ifdef __cplusplus
}
#endif

#endif
