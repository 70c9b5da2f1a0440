/* The bloom downsample of Jimenez 2014 ("Next Generation Post Processing in
 * Call of Duty: Advanced Warfare", SIGGRAPH course, slides 160-165) and the
 * 9-tap refit INSIDE ships (Gjoel, GDC 2016, seed 002, "Sample Fitting").
 *
 * Coordinates are source texels: texel t covers [t, t + 1[ with its centre at
 * t + 1/2; an output pixel i of a destination of size D over a source of
 * size S sits at c = (i + 1/2) S / D, a texel corner when S = 2D. A tap is a
 * bilinear fetch at c + (x, y) with weight w; a fetch at p reads texel t with
 * the weight tent(p_x - t_x - 1/2) tent(p_y - t_y - 1/2), tent(d) =
 * max(0, 1 - |d|) (clamp-to-edge at the borders, as a sampler does).
 *
 * Jimenez's 13 taps: five overlapping 2x2-tap boxes of spacing 2 texels, the
 * centre box (taps at (+-1, +-1)) weighted 1/2 and the four corner boxes
 * (taps at 0, +-2) 1/8 each, a tap's weight the sum over the boxes holding
 * it / 4: corners (+-2, +-2) 1/32, edges (0, +-2), (+-2, 0) 2/32, centre 4/32,
 * inner (+-1, +-1) 4/32. At half resolution every tap lands on a texel
 * corner and spreads its weight over 4 texels: 36 texels (6 x 6) with the
 * weights /128 of the talk's table, some read by up to 4 taps.
 *
 * A 9-tap kernel reads each of the 6 x 6 texels once: tap k of the 3 x 3
 * layout stays inside its 2 x 2 block (block centres at -2, 0, 2), i.e.
 * |x - X_k| <= 1/2 and |y - Y_k| <= 1/2. Within a block its texel weights are
 * w (1 - a)(1 - b), w a (1 - b), ...: rank one, so a target block of rank
 * two (the 13-tap corner block [[1, 1], [1, 5]] / 128) cannot be met, while
 * a separable target (a sampled Gaussian) is met exactly. */
#ifndef GTLAB_BLOOM_BLOOM_DOWNSAMPLE_H
#define GTLAB_BLOOM_BLOOM_DOWNSAMPLE_H

enum {
    BLOOM_JIMENEZ_TAPS = 13,
    BLOOM_FIT_TAPS = 9,
    BLOOM_FOOTPRINT = 6, /* texels per axis the kernels cover at half resolution */
    BLOOM_GRID = 8       /* texels per axis of a weight grid: the footprint and a ring, for off-half phases */
};

typedef struct {
    double x, y, w;
} bloom_tap;

/* Jimenez's 13 taps (offsets from c in source texels, weights summing to 1). */
void bloom_jimenez13(bloom_tap taps[BLOOM_JIMENEZ_TAPS]);

/* The centre of block k (row-major 3 x 3: -2, 0, 2) of the 9-tap layout. */
void bloom_block_centre(int k, double *x, double *y);

/* The texel weights of a kernel whose centre c sits `phase` texels past a
 * texel corner (phase 0, 0 at half resolution): grid[j][i] is the weight of
 * the texel whose centre is at c - phase + (i - 7/2, j - 7/2), i, j in 0..7.
 * No clamping (an interior pixel). */
void bloom_texel_weights(const bloom_tap *taps, int count, double phase_x, double phase_y,
                         double grid[BLOOM_GRID][BLOOM_GRID]);

/* The real part of the kernel's frequency response at (wx, wy) radians per
 * source texel: sum of grid weights times cos(w . (texel centre - c)); the
 * kernels here are symmetric, so it is the whole response. */
double bloom_frequency_response(const double grid[BLOOM_GRID][BLOOM_GRID], double wx, double wy);

/* A bilinear fetch at (x, y) in source texels of a w x h plane, clamp to edge. */
double bloom_fetch(const float *src, int w, int h, double x, double y);

/* dst (dw x dh) = the kernel applied at every output pixel of src (sw x sh). */
void bloom_downsample(const float *src, int sw, int sh, float *dst, int dw, int dh, const bloom_tap *taps, int count);

#endif
