/* One reference render from start to finish: Embree scene, G-buffer, the
 * quantity's integrator, and the output image with the DESIGN.md channels and
 * header (quantity, scene, camera, spp, seed, sample block, version).
 * `gtlab render`, `gtlab all`, `gtlab bench` and the tests all come here. */
#ifndef GTLAB_RAYTRACER_REFERENCE_RENDER_H
#define GTLAB_RAYTRACER_REFERENCE_RENDER_H

#include "core/image.h"
#include "raytracer/gbuffer.h"
#include "raytracer/reference_quantity.h"
#include "raytracer/render_loop.h"
#include "scene/scene.h"

/* The quantity every other stands on, the G-buffer (gbuffer_quantity.c), by
 * name for callers: `.quantity = QUANTITY_GBUFFER`. A technique's quantities
 * are declared by its reference part (e.g. techniques/ao/ao_quantity.h:
 * QUANTITY_AO). */
extern const reference_quantity_descriptor reference_quantity_gbuffer;
#define QUANTITY_GBUFFER (&reference_quantity_gbuffer)

/* What to render. A quantity keeps its settings in its own struct, headed by
 * a reference_settings naming it (reference_quantity.h), pointed at by
 * `settings` (its descriptor's settings_size: its options fill it on the
 * command line, a caller points it at its own struct), so adding a quantity
 * changes nothing here. A zeroed request (quantity NULL) renders the
 * G-buffer. */
typedef struct reference_request {
    reference_quantity quantity;
    sampling_settings sampling;
    normal_mode normals;
    reference_settings *settings;     /* the quantity's own settings (their header names it), or NULL */
    /* Where this process keeps its checkpoint (raytracer/render_checkpoint.h;
     * under mpirun each rank its own: render_checkpoint_files.h), or NULL:
     * no checkpoints. */
    const char *checkpoint;
    int resume; /* continue from the checkpoint there */
} reference_request;

/* Renders into `out` (initialised here). scene_spec is recorded in the header. */
int reference_render(const scene *s, const char *scene_spec, const camera *cam, const reference_request *req,
                     image *out, render_stats *stats, gt_error *e);

#endif
