/* `gtlab render heightfield-ao`: AO where only the depth buffer, taken as a
 * height field, blocks rays (raytracer/heightfield_ao_integrator.h). Shares
 * --max-distance and the settings header with ao; --thickness T makes each
 * pixel a slab of depth T (the header's settings then end in thickness=T). */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "core/number_parse.h"
#include "core/reference_schema.h"
#include "raytracer/ao_quantity.h"
#include "raytracer/heightfield_ao_integrator.h"

_Static_assert(offsetof(heightfield_ao_options, header) == 0, "the header comes first");

heightfield_ao_options heightfield_ao_thickness(float thickness)
{
    return (heightfield_ao_options){{QUANTITY_HEIGHTFIELD_AO}, thickness};
}

static heightfield_ao_options *options_of(const reference_request *rq)
{
    return (heightfield_ao_options *)reference_settings_of(rq, QUANTITY_HEIGHTFIELD_AO);
}

static float thickness_of(const reference_request *rq)
{
    const heightfield_ao_options *o = options_of(rq);
    return o ? o->thickness : INFINITY;
}

static int parse_thickness(reference_request *rq, const char *value, gt_error *e)
{
    double t;
    if (parse_real_in("--thickness", value, 1e-30, 1e30, &t, e) != 0)
        return -1;
    options_of(rq)->thickness = (float)t;
    return 0;
}

static const reference_option option_thickness = {
    .name = "thickness",
    .value = "T",
    .help = "each pixel blocks rays only between its\ndepth d and d + T along the camera axis\n"
            "(light passes behind thin objects;\ndefault: infinite, solid behind)",
    .parse = parse_thickness,
};

static void set_defaults(reference_request *rq)
{
    ao_quantity_set_defaults(rq);
    if (options_of(rq))
        options_of(rq)->thickness = INFINITY;
}

/* ao's settings (heightfield-ao has no fade), " thickness=T" appended when T is finite. */
static int write_settings(const reference_request *rq, image *out)
{
    float t = thickness_of(rq);
    if (isinf(t))
        return ao_quantity_write_settings(rq, out);
    return reference_set_attributef(out, ATTR_SETTINGS, "max_distance=%.9g target_stderr=%.9g thickness=%.9g",
                                    rq->max_distance, rq->sampling.target_stderr, t);
}

static int prepare(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    heightfield_settings *hf = calloc(1, sizeof *hf);
    if (!hf || heightfield_settings_init(hf, pass->gb, pass->req->max_distance) != 0) {
        free(hf);
        return gt_error_set(e, pass->scene_spec, "out of memory for the height field");
    }
    hf->thickness = thickness_of(pass->req);
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
            "rays leaving the image escape): what screen-space AO can know;\n"
            "with --thickness T, a slab of depth T behind each pixel instead",
    .options = (const reference_option *const[]){&reference_option_max_distance, &option_thickness, NULL},
    .settings_size = sizeof(heightfield_ao_options),
    .set_defaults = set_defaults,
    .prepare = prepare,
    .release = release,
    .write_settings = write_settings,
};
