/* The G-buffer as a real-time technique sees it: per-pixel depth along the
 * camera axis (depth.Z), world-space shading normal (N.*), coverage (mask.A)
 * and the pinhole camera that produced them, with the view-space
 * reconstruction every screen-space AO technique shares.
 *
 * View space: right-handed, x to the right, y up, the camera at the origin
 * looking down -z (the usual OpenGL convention). Pixel (i, j) (column i from
 * the left, row j from the top) has its centre at (i + 0.5, j + 0.5); its
 * view-space position at depth d is d * (sx, sy, -1) with
 *   sx = (2 (i + 0.5) / W - 1) tan(yfov/2) aspect,  sy = (1 - 2 (j + 0.5) / H) tan(yfov/2),
 * the same primary ray as scene/camera.c, so the reconstruction lands on the
 * surface point the reference integrators saw. No scene or Embree code here:
 * the caller fills the camera basis. */
#ifndef GTLAB_REALTIME_SCREEN_SPACE_H
#define GTLAB_REALTIME_SCREEN_SPACE_H

#include "core/error.h"
#include "core/image.h"
#include "core/vec3.h"

typedef struct {
    vec3 forward, right, up; /* world-space camera basis, right = forward x up */
    float tan_half_yfov;     /* tan(yfov / 2) */
    float aspect;            /* width / height */
} ss_camera;

typedef struct {
    int width, height;
    const float *depth;     /* depth.Z: distance along the camera axis */
    const float *normal[3]; /* N.X, N.Y, N.Z: world-space unit normals */
    const float *mask;      /* mask.A: 1 where a surface was hit */
    ss_camera camera;
    /* Optional: every pixel's ss_depth_bounds (ss_depth_bounds_planes); NULL:
     * ss_sample_position works them out per sample, to the same bits. */
    const float *depth_lo, *depth_hi;
} ss_gbuffer;

/* Points g at the channels of img (depth.Z, N.X, N.Y, N.Z, mask.A) with the
 * given camera. Returns 0, or -1 with e = "<what>: missing channel <name>
 * (...)" or a camera whose size differs from the image's. */
int ss_gbuffer_from_image(const image *img, const char *what, ss_camera camera, ss_gbuffer *g, gt_error *e);

/* min/max without libm's NaN handling, which GCC does not inline (operands
 * here are never NaN): the horizon loops call them per sample. */
static inline float ss_minf(float a, float b) { return a < b ? a : b; }
static inline float ss_maxf(float a, float b) { return a > b ? a : b; }
static inline float ss_clampf(float x, float lo, float hi) { return ss_minf(ss_maxf(x, lo), hi); }

static inline int ss_covered(const ss_gbuffer *g, int x, int y)
{
    return x >= 0 && y >= 0 && x < g->width && y < g->height && g->mask[(long)y * g->width + x] != 0.0f;
}

/* View-space position of the surface seen through the centre of pixel (x, y). */
vec3 ss_view_position(const ss_gbuffer *g, int x, int y);
/* View-space position of the depth buffer's surface seen through screen
 * point (fx, fy) (pixels, not snapped to a centre): the eye ray through the
 * point meets the tangent plane of the pixel it falls in (that pixel's
 * position and normal), clamped to the depths of the pixel and its
 * neighbours (core/optics/heightfield_model.h, shared with the height-field
 * reference). Each pixel is a planar piece of the height field, so a sample
 * stays exactly in its slice and a plane is reproduced exactly; snapping
 * samples to pixel centres moves them off the slice and raises a plane's
 * horizons above its tangent. */
vec3 ss_sample_position(const ss_gbuffer *g, float fx, float fy);
/* The depths a sample in pixel (x, y) is clamped to: the lowest and highest
 * of the pixel's and its 8 neighbours' depths, a neighbour off the surface
 * replaced by its opposite mirrored through the pixel (2 d - d_opposite),
 * skipped if that is off too (core/optics/heightfield_model.h). */
void ss_depth_bounds(const ss_gbuffer *g, int x, int y, float *lo, float *hi);
/* Fills lo and hi (width x height each) with every pixel's ss_depth_bounds,
 * for g's depth_lo and depth_hi: the horizon searches read them per sample. */
void ss_depth_bounds_planes(const ss_gbuffer *g, float *lo, float *hi);
/* The pixel's normal rotated into view space. */
vec3 ss_view_normal(const ss_gbuffer *g, int x, int y);
/* A view-space direction rotated back into world space. */
vec3 ss_world_direction(const ss_gbuffer *g, vec3 v);
/* Pixels spanned by one world unit at depth d, at the image centre (the
 * screen-space radius of a world-space radius). */
float ss_pixels_per_unit(const ss_gbuffer *g, float depth);
/* The screen-space radius at pixel (x, y) of a world-space radius, clamped to
 * max_px (the talk's guard against cache thrashing on near objects). */
float ss_radius_px(const ss_gbuffer *g, int x, int y, float radius, float max_px);

#endif
