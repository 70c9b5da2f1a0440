/* The sampling loop every reference shares: for each G-buffer pixel, draw
 * samples (sequence indices sample_offset, sample_offset + 1, ...) from the
 * pixel's Owen-scrambled Sobol' sequence, ask the integrator for one sample of
 * each quantity, and accumulate them exactly (core/mc_film.h).
 *
 * Stop rule: with target_stderr > 0 a pixel stops at the first power-of-two
 * sample count >= 16 at which the standard error of quantity 0 is at most the
 * target (or at spp). Checking only at powers of two keeps each pixel's sample
 * set a complete (0, m, 2)-net.
 *
 * Determinism: a pixel's samples depend only on (seed, pixel, index), and each
 * pixel is accumulated by one thread in index order, so the output is
 * bit-identical for any thread count. */
#ifndef GTLAB_RAYTRACER_RENDER_LOOP_H
#define GTLAB_RAYTRACER_RENDER_LOOP_H

#include <stdint.h>

#include "core/frame.h"
#include "core/mc_film.h"
#include "core/sobol.h"
#include "raytracer/embree_scene.h"
#include "raytracer/gbuffer.h"

/* What every sample of a pixel shares, prepared once per pixel. */
typedef struct {
    const surface_hit *surface;
    frame shading;   /* orthonormal frame about the shading normal */
    vec3 ray_origin; /* the surface point lifted off the surface (offset_ray_origin) */
    uint32_t seed;   /* the pixel's sequence seed */
} pixel_context;

/* Samples are drawn in batches so an integrator can trace them together (one
 * Embree stream call) and derive its per-pair scramble seeds once. 16 divides
 * every power-of-two checkpoint of the stop rule. */
enum { SAMPLE_BATCH = 16 };

typedef struct integrator {
    const char *label; /* for the progress bar */
    int quantity_count;
    const mc_quantity *quantities;
    const char *normalized_layer; /* a vector layer written normalised, or NULL */
    /* Estimates samples first_index .. first_index + count - 1 (count <=
     * SAMPLE_BATCH) into values[k * quantity_count + q]; returns the number
     * of rays traced. */
    int (*sample_batch)(const struct integrator *self, const pixel_context *px, uint32_t first_index, int count,
                        float *values);
    const embree_scene *scene;
    const void *settings; /* the integrator's own parameters */
} integrator;

typedef struct {
    int spp;                /* samples per pixel (maximum with target_stderr) */
    uint32_t sample_offset; /* first sequence index */
    uint32_t seed;
    double target_stderr;   /* 0: off */
    int threads;
} sampling_settings;

typedef struct {
    uint64_t rays, samples;
    double seconds;
} render_stats;

int render_estimates(const gbuffer *gb, const integrator *it, const sampling_settings *ss, mc_film *film,
                     render_stats *stats, gt_error *e);

#endif
