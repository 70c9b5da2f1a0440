/* The sampling loop every reference shares: for each G-buffer pixel, draw
 * samples (sequence indices sample_offset, sample_offset + 1, ...) from the
 * pixel's Owen-scrambled Sobol' sequence, ask the integrator for one sample of
 * each quantity, and accumulate them exactly (core/statistics/mc_film.h).
 *
 * Stop rule: with target_stderr > 0 (or target_rel_stderr > 0) a pixel stops
 * at the first power-of-two sample count >= 64 at which the standard error of
 * quantity 0 is at most the target (or the relative target times the mean's
 * magnitude), or at spp. Checking only at powers of two keeps each pixel's
 * sample set a complete (0, m, 2)-net. The first check waits for 64 samples
 * (docs/decisions.md, "Stop rule"): fewer estimate the variance too poorly
 * where rare samples carry the integral (a penumbra seen through 16 samples
 * that all missed the light reports a standard error of 0). The standard
 * error is each pixel's own (core/statistics/moment_sums.h), so the rule does not
 * depend on how bright other pixels are.
 *
 * Determinism: a pixel's samples depend only on (seed, pixel, index), and each
 * pixel is accumulated by one thread in index order, so the output is
 * bit-identical for any thread count. */
#ifndef GTLAB_RAYTRACER_RENDER_LOOP_H
#define GTLAB_RAYTRACER_RENDER_LOOP_H

#include <signal.h>
#include <stdint.h>

#include "core/frame.h"
#include "core/statistics/mc_film.h"
#include "core/sampling/sobol.h"
#include "raytracer/embree_scene.h"
#include "raytracer/gbuffer.h"

/* What every sample of a pixel shares, prepared once per pixel. */
typedef struct {
    const surface_hit *surface;
    frame shading;   /* orthonormal frame about the shading normal */
    vec3 ray_origin; /* the surface point lifted off the surface (offset_ray_origin) */
    uint32_t half_seed[2]; /* seeds of the even- and odd-sample sequences */
    int pixel;             /* row-major G-buffer index (pixel_context_at), or -1 */
} pixel_context;

/* The context of a pixel whose sequence seed is pixel_seed(seed, x, y). */
pixel_context pixel_context_prepare(const surface_hit *surface, uint32_t seed);
/* The context of G-buffer pixel `pixel` (row-major) under the render seed. */
pixel_context pixel_context_at(const gbuffer *gb, int pixel, uint32_t seed);

/* The two halves of a pixel's samples come from two independently scrambled
 * Sobol' sequences: sample i is point i / 2 of sequence i mod 2. Within one
 * sequence consecutive points are anti-correlated (each fills the strata the
 * others left), so halves taken from a single sequence would not be
 * independent estimates, and the noise floor (DSSIM between the halves)
 * would be wrong. Each half stays a well-stratified sequence of its own. */
typedef struct {
    sobol_pair_seeds half[2];
} sample_pair_seeds;

static inline sample_pair_seeds sample_pair_seeds_for(const pixel_context *px, uint32_t pair)
{
    sample_pair_seeds s = {{sobol_owen_pair_seeds(px->half_seed[0], pair), sobol_owen_pair_seeds(px->half_seed[1], pair)}};
    return s;
}

/* The 2-D point of sample `index` in a dimension pair, in [0,1)^2. */
static inline void sample_pair_point(const sample_pair_seeds *s, uint32_t index, float u[2])
{
    sobol_owen_point(&s->half[index & 1u], index >> 1, u);
}

/* The points of samples first .. first + count - 1 (count <= SAMPLE_BATCH),
 * as two coordinate arrays; the same values as sample_pair_point. */
void sample_pair_points(const sample_pair_seeds *s, uint32_t first, int count, float *u0, float *u1);

/* Samples are drawn in batches so an integrator can trace them together (one
 * Embree stream call) and derive its per-pair scramble seeds once. With a
 * target standard error, batches are cut to end on the stop rule's
 * checkpoints (powers of two from 64). */
enum { SAMPLE_BATCH = 64 };

typedef struct integrator {
    const char *label; /* for the progress bar */
    int quantity_count;
    const mc_quantity *quantities;
    const char *normalized_layer; /* a vector layer written normalised, or NULL */
    /* Estimates samples first_index .. first_index + count - 1 (count <=
     * SAMPLE_BATCH) into values[q * SAMPLE_BATCH + k] (quantity-major);
     * returns the number of rays traced. */
    int (*sample_batch)(const struct integrator *self, const pixel_context *px, uint32_t first_index, int count,
                        float *values);
    const embree_scene *scene;
    const void *settings; /* the integrator's own parameters */
    /* 1: the background pixels too (primary ray escapes: px->surface->t is
     * +infinity, px->pixel names the pixel); 0: only the covered pixels */
    int covers_background;
} integrator;

typedef struct {
    int spp;                /* samples per pixel (maximum with target_stderr) */
    uint32_t sample_offset; /* first sequence index */
    uint32_t seed;
    double target_stderr;   /* 0: off */
    int threads;
    double target_rel_stderr; /* relative to |mean|; 0: off (either target met stops the pixel) */
} sampling_settings;

typedef struct {
    uint64_t rays, samples;
    double seconds;
} render_stats;

/* Initialises the film and renders every masked pixel's samples into it
 * (under MPI this process's share, the film the job's on rank 0:
 * raytracer/distributed_render.h). */
int render_estimates(const gbuffer *gb, const integrator *it, const sampling_settings *ss, mc_film *film,
                     render_stats *stats, gt_error *e);

/* For a render in blocks (raytracer/render_checkpoint.h): an empty film of
 * the integrator's quantities; then the samples of ss (a fixed spp; not
 * shared among MPI ranks: the caller gives each rank its share) added at
 * every masked pixel, stats added to. When *stop becomes non-zero (stop may be NULL) the rows left are skipped and 1 is
 * returned: the film then holds part of the block. */
int render_estimates_film(const gbuffer *gb, const integrator *it, mc_film *film, gt_error *e);
int render_estimates_add(const gbuffer *gb, const integrator *it, const sampling_settings *ss, mc_film *film,
                         render_stats *stats, const volatile sig_atomic_t *stop);
/* The same over the rows first_row, first_row + row_step, ... below
 * end_row only, every pixel to its stopping target when ss has one (an
 * adaptive render in blocks of rows; under mpirun a rank's rows). */
int render_estimates_add_rows(const gbuffer *gb, const integrator *it, const sampling_settings *ss, int first_row,
                              int row_step, int end_row, mc_film *film, render_stats *stats,
                              const volatile sig_atomic_t *stop);

#endif
