/* The G-buffer: one primary ray through each pixel centre, the surface it
 * hits, and the DESIGN.md channels a real-time technique would read
 * (depth.Z, N.*, Ng.*, P.*, albedo.*, roughness.Y, mask.A). Every reference
 * integrator estimates its quantity at exactly these surface points, so the
 * reference and the approximation see the same pixels. */
#ifndef GTLAB_RAYTRACER_GBUFFER_H
#define GTLAB_RAYTRACER_GBUFFER_H

#include "core/image.h"
#include "raytracer/embree_scene.h"
#include "scene/camera.h"

typedef enum { NORMAL_SHADING, NORMAL_GEOMETRIC } normal_mode;

typedef struct {
    int width, height;
    surface_hit *hits;     /* per pixel; ns == ng under NORMAL_GEOMETRIC; where the
                              primary ray escapes, t = +infinity, mesh = -1, the rest 0 */
    unsigned char *mask;   /* 1 where the primary ray hit a surface */
    camera_view view;
} gbuffer;

int gbuffer_render(const embree_scene *es, const camera *cam, normal_mode normals, int threads, gbuffer *gb,
                   gt_error *e);
/* Adds the G-buffer channels to img (same size). */
int gbuffer_write_channels(const gbuffer *gb, const scene *s, image *img);
/* The number of pixels whose primary ray hit a surface. */
long gbuffer_covered_pixels(const gbuffer *gb);
void gbuffer_free(gbuffer *gb);

#endif
