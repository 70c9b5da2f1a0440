/* One built-in scene's inputs for the studies of the GTAO talk's shortcuts
 * (issue 25, items 9-13): the 3-D AO reference with its G-buffer and camera
 * (the `ao` stage's <scene>.exr) and the height-field reference the `gtao`
 * stage rendered at the same camera (gtao/<scene>_heightfield.exr,
 * gtao_validation.h). Both carry ao.V and its standard error; the 3-D
 * one carries the reference bent normal too. */
#ifndef GTLAB_GTAO_GTAO_SCENE_REFS_H
#define GTLAB_GTAO_GTAO_SCENE_REFS_H

#include "core/image.h"
#include "gtao/gtao.h"
#include "project/gbuffer_input.h"
#include "project/study_context.h"

typedef struct {
    char scene[64];
    approx_input in; /* the 3-D reference: its G-buffer in in.g */
    image hf;        /* the height-field reference */
    int width, height;
    const float *mask;
    const float *ref3d, *ref3d_stderr; /* ao.V, ao.V.stderr of the 3-D reference */
    const float *hf_ao, *hf_stderr;    /* the same of the height-field reference */
    const float *bent[3];              /* the 3-D reference's bent normal (NULL if absent) */
    float vo_radius;                   /* a quarter of the camera's distance to its target (as gtao_validation) */
} gtao_scene_refs;

/* Loads <refs_dir>/<scene>.exr and <gtao_dir>/<scene>_heightfield.exr.
 * Returns 0, or -1 with e naming the file at fault (missing, wrong size, no
 * ao.V); nothing to free then. */
int gtao_scene_refs_load(const char *refs_dir, const char *gtao_dir, const char *scene, gtao_scene_refs *out,
                         gt_error *e);
/* The 3-D reference alone, <refs_dir>/<scene>.exr: hf is empty and hf_ao,
 * hf_stderr NULL (the stage screen-shaders, which needs only the ao stage). */
int gtao_scene_refs_load_3d(const char *refs_dir, const char *scene, gtao_scene_refs *out, gt_error *e);
void gtao_scene_refs_free(gtao_scene_refs *s);

/* GTAO's parameters with no radius limit, as gtao_validation scores them:
 * the preset, radius 1e6, no falloff, screen radius the image width, one
 * frame. */
gtao_params gtao_scene_params(const gtao_scene_refs *s, int preset);

/* The height-field reference of scene `spec` at camera `cam` (shading
 * normals, no distance limit, seed 1, at most spp samples per pixel, a
 * pixel stopping at the standard error noise_budget; 0: every pixel takes
 * spp) into hf,
 * written to path (the gtao stage's <scene>_heightfield.exr, the
 * multi-bounce study's "agnostic" source). Returns 0, or -1 with e (hf
 * empty then). */
int gtao_render_heightfield(const study_context *ctx, const char *spec, const camera *cam, int spp,
                            double noise_budget, const char *path, image *hf, gt_error *e);

#endif
