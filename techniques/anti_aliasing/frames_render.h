/* Frames along a camera path for temporal anti-aliasing (issue 19): one
 * shaded sample per pixel (raytracer/shaded_frame.h) at the pixel centre
 * plus a sub-pixel jitter, with what a game's G-buffer gives its TAA:
 *   depth     the camera depth (camera_depth) of the surface the sample
 *             sees, 0 where it sees the sky;
 *   motion    the exact reprojection of that surface point: its image
 *             position in the previous frame's camera (unjittered) minus
 *             the sample's own position, in pixels (so the history of
 *             pixel c is read at c + motion); for the sky, the direction's
 *             reprojection; 0 without a previous camera;
 *   disoccluded  1 where the point was not seen by the previous frame:
 *             behind or outside its image, or hidden from its camera (a
 *             ray from the previous camera stops before 1 - 1e-4 of the
 *             distance to the point); 0 for the sky.
 * Everything is computed from rays, so it is exact to float rounding. */
#ifndef GTLAB_ANTI_ALIASING_FRAMES_RENDER_H
#define GTLAB_ANTI_ALIASING_FRAMES_RENDER_H

#include "raytracer/shaded_frame.h"

typedef struct {
    float *rgb;                 /* 3 floats a pixel, linear radiance */
    float *depth;               /* 1 a pixel */
    float *motion;              /* 2 a pixel */
    unsigned char *disoccluded; /* 1 a pixel */
} frame_buffers;

/* Allocates (all or nothing; 0 or -1) and frees the buffers of W x H pixels. */
int frame_buffers_alloc(frame_buffers *f, int width, int height);
void frame_buffers_free(frame_buffers *f);

/* Renders cam's frame with the sample of pixel (i, j) at (i + 0.5 +
 * jitter[0], j + 0.5 + jitter[1]); previous may be NULL (first frame).
 * Deterministic for any thread count. */
void frames_render(const embree_scene *es, const camera *cam, const camera *previous, const frame_lighting *light,
                   const float jitter[2], int threads, frame_buffers *out);

#endif
