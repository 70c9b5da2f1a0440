/* `gtlab render volumetric-light`: single-scattered radiance of a shadowed
 * spot or point light in a homogeneous medium
 * (techniques/volumetric_light/volumetric_light_integrator.h). */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/number_parse.h"
#include "core/reference_schema.h"
#include "raytracer/reference_render.h"
#include "volumetric_light/volumetric_light_integrator.h"

_Static_assert(offsetof(volumetric_light_settings, header) == 0, "the header comes first");

static volumetric_light_settings *settings_of(const reference_request *rq)
{
    return (volumetric_light_settings *)reference_settings_of(rq, &reference_quantity_volumetric_light);
}

static int parse_light(reference_request *rq, const char *value, gt_error *e)
{
    if (strcmp(value, "spot") == 0)
        settings_of(rq)->kind = VOLUMETRIC_SPOT_LIGHT;
    else if (strcmp(value, "point") == 0)
        settings_of(rq)->kind = VOLUMETRIC_POINT_LIGHT;
    else
        return gt_error_set(e, "--vlight-light", "'%s' is neither spot nor point", value);
    return 0;
}

static int parse_method(reference_request *rq, const char *value, gt_error *e)
{
    if (volumetric_light_method_parse(value, &settings_of(rq)->method) != 0)
        return gt_error_set(e, "--vlight-method", "'%s' is neither quadrature nor monte-carlo", value);
    return 0;
}

static int parse_extinction(reference_request *rq, const char *value, gt_error *e)
{
    return parse_real_in("--vlight-extinction", value, 1e-9, 1e9, &settings_of(rq)->sigma_t, e);
}

static int parse_g(reference_request *rq, const char *value, gt_error *e)
{
    return parse_real_in("--vlight-g", value, -0.99, 0.99, &settings_of(rq)->g, e);
}

static int parse_no_shadows(reference_request *rq, const char *value, gt_error *e)
{
    (void)value, (void)e;
    settings_of(rq)->no_shadows = 1;
    return 0;
}

static const reference_option light_option = {
    .name = "vlight-light", .value = "L", .help = "spot (default) or point", .parse = parse_light};
static const reference_option method_option = {
    .name = "vlight-method",
    .value = "M",
    .help = "quadrature (default; gk15 with an error estimate)\nor monte-carlo (equiangular sampling)",
    .parse = parse_method,
};
static const reference_option extinction_option = {
    .name = "vlight-extinction",
    .value = "S",
    .help = "the medium's sigma_t [1/scene unit] (default 1 / the\nscene's bounding-box diagonal); albedo 0.8",
    .parse = parse_extinction,
};
static const reference_option g_option = {
    .name = "vlight-g", .value = "G", .help = "Henyey-Greenstein g (default 0.3)", .parse = parse_g};
static const reference_option no_shadows_option = {
    .name = "vlight-no-shadows", .help = "the scene does not shadow the light", .parse = parse_no_shadows};

static void set_defaults(reference_request *rq)
{
    volumetric_light_settings *s = settings_of(rq);
    volumetric_light_settings_default(s);
    s->header.quantity = &reference_quantity_volumetric_light;
}

static int prepare(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    const volumetric_light_settings *s = settings_of(pass->req);
    if (!s)
        return gt_error_set(e, "volumetric-light", "no settings");
    volumetric_light_plan *plan = malloc(sizeof *plan);
    if (!plan)
        return gt_error_set(e, pass->scene_spec, "out of memory");
    vec3 lo, hi;
    scene_bounds(pass->scene, &lo, &hi);
    if (volumetric_light_plan_init(plan, s, pass->es, lo, hi, pass->gb->view.origin, e) != 0) {
        free(plan);
        return -1;
    }
    *state = plan;
    *it = volumetric_light_integrator(pass->es, plan);
    return 0;
}

static int write_settings(const reference_request *rq, image *out)
{
    const volumetric_light_settings *s = settings_of(rq);
    return reference_set_attributef(
        out, ATTR_SETTINGS,
        "light=%s method=%s placement=%s outer_deg=%.9g inner_deg=%.9g intensity=%.9g sigma_t=%.9g albedo=%.9g "
        "g=%.9g shadows=%s rel_tol=%.9g",
        s->kind == VOLUMETRIC_SPOT_LIGHT ? "spot" : "point", volumetric_light_method_name(s->method),
        s->has_placement ? "given" : "bounds", s->outer_deg, s->inner_deg, s->intensity, s->sigma_t, s->albedo, s->g,
        s->no_shadows ? "off" : "on", s->rel_tol);
}

const reference_quantity_descriptor reference_quantity_volumetric_light = {
    .name = "volumetric-light",
    .help = "the G-buffer plus the light a shadowed spot (or point) light scatters\n"
            "once towards the camera in a homogeneous medium, up to the first\n"
            "surface: vlight.L.R/G/B (with .stderr); with --vlight-method quadrature\n"
            "also vlight_quadrature_error.R/G/B",
    .options = (const reference_option *const[]){&light_option, &method_option, &extinction_option, &g_option,
                                                 &no_shadows_option, NULL},
    .settings_size = sizeof(volumetric_light_settings),
    .set_defaults = set_defaults,
    .prepare = prepare,
    .release = free,
    .write_settings = write_settings,
};
