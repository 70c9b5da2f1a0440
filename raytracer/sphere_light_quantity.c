/* `gtlab render sphere-light`: radiance towards the camera from a uniform
 * spherical light over the glTF materials
 * (raytracer/sphere_light_integrator.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/number_parse.h"
#include "core/reference_schema.h"
#include "raytracer/reference_render.h"

/* "X,Y,Z": three finite numbers. */
static int parse_position(reference_request *rq, const char *value, gt_error *e)
{
    double v[3];
    char extra;
    if (sscanf(value, "%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &extra) != 3 || !isfinite(v[0]) || !isfinite(v[1]) ||
        !isfinite(v[2]))
        return gt_error_set(e, "--light-position", "'%s' is not three numbers X,Y,Z", value);
    rq->sphere_light.position = v3((float)v[0], (float)v[1], (float)v[2]);
    return 0;
}

static int parse_radius(reference_request *rq, const char *value, gt_error *e)
{
    double radius;
    if (parse_real_in("--light-radius", value, 1e-30, 1e30, &radius, e) != 0)
        return -1;
    rq->sphere_light.radius = (float)radius;
    return 0;
}

static int parse_radiance(reference_request *rq, const char *value, gt_error *e)
{
    double radiance;
    if (parse_real_in("--light-radiance", value, 1e-30, 1e30, &radiance, e) != 0)
        return -1;
    rq->sphere_light.radiance = (float)radiance;
    return 0;
}

static int parse_shadows(reference_request *rq, const char *value, gt_error *e)
{
    (void)value, (void)e;
    rq->sphere_light.shadows = 1;
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
    rq->sphere_light.radiance = 1.0f;
}

static int prepare(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    sphere_light_plan *plan = malloc(sizeof *plan);
    if (!plan)
        return gt_error_set(e, pass->scene_spec, "out of memory");
    if (sphere_light_plan_init(plan, &pass->req->sphere_light, pass->scene, pass->cam->position, e) != 0) {
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
    sphere_light_settings_text(&rq->sphere_light, light, sizeof light);
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
    .set_defaults = set_defaults,
    .prepare = prepare,
    .release = free,
    .write_settings = write_settings,
};
