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

#include "core/mc_film.h"
#include "core/sobol.h"
#include "raytracer/embree_scene.h"
#include "raytracer/gbuffer.h"

/* Where one sample is drawn: the pixel's surface and its sample stream. */
typedef struct {
    const surface_hit *surface;
    uint32_t seed;  /* the pixel's seed */
    uint32_t index; /* the sample's index in the pixel's sequence */
} sample_point;

/* The next 2-D point of the sample's stream: pair 0, 1, 2, ... in order. */
static inline void sample_point_2d(const sample_point *sp, uint32_t pair, float u[2])
{
    sobol_owen_2d(sp->seed, sp->index, pair, u);
}

typedef struct integrator {
    const char *label; /* for the progress bar */
    int quantity_count;
    const mc_quantity *quantities;
    const char *normalized_layer; /* a vector layer written normalised, or NULL */
    /* Fills values[quantity_count] with one sample's estimates; returns the
     * number of rays it traced. */
    int (*sample)(const struct integrator *self, const sample_point *sp, float *values);
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
