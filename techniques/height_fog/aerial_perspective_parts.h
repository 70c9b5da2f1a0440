/* Internals of the combination images (height_fog/aerial_perspective_study.h): the
 * camera rays of one image and the planes the reference and the models
 * fill. */
#ifndef GTLAB_HEIGHT_FOG_AERIAL_PERSPECTIVE_PARTS_H
#define GTLAB_HEIGHT_FOG_AERIAL_PERSPECTIVE_PARTS_H

#include "height_fog/aerial_perspective_study.h"

/* The rays of one image: per pixel a unit direction, whether it is
 * rendered (inside), whether it ends on the terrain (terrain), the
 * segment's length and the surface's altitude there. */
typedef struct {
    int width, height;
    double camera_y;
    float *dir;                 /* 3 per pixel */
    float *inside, *terrain;    /* 0 or 1 */
    float *length, *surface_y;  /* terrain pixels */
} aerial_rays;

/* RGB planes of the reference and of each model. */
typedef struct {
    float *reference[3], *model[AERIAL_MODELS][3];
    double reference_error; /* the largest quadrature estimate */
} aerial_planes;

/* The lighting of one case: the weather's blend, its precomputation (the
 * reference), the LUTs (the model) and the sun. */
typedef struct {
    const atmosphere_solution *solution;
    const atmosphere_luts *luts, *fine; /* the request's sizes and its finer ones */
    double t;
    vec3 sun;
} aerial_light;

/* Allocates rays for w x h pixels (zeroed); -1 out of memory (nothing to free). */
int aerial_rays_alloc(aerial_rays *rays, int width, int height);
void aerial_rays_free(aerial_rays *rays);
/* The fisheye's rays (the header's mapping), camera at y = 0. */
void aerial_fisheye_rays(aerial_rays *rays);

int aerial_planes_alloc(aerial_planes *p, size_t n);
void aerial_planes_free(aerial_planes *p);

/* Renders every inside pixel: the reference and the models (parallel; bits
 * independent of `threads`); aerial_render_models the models alone. */
void aerial_render_models(const aerial_light *light, const aerial_rays *rays, int threads, aerial_planes *out);
void aerial_render(const aerial_light *light, const aerial_rays *rays, const aerial_perspective_request *rq,
                   int threads, aerial_planes *out);

/* Scores one rendered image into the case (the view: is_view, else the
 * fisheye); 0, or -1 with e. */
int aerial_score(const aerial_rays *rays, const aerial_planes *planes, int is_view, aerial_case *c, gt_error *e);
/* The fisheye's *_fine scores: planes' model 0 from the finer LUTs. */
int aerial_score_fine(const aerial_rays *rays, const aerial_planes *planes, aerial_case *c, gt_error *e);
/* Writes <kind>_<weather>_sunNN.exr, .png and _error.png into dir. */
int aerial_write(const char *dir, const char *kind, const aerial_rays *rays, const aerial_planes *planes,
                 const aerial_case *c, gt_error *e);

#endif
