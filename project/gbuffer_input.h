/* A G-buffer as the screen-space techniques take it, read from any EXR that
 * holds depth.Z, N.X/Y/Z and mask.A (a `gtlab render gbuffer` output or any
 * reference render) with its camera, and the approximation output image that
 * goes with it. Shared by `gtlab approx`, the GTAO study and parameter fit,
 * and the specular-occlusion stage. It knows scene/camera and
 * realtime/screen_space, so it lives in project/, the lowest layer that may
 * include both. */
#ifndef GTLAB_PROJECT_GBUFFER_INPUT_H
#define GTLAB_PROJECT_GBUFFER_INPUT_H

#include "core/error.h"
#include "core/image.h"
#include "realtime/screen_space.h"
#include "scene/camera.h"
#include "scene/scene.h"

typedef struct {
    image img;      /* every channel of the file (a reference's too, e.g. ao.V) */
    ss_gbuffer g;   /* views into img */
    camera cam;
} approx_input;

/* The camera of a G-buffer as real-time code sees it. */
ss_camera approx_ss_camera(const camera *cam);

/* Reads `path` (an EXR with depth.Z, N.X/Y/Z and mask.A) and its camera:
 * camera_path if given, else the header's gtlab.camera, else the sidecar
 * <path>.camera.json. Returns 0, or -1 with e naming the file at fault. */
int approx_load(const char *path, const char *camera_path, approx_input *in, gt_error *e);
/* The same for in->img, already read from `path`; in takes it over (and
 * frees it on failure). */
int approx_from_image(const char *path, const char *camera_path, approx_input *in, gt_error *e);
void approx_input_free(approx_input *in);
/* The G-buffer of scene s (named `name` in errors and the header) at camera
 * cam, rendered by the ray tracer (primary rays only, shading normals) into
 * in, its camera cam: what a real-time renderer's G-buffer pass gives.
 * Returns 0, or -1 with e (nothing to free then). */
int approx_render_gbuffer(const scene *s, const char *name, const camera *cam, int threads, approx_input *in,
                          gt_error *e);

/* A fresh output image of the input's size holding mask.A and the header
 * (gtlab.quantity = "approx", gtlab.technique, gtlab.settings, and the
 * input's gtlab.camera / gtlab.scene). Returns 0 or -1 when out of memory. */
int approx_output_init(const approx_input *in, const char *technique, const char *settings, image *out);

#endif
