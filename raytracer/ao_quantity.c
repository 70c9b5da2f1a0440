/* `gtlab render ao`: ambient occlusion and bent normals traced in the 3-D
 * scene (raytracer/ao_integrator.h). */
#include "raytracer/ao_quantity.h"

#include <math.h>
#include <stdlib.h>

#include "core/number_parse.h"
#include "core/reference_schema.h"
#include "raytracer/ao_integrator.h"

static int parse_max_distance(reference_request *rq, const char *value, gt_error *e)
{
    double d;
    if (parse_real_in("--max-distance", value, 1e-30, 1e30, &d, e) != 0)
        return -1;
    rq->max_distance = (float)d;
    return 0;
}

const reference_option reference_option_max_distance = {
    .name = "max-distance",
    .value = "D",
    .help = "rays farther than D count as\nunoccluded (default: none)",
    .parse = parse_max_distance,
};

void ao_quantity_set_defaults(reference_request *rq)
{
    rq->max_distance = INFINITY;
}

int ao_quantity_write_settings(const reference_request *rq, image *out)
{
    return reference_set_attributef(out, ATTR_SETTINGS, "max_distance=%.9g target_stderr=%.9g", rq->max_distance,
                                    rq->sampling.target_stderr);
}

static int prepare(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    ao_settings *ao = malloc(sizeof *ao);
    if (!ao)
        return gt_error_set(e, pass->scene_spec, "out of memory");
    ao->max_distance = pass->req->max_distance;
    *state = ao;
    *it = ao_integrator(pass->es, ao);
    return 0;
}

const reference_quantity_descriptor reference_quantity_ao = {
    .name = "ao",
    .help = "the G-buffer plus ao.V (cosine AO), ao.Vuniform (uniform AO),\n"
            "bent.X/Y/Z (bent normal), each with .stderr and the exact\n"
            "accumulators (.sum, .sumeven, .peak, .m1_*, .m2_*) that 'gtlab merge'\n"
            "combines",
    .options = (const reference_option *const[]){&reference_option_max_distance, NULL},
    .set_defaults = ao_quantity_set_defaults,
    .prepare = prepare,
    .release = free,
    .write_settings = ao_quantity_write_settings,
};
