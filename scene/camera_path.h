/* Camera paths for temporal anti-aliasing (issue 19): frame k's camera is
 * the start camera moved by k steps of a constant translation and turned by
 * k steps of a constant yaw (about +Y through the camera's position, positive
 * counter-clockwise seen from above), so every frame's camera is exact, not
 * integrated. Also the projection of a world point into a camera's image,
 * the inverse of camera_ray, from which motion vectors are computed. */
#ifndef GTLAB_SCENE_CAMERA_PATH_H
#define GTLAB_SCENE_CAMERA_PATH_H

#include "scene/camera.h"

typedef struct {
    camera start;
    vec3 step;        /* translation per frame (world units) */
    float yaw_step;   /* rotation per frame, radians */
} camera_path;

/* A static path (no motion) from cam. */
camera_path camera_path_static(const camera *cam);
/* Frame k's camera (k >= 0; k = 0 is the start). */
camera camera_path_at(const camera_path *path, int k);

/* Image position (x, y) in pixels (centres at +0.5) of world point p, as
 * camera_ray's inverse: camera_ray(view, x, y) points at p. Returns p's depth
 * along the view axis (<= 0: behind the camera, xy undefined). */
float camera_project(const camera_view *view, vec3 p, float xy[2]);
/* The same for a direction d (a point at infinity, e.g. the sky). */
float camera_project_direction(const camera_view *view, vec3 d, float xy[2]);

#endif
