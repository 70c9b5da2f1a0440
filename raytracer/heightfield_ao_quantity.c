/* `gtlab render heightfield-ao`: AO where only the depth buffer, taken as a
 * height field, blocks rays (raytracer/heightfield_ao_integrator.h). Shares
 * --max-distance and the settings header with ao. */
#include <stdlib.h>

#include "raytracer/ao_quantity.h"
#include "raytracer/heightfield_ao_integrator.h"

static int prepare(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    heightfield_settings *hf = calloc(1, sizeof *hf);
    if (!hf || heightfield_settings_init(hf, pass->gb, pass->req->max_distance) != 0) {
        free(hf);
        return gt_error_set(e, pass->scene_spec, "out of memory for the height field");
    }
    *state = hf;
    *it = heightfield_ao_integrator(hf);
    return 0;
}

static void release(void *state)
{
    heightfield_settings_free(state);
    free(state);
}

const reference_quantity_descriptor reference_quantity_heightfield_ao = {
    .name = "heightfield-ao",
    .help = "the G-buffer plus ao.V and ao.Vuniform where rays are blocked\n"
            "only by the depth buffer taken as a height field (infinite thickness,\n"
            "rays leaving the image escape): what screen-space AO can know",
    .options = (const reference_option *const[]){&reference_option_max_distance, NULL},
    .set_defaults = ao_quantity_set_defaults,
    .prepare = prepare,
    .release = release,
    .write_settings = ao_quantity_write_settings,
};
