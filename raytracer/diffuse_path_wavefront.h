/* The paths of a batch of samples as a wavefront, shared by the two diffuse
 * path tracers (techniques/multibounce/multibounce_integrator.c under the white dome,
 * techniques/environment/environment_diffuse_integrator.c under an environment): every
 * live path takes one bounce before any takes the next, so each depth's
 * rays go to Embree as one stream and each dimension pair's scramble seeds
 * are derived once per batch.
 *
 * What the two share is the Lambertian random walk itself: a path's
 * throughput per albedo weight w (one grey albedo each, or the three colour
 * channels of the scene's base colour) is the product over its vertices
 * after the first of rho_w at a fixed depth, or, unlimited, of rho_w / q
 * with Russian roulette survival probability q = max_w rho_w. What they
 * add at an escape (1, or the environment's radiance) and how they choose
 * directions (cosine, or a mixture with the environment's distribution)
 * stays theirs. */
#ifndef GTLAB_RAYTRACER_DIFFUSE_PATH_WAVEFRONT_H
#define GTLAB_RAYTRACER_DIFFUSE_PATH_WAVEFRONT_H

#include "raytracer/diffuse_path_albedos.h"
#include "raytracer/render_loop.h"

/* A live path at its current vertex. Its throughput lives apart, per
 * sample, so compacting the live paths moves 64 bytes each. */
typedef struct {
    vec3 origin, ng;
    frame shading;
    int sample; /* index within the batch */
} path_vertex;

typedef struct {
    const embree_scene *scene;
    const pixel_context *px;
    const multibounce_settings *albedo;
    normal_mode normals;
    uint32_t first_index;
    int count, weights, unlimited, max_bounces, live;
    unsigned surface_parts; /* what a vertex reads of its surface_hit */
    path_vertex paths[SAMPLE_BATCH];
    float throughput[MULTIBOUNCE_MAX_ALBEDOS][SAMPLE_BATCH]; /* [w][sample] */
} path_wavefront;

/* count paths at the pixel's primary hit, throughput 1; weights: 3 with
 * the scene's albedo, else one per grey albedo of `albedo` (kept as a
 * pointer). */
void path_wavefront_start(path_wavefront *wf, const embree_scene *scene, const pixel_context *px, uint32_t first_index,
                          int count, const multibounce_settings *albedo, normal_mode normals);

/* The 2-D points of the live paths in dimension pair `pair`, in path order:
 * all of the batch's at once (the vectorised loop) while most paths live,
 * one by one once few do; the same values either way. */
void path_wavefront_live_points(const path_wavefront *wf, uint32_t pair, float *u0, float *u1);

/* The Russian roulette numbers of the live paths leaving depth `depth`
 * (unlimited bounces only; dimension pair MULTIBOUNCE_ROULETTE_PAIRS +
 * depth + 1). */
void path_wavefront_roulette(const path_wavefront *wf, int depth, float *u);

/* Live path p's ray hit a surface (at least wf->surface_parts of it,
 * embree_surface_at): its albedos multiply its throughput (after roulette
 * with u when unlimited) and p moves to the hit. Returns 0 if the path ends
 * there. */
int path_wavefront_continue(path_wavefront *wf, const surface_hit *hit, float u, path_vertex *p);

#endif
