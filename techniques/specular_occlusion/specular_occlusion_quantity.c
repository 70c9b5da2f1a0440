/* `gtlab render specular-occlusion`: GTSO specular occlusion under a white
 * dome, and with --environment sky the split integrals under an analytic sky
 * (specular_occlusion_integrator.h). */
#include "specular_occlusion/specular_occlusion_quantity.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/reference_schema.h"
#include "core/roughness_setting.h"
#include "specular_occlusion/specular_occlusion_integrator.h"

_Static_assert(offsetof(specular_occlusion_render_settings, header) == 0, "the header comes first");

specular_occlusion_render_settings specular_occlusion_render_settings_make(float roughness,
                                                                           environment_kind environment)
{
    return (specular_occlusion_render_settings){{QUANTITY_SPECULAR_OCCLUSION}, roughness, environment};
}

static specular_occlusion_render_settings *settings_of(const reference_request *rq)
{
    return (specular_occlusion_render_settings *)reference_settings_of(rq, QUANTITY_SPECULAR_OCCLUSION);
}

/* env-diffuse and env-specular have their own --environment and
 * --roughness (their --environment's help follows this one's in `gtlab
 * render --help`). */
static int parse_environment(reference_request *rq, const char *value, gt_error *e)
{
    if (environment_parse(value, &settings_of(rq)->environment) != 0)
        return gt_error_set(e, "--environment", "'%s' is neither white nor sky", value);
    return 0;
}

static int parse_roughness(reference_request *rq, const char *value, gt_error *e)
{
    return reference_parse_roughness(value, &settings_of(rq)->roughness, e);
}

static const reference_option environment_option = {
    .name = "environment",
    .value = "E",
    .help = "white (default) or sky, which adds the\n"
            "two- vs three-split channels (techniques/specular_occlusion/README.md);",
    .parse = parse_environment,
};

static const reference_option option_roughness = {
    .name = "roughness",
    .value = "R",
    .help = "perceptual roughness in [0, 1] for\n"
            "every surface (GGX alpha = R^2); default: the glTF material",
    .parse = parse_roughness,
};

static void set_defaults(reference_request *rq)
{
    if (settings_of(rq))
        settings_of(rq)->roughness = ROUGHNESS_OF_MATERIAL;
}

static int prepare(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    const specular_occlusion_render_settings *s = settings_of(pass->req);
    if (!s)
        return gt_error_set(e, reference_quantity_name(pass->req->quantity), "no settings");
    specular_occlusion_settings *so = malloc(sizeof *so);
    if (!so)
        return gt_error_set(e, pass->scene_spec, "out of memory");
    *so = (specular_occlusion_settings){s->roughness, pass->gb->view.origin, s->environment};
    *state = so;
    *it = specular_occlusion_integrator(pass->es, so);
    return 0;
}

/* gtlab.roughness (when fixed) and gtlab.settings. */
static int write_settings(const reference_request *rq, image *out)
{
    const specular_occlusion_render_settings *s = settings_of(rq);
    char roughness[32];
    int rc = reference_write_roughness(out, s->roughness, roughness, sizeof roughness);
    rc |= reference_set_attributef(out, ATTR_SETTINGS, "roughness=%s environment=%s target_stderr=%.9g", roughness,
                                   environment_name(s->environment), rq->sampling.target_stderr);
    return rc;
}

const reference_quantity_descriptor reference_quantity_specular_occlusion = {
    .name = "specular-occlusion",
    .help = "the G-buffer plus GTSO specular occlusion under a white\n"
            "dome: specocc.V = integral of V f_r cos / integral of f_r cos (GGX,\n"
            "no Fresnel, view from the camera), specocc_d.V (the older D-only\n"
            "definition), specocc_phong.V (the same with Phong's NDF,\n"
            "p = 2/alpha^2 - 2), and the integrals: specocc_occluded.V,\n"
            "specocc_unoccluded.V (directional albedo), specocc_d_*.V,\n"
            "specocc_phong_*.V; ratios'\n"
            "standard errors by the delta method. With --environment sky also\n"
            "the GTSO talk's split integrals under an analytic sky: split_truth.V\n"
            "(integral of V L f_r cos), split_two.V, split_three.V",
    .options = (const reference_option *const[]){&environment_option, &option_roughness, NULL},
    .settings_size = sizeof(specular_occlusion_render_settings),
    .set_defaults = set_defaults,
    .prepare = prepare,
    .release = free,
    .finish = specular_occlusion_write_ratios,
    .write_settings = write_settings,
};
