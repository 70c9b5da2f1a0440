/* `gtlab render heightfield-ao`: AO where only the depth buffer, taken as a
 * height field, blocks rays (techniques/ao/heightfield_ao_integrator.h). Shares
 * the parse of --max-distance and the settings header with ao; --thickness T makes each
 * pixel a slab of depth T (the header's settings then end in thickness=T). */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "core/number_parse.h"
#include "core/reference_schema.h"
#include "ao/ao_quantity.h"
#include "ao/heightfield_ao_integrator.h"

_Static_assert(offsetof(heightfield_ao_options, header) == 0, "the header comes first");

heightfield_ao_options heightfield_ao_thickness(float thickness)
{
    return (heightfield_ao_options){{QUANTITY_HEIGHTFIELD_AO}, INFINITY, thickness};
}

static heightfield_ao_options *options_of(const reference_request *rq)
{
    return (heightfield_ao_options *)reference_settings_of(rq, QUANTITY_HEIGHTFIELD_AO);
}

/* rq's settings, or the defaults (no limit, solid behind) when it carries none. */
static heightfield_ao_options options_or_defaults(const reference_request *rq)
{
    const heightfield_ao_options *o = options_of(rq);
    return o ? *o : heightfield_ao_thickness(INFINITY);
}

static int parse_max_distance(reference_request *rq, const char *value, gt_error *e)
{
    return ao_parse_max_distance(value, &options_of(rq)->max_distance, e);
}

/* ao's option of the same name says what it does (a NULL help adds none). */
static const reference_option option_max_distance = {
    .name = "max-distance",
    .value = "D",
    .parse = parse_max_distance,
};

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
    if (options_of(rq))
        *options_of(rq) = heightfield_ao_thickness(INFINITY);
}

/* ao's settings (heightfield-ao has no fade), " thickness=T" appended when T is finite. */
static int write_settings(const reference_request *rq, image *out)
{
    heightfield_ao_options o = options_or_defaults(rq);
    if (isinf(o.thickness))
        return ao_quantity_write_settings(out, o.max_distance, 0.0f, rq->sampling.target_stderr);
    return reference_set_attributef(out, ATTR_SETTINGS, "max_distance=%.9g target_stderr=%.9g thickness=%.9g",
                                    o.max_distance, rq->sampling.target_stderr, o.thickness);
}

static int prepare(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    heightfield_ao_options o = options_or_defaults(pass->req);
    heightfield_settings *hf = calloc(1, sizeof *hf);
    if (!hf || heightfield_settings_init(hf, pass->gb, o.max_distance) != 0) {
        free(hf);
        return gt_error_set(e, pass->scene_spec, "out of memory for the height field");
    }
    hf->thickness = o.thickness;
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
    .options = (const reference_option *const[]){&option_max_distance, &option_thickness, NULL},
    .settings_size = sizeof(heightfield_ao_options),
    .set_defaults = set_defaults,
    .prepare = prepare,
    .release = release,
    .write_settings = write_settings,
};
