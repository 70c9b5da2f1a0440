/* `gtlab render multibounce`: GTAO's multi-bounce AO V'_d under a white dome
 * for one or several albedos, or the scene's colours
 * (multibounce_integrator.h); `gtlab render
 * heightfield-multibounce`: the same of the depth buffer taken as a height
 * field (heightfield_multibounce_integrator.h), with the same
 * options, channels and header. */
#include "multibounce/multibounce_quantity.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#include "core/reference_schema.h"
#include "multibounce/heightfield_multibounce_integrator.h"

_Static_assert(offsetof(multibounce_render_settings, header) == 0, "the header comes first");

multibounce_settings *multibounce_settings_of(const reference_request *rq)
{
    reference_settings *s = reference_settings_of(rq, QUANTITY_MULTIBOUNCE);
    if (!s)
        s = reference_settings_of(rq, QUANTITY_HEIGHTFIELD_MULTIBOUNCE);
    return s ? &((multibounce_render_settings *)s)->multibounce : NULL;
}

static int parse_albedo(reference_request *rq, const char *value, gt_error *e)
{
    return multibounce_parse_albedos(value, multibounce_settings_of(rq), e);
}

static int parse_bounces(reference_request *rq, const char *value, gt_error *e)
{
    return multibounce_parse_bounces(value, multibounce_settings_of(rq), e);
}

/* env-diffuse lists its own --albedo and --bounces, of the same names
 * (techniques/environment/environment_quantity.c); its --albedo's help
 * follows this one in `gtlab render --help`. */
static const reference_option option_albedo = {
    .name = "albedo",
    .value = "A,B,...|scene",
    .required = 1,
    .hint = "grey albedos such as 0.1,0.5,0.9, or 'scene'",
    .help = "grey albedos in [0, 1], all\n"
            "rendered from the same paths in one pass, or 'scene': the\n"
            "glTF base colours (textures included), coloured R, G, B",
    .parse = parse_albedo,
};

static const reference_option option_bounces = {
    .name = "bounces",
    .value = "N|inf",
    .help = "inter-reflections after the first hit\n"
            "(0 gives V_d; default 4, as the GTAO talk); 'inf' ends paths\n"
            "by Russian roulette instead (unbiased)",
    .parse = parse_bounces,
};

static void set_defaults(reference_request *rq)
{
    multibounce_settings *mb = multibounce_settings_of(rq);
    if (mb)
        mb->bounces = 4; /* the GTAO talk's */
}

/* rq's albedos and bounces, or an error naming the quantity when it has none. */
static const multibounce_settings *settings_or_error(const reference_pass *pass, gt_error *e)
{
    const multibounce_settings *mb = multibounce_settings_of(pass->req);
    if (!mb)
        gt_error_set(e, reference_quantity_name(pass->req->quantity), "no settings");
    return mb;
}

static int prepare(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    const multibounce_settings *mb = settings_or_error(pass, e);
    if (!mb)
        return -1;
    multibounce_plan *plan = malloc(sizeof *plan);
    if (!plan)
        return gt_error_set(e, pass->scene_spec, "out of memory");
    if (multibounce_plan_init(plan, mb, pass->req->normals, e) != 0) {
        free(plan);
        return -1;
    }
    if (mb->scene_albedo)
        multibounce_warn_albedo_range(pass->scene);
    *state = plan;
    *it = multibounce_integrator(pass->es, plan);
    return 0;
}

/* gtlab.albedos, gtlab.bounces and gtlab.settings. */
static int write_settings(const reference_request *rq, image *out)
{
    char albedos[512], bounces[16];
    const multibounce_settings *mb = multibounce_settings_of(rq);
    if (!mb)
        return -1;
    multibounce_albedos_text(mb, albedos, sizeof albedos);
    multibounce_bounces_text(mb, bounces, sizeof bounces);
    int rc = image_set_attribute(out, ATTR_ALBEDOS, albedos);
    rc |= image_set_attribute(out, ATTR_BOUNCES, bounces);
    rc |= reference_set_attributef(out, ATTR_SETTINGS, "albedos=%s bounces=%s target_stderr=%.9g", albedos, bounces,
                                   rq->sampling.target_stderr);
    return rc;
}

/* The plan and the height field its world points at. */
typedef struct {
    multibounce_plan plan;
    heightfield_settings hf;
} heightfield_multibounce_state;

static void release_heightfield(void *state)
{
    heightfield_multibounce_state *st = state;
    heightfield_settings_free(&st->hf);
    free(st);
}

static int prepare_heightfield(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    const multibounce_settings *mb = settings_or_error(pass, e);
    if (!mb)
        return -1;
    heightfield_multibounce_state *st = calloc(1, sizeof *st);
    if (!st)
        return gt_error_set(e, pass->scene_spec, "out of memory");
    if (multibounce_plan_init(&st->plan, mb, pass->req->normals, e) != 0) {
        free(st);
        return -1;
    }
    if (heightfield_settings_init(&st->hf, pass->gb, INFINITY) != 0) {
        free(st);
        return gt_error_set(e, pass->scene_spec, "out of memory for the height field");
    }
    if (mb->scene_albedo)
        multibounce_warn_albedo_range(pass->scene);
    *state = st;
    *it = heightfield_multibounce_integrator(pass->es, &st->hf, &st->plan);
    return 0;
}

const reference_quantity_descriptor reference_quantity_heightfield_multibounce = {
    .name = "heightfield-multibounce",
    .help = "multibounce's channels and header where rays meet only the depth\n"
            "buffer taken as a height field (as heightfield-ao: infinite\n"
            "thickness, rays leaving the image escape) and a blocked ray goes on\n"
            "from the height field's surface it enters (a pixel's plane or its\n"
            "column's side): the multi-bounce truth of the world screen-space\n"
            "AO sees",
    .options = (const reference_option *const[]){&option_albedo, &option_bounces, NULL},
    .settings_size = sizeof(multibounce_render_settings),
    .set_defaults = set_defaults,
    .prepare = prepare_heightfield,
    .release = release_heightfield,
    .write_settings = write_settings,
};

const reference_quantity_descriptor reference_quantity_multibounce = {
    .name = "multibounce",
    .help = "the G-buffer plus V'_d = L / albedo: the radiance of Lambertian\n"
            "surfaces of that albedo under a uniform white dome of radiance 1,\n"
            "divided by the albedo (GTAO's multi-bounce AO), and ao.V (V_d) of the\n"
            "same pixels. Channels: multibounce.V (one albedo), multibounce_<a>.V\n"
            "for each of several (e.g. multibounce_0.3.V), or multibounce.R/G/B with\n"
            "--albedo scene; the header holds gtlab.albedos and gtlab.bounces",
    .options = (const reference_option *const[]){&option_albedo, &option_bounces, NULL},
    .settings_size = sizeof(multibounce_render_settings),
    .set_defaults = set_defaults,
    .prepare = prepare,
    .release = free,
    .write_settings = write_settings,
};
