/* `gtlab render sphere-light`: radiance towards the camera from a uniform
 * spherical light over the glTF materials
 * (techniques/sphere_light/sphere_light_integrator.h). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/number_parse.h"
#include "core/reference_schema.h"
#include "sphere_light/sphere_light_quantity.h"

_Static_assert(offsetof(sphere_light_quantity_settings, header) == 0, "the header comes first");

sphere_light_quantity_settings sphere_light_quantity_settings_of(sphere_light_settings light)
{
    return (sphere_light_quantity_settings){{QUANTITY_SPHERE_LIGHT}, light};
}

/* The light of rq's settings (the options' and set_defaults' rq has them). */
static sphere_light_settings *light_of(const reference_request *rq)
{
    sphere_light_quantity_settings *s =
        (sphere_light_quantity_settings *)reference_settings_of(rq, QUANTITY_SPHERE_LIGHT);
    return s ? &s->light : NULL;
}

/* "X,Y,Z": three finite numbers. */
static int parse_position(reference_request *rq, const char *value, gt_error *e)
{
    double v[3];
    char extra;
    if (sscanf(value, "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &extra) != 3 || !isfinite(v[0]) || !isfinite(v[1]) ||
        !isfinite(v[2]))
        return gt_error_set(e, "--light-position", "'%s' is not three numbers X,Y,Z", value);
    light_of(rq)->position = v3((float)v[0], (float)v[1], (float)v[2]);
    return 0;
}

static int parse_radius(reference_request *rq, const char *value, gt_error *e)
{
    double radius;
    if (parse_real_in("--light-radius", value, 1e-30, 1e30, &radius, e) != 0)
        return -1;
    light_of(rq)->radius = (float)radius;
    return 0;
}

static int parse_radiance(reference_request *rq, const char *value, gt_error *e)
{
    double radiance;
    if (parse_real_in("--light-radiance", value, 1e-30, 1e30, &radiance, e) != 0)
        return -1;
    light_of(rq)->radiance = (float)radiance;
    return 0;
}

static int parse_shadows(reference_request *rq, const char *value, gt_error *e)
{
    (void)value, (void)e;
    light_of(rq)->shadows = 1;
    return 0;
}

/* A relative target suits a quantity spanning decades: an absolute one is
 * met at once by dim pixels and late by bright ones. */
static int parse_target_rel(reference_request *rq, const char *value, gt_error *e)
{
    return parse_real_in("--target-rel-stderr", value, 0.0, 1.0, &rq->sampling.target_rel_stderr, e);
}

static const reference_option position_option = {
    .name = "light-position", .value = "X,Y,Z", .required = 1, .help = "the light's centre", .parse = parse_position};
static const reference_option radius_option = {
    .name = "light-radius", .value = "R", .required = 1, .help = "its radius, > 0", .parse = parse_radius};
static const reference_option radiance_option = {
    .name = "light-radiance", .value = "L", .help = "its emitted radiance (default 1)", .parse = parse_radiance};
static const reference_option shadows_option = {
    .name = "shadows",
    .help = "the scene's geometry blocks the light (one\n"
            "occlusion ray per light-carrying sample direction)",
    .parse = parse_shadows,
};

static const reference_option target_rel_option = {
    .name = "target-rel-stderr",
    .value = "R",
    .help = "stop a pixel once the standard error of sphere.R\n"
            "is <= R times its mean (checked as --target-stderr;\n"
            "with both, the first met stops it)",
    .parse = parse_target_rel,
};

static void set_defaults(reference_request *rq)
{
    light_of(rq)->radiance = 1.0f;
}

static int prepare(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    const sphere_light_settings *light = light_of(pass->req);
    if (!light)
        return gt_error_set(e, "sphere-light", "no settings");
    sphere_light_plan *plan = malloc(sizeof *plan);
    if (!plan)
        return gt_error_set(e, pass->scene_spec, "out of memory");
    if (sphere_light_plan_init(plan, light, pass->scene, pass->cam->position, e) != 0) {
        free(plan);
        return -1;
    }
    *state = plan;
    *it = sphere_light_integrator(pass->es, plan);
    return 0;
}

static int write_settings(const reference_request *rq, image *out)
{
    char light[512];
    sphere_light_settings_text(light_of(rq), light, sizeof light);
    return reference_set_attributef(out, ATTR_SETTINGS, "%s target_stderr=%.9g target_rel_stderr=%.9g", light,
                                    rq->sampling.target_stderr, rq->sampling.target_rel_stderr);
}

const reference_quantity_descriptor reference_quantity_sphere_light = {
    .name = "sphere-light",
    .help = "the G-buffer plus sphere.R/G/B: radiance towards the camera from a\n"
            "uniform spherical light over the glTF materials (Lambert + GGX with\n"
            "Schlick Fresnel), integrated exactly over the light (MIS); unshadowed\n"
            "like the real-time approximations unless --shadows",
    .options = (const reference_option *const[]){&position_option, &radius_option, &radiance_option, &shadows_option,
                                                 &target_rel_option, NULL},
    .settings_size = sizeof(sphere_light_quantity_settings),
    .set_defaults = set_defaults,
    .prepare = prepare,
    .release = free,
    .write_settings = write_settings,
};
