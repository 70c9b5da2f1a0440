/* INSIDE's volumetric-light ray-march (Gjoel & Svendsen, GDC 2016, seed 002,
 * "Volumetric Lighting" .. "Reducing Bandwidth"), in C: per pixel, N uniform
 * steps along the camera ray inside the light's volume, each step the
 * integrand of core/optics/volumetric_light.h with the visibility looked up in a
 * shadow map (volumetric_light/volumetric_light_shadow_map.h), the start jittered by a noise value.
 *
 * Steps: the ray's part inside the light, [t0, t1] = [0, d] intersected
 * with the spot's outer cone (volumetric_cone_interval; a point light:
 * [0, d]), d the distance to the surface. (The talk clips a box with the
 * light's frustum, Sutherland-Hodgman, and marches from the front faces to
 * the back faces; the exact cone is the tightest such volume.) With
 * delta = (t1 - t0) / N and the offset xi in [0, 1):
 *     L ~ delta sum_{i<N} j(t0 + (i + xi) delta) V(x_i)    (times I)
 * For xi uniform the expectation is the integral exactly (each step is
 * stratified sampling of its own stratum). The talk's transcribed code
 * reads `p = p0 + rand/stepvec` and `sum /= STEPS`: the offset must be
 * rand * stepvec (a fraction of a step; dividing by a vector has no
 * meaning), and the mean of the samples is the integral only after
 * multiplying by |p1 - p0| (the ray's length inside the volume differs
 * from pixel to pixel).
 *
 * The offset xi of pixel (x, y) in frame f, by noise type (the patterns of
 * realtime/dither_patterns.h, not re-defined here):
 *   none   0 (the talk's uniform sampling: the same steps every frame);
 *   white  an independent uniform per pixel and frame (stream f);
 *   bayer, ign, blue: the pattern's value v (stream 0) moved by the golden
 *          ratio each frame, frac(v + f (sqrt 5 - 1) / 2). The talk only says
 *          "animate the noise"; the additive recurrence keeps every frame's
 *          histogram flat and makes each pixel's offsets over frames a
 *          low-discrepancy sequence, so the temporal mean converges.
 * Blue noise is the void-and-cluster texture of luts/blue_noise.h. */
#ifndef GTLAB_VOLUMETRIC_LIGHT_RAYMARCH_H
#define GTLAB_VOLUMETRIC_LIGHT_RAYMARCH_H

#include "core/optics/volumetric_light.h"
#include "luts/blue_noise.h"
#include "volumetric_light/volumetric_light_shadow_map.h"

typedef enum {
    RAYMARCH_NOISE_NONE = 0,
    RAYMARCH_NOISE_WHITE,
    RAYMARCH_NOISE_BAYER,
    RAYMARCH_NOISE_IGN,
    RAYMARCH_NOISE_BLUE,
    RAYMARCH_NOISE_COUNT
} raymarch_noise;

const char *raymarch_noise_name(raymarch_noise n);
/* "none", "white", "bayer", "ign", "blue" -> n; -1 if unknown. */
int raymarch_noise_parse(const char *name, raymarch_noise *n);

/* The start offset xi in [0, 1) above; blue may be NULL but for blue. */
double raymarch_offset(raymarch_noise n, const blue_noise_texture *blue, int frame, int x, int y);

typedef struct {
    const volumetric_light *light;
    const volumetric_medium *medium;
    const shadow_map *shadows; /* a spot's map; NULL: unshadowed (unless cube) */
    const shadow_cube *cube;   /* a point light's cube of maps; NULL: none */
} raymarch_lighting;

/* L / I along o + t w, t in [0, distance], with `steps` steps at offset xi. */
double raymarch_ray(const raymarch_lighting *l, vec3 o, vec3 w, double distance, int steps, double xi);

/* The camera rays of an image: a pinhole at eye, unit directions dir[3 p]
 * and distances to the surface distance[p] (0: no surface, nothing marched). */
typedef struct {
    int width, height;
    vec3 eye;
    const float *dir;
    const float *distance;
} raymarch_view;

/* One frame at full resolution into out[p] (L / I); OpenMP over rows,
 * the same bits for any thread count. */
void raymarch_image(const raymarch_lighting *l, const raymarch_view *view, int steps, raymarch_noise noise,
                    const blue_noise_texture *blue, int frame, int threads, float *out);

#endif
