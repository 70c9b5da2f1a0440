/* Pinhole cameras: the camera JSON contract of DESIGN.md, the glTF camera,
 * and the automatic 3/4 framing. Right-handed, +Y up. Pixel (i, j) — column i
 * from the left, row j from the top — has its centre at (i + 0.5, j + 0.5). */
#ifndef GTLAB_SCENE_CAMERA_H
#define GTLAB_SCENE_CAMERA_H

#include <stddef.h>

#include "core/error.h"
#include "core/vec3.h"

typedef struct {
    vec3 position, target, up;
    float yfov; /* vertical field of view, radians */
    int width, height;
} camera;

/* The orthonormal view basis and image-plane scale derived from a camera. */
typedef struct {
    vec3 origin;
    vec3 forward, right, up; /* right-handed: right = forward x up */
    float tan_half_yfov, aspect;
    int width, height;
} camera_view;

/* Checks a camera (finite values, position != target, up not parallel to the
 * view direction, 0 < yfov < 180 deg, positive size). */
int camera_validate(const camera *cam, const char *what, gt_error *e);
camera_view camera_view_from(const camera *cam);

/* Primary ray through image position (x, y) in pixels (x = i + 0.5 is the
 * centre of column i). Direction is unit length. */
void camera_ray(const camera_view *view, float x, float y, vec3 *origin, vec3 *direction);
/* Distance along the camera axis (the depth.Z of DESIGN.md) of point p. */
float camera_depth(const camera_view *view, vec3 p);

/* Camera JSON: {"position":[..],"target":[..],"up":[..],"yfov_deg":..,"width":..,"height":..}.
 * "up" defaults to [0,1,0]. Errors name the file and the bad key. */
int camera_read_json(const char *path, camera *cam, gt_error *e);
int camera_parse_json(const char *text, const char *what, camera *cam, gt_error *e);
/* The same for text[0, length), which need not end in a NUL (a NUL inside
 * is an error). Every camera JSON passes the JSON gate (core/files/json_check.h)
 * before cJSON parses it. */
int camera_parse_json_bytes(const char *text, size_t length, const char *what, camera *cam, gt_error *e);
/* The JSON text (malloc'd, free()) and an atomic write of it. */
char *camera_to_json(const camera *cam);
int camera_write_json(const char *path, const camera *cam, gt_error *e);

/* A 3/4 view from above of the axis-aligned box [lo, hi], framing its
 * bounding sphere. */
camera camera_auto_framing(vec3 lo, vec3 hi, int width, int height);

/* "<output without .exr>.camera.json", the file written next to every output. */
void camera_sidecar_path(const char *output_path, char *out, int out_size);

#endif
