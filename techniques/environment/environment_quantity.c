/* `gtlab render env-diffuse` and `env-specular`: Lambertian and GGX
 * surfaces lit by an environment, with visibility and without
 * (techniques/environment/environment_diffuse_integrator.h,
 * techniques/environment/environment_specular_integrator.h). */
#include "environment/environment_quantity.h"

#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/number_parse.h"
#include "core/reference_schema.h"
#include "core/roughness_setting.h"
#include "environment/environment_diffuse_integrator.h"
#include "environment/environment_specular_integrator.h"
#include "raytracer/reference_render.h"

_Static_assert(offsetof(environment_render_settings, header) == 0, "the header comes first");

/* rq's settings, made for env-diffuse or env-specular (one struct for both). */
static environment_render_settings *settings_of(const reference_request *rq)
{
    reference_settings *s = reference_settings_of(rq, &reference_quantity_env_diffuse);
    return (environment_render_settings *)(s ? s : reference_settings_of(rq, &reference_quantity_env_specular));
}

/* --environment NAME|FILE: stored in the settings; the file is read by prepare. */
static int parse_environment(reference_request *rq, const char *value, gt_error *e)
{
    environment_render_settings *s = settings_of(rq);
    if (value[0] == '\0' || strlen(value) >= sizeof s->environment)
        return gt_error_set(e, "--environment", "'%s' is neither white, sky, sun nor a file name", value);
    snprintf(s->environment, sizeof s->environment, "%s", value);
    return 0;
}

static int parse_rotate(reference_request *rq, const char *value, gt_error *e)
{
    double degrees;
    if (parse_real_in("--env-rotate", value, -360.0, 360.0, &degrees, e) != 0)
        return -1;
    settings_of(rq)->rotate_degrees = (float)degrees;
    return 0;
}

static int parse_intensity(reference_request *rq, const char *value, gt_error *e)
{
    double intensity;
    if (parse_real_in("--env-intensity", value, 0.0, 1e9, &intensity, e) != 0)
        return -1;
    settings_of(rq)->intensity = (float)intensity;
    return 0;
}

static int parse_f0(reference_request *rq, const char *value, gt_error *e)
{
    double f0;
    if (parse_real_in("--f0", value, 0.0, 1.0, &f0, e) != 0)
        return -1;
    settings_of(rq)->f0 = (float)f0;
    return 0;
}

static int parse_albedo(reference_request *rq, const char *value, gt_error *e)
{
    return multibounce_parse_albedos(value, &settings_of(rq)->multibounce, e);
}

static int parse_bounces(reference_request *rq, const char *value, gt_error *e)
{
    return multibounce_parse_bounces(value, &settings_of(rq)->multibounce, e);
}

static int parse_roughness(reference_request *rq, const char *value, gt_error *e)
{
    return reference_parse_roughness(value, &settings_of(rq)->roughness, e);
}

/* Share their names with multibounce's --albedo and --bounces and
 * specular-occlusion's --roughness, whose helps come first in `gtlab render
 * --help` (--bounces and --roughness add nothing to them). */
static const reference_option albedo_option = {
    .name = "albedo",
    .value = "A,B,...|scene",
    .required = 1,
    .hint = "grey albedos such as 0.1,0.5,0.9, or 'scene'",
    .help = "(env-diffuse: one grey albedo or 'scene')",
    .parse = parse_albedo,
};

static const reference_option bounces_option = {
    .name = "bounces",
    .value = "N|inf",
    .parse = parse_bounces,
};

static const reference_option roughness_option = {
    .name = "roughness",
    .value = "R",
    .parse = parse_roughness,
};

/* Shares its name with specular-occlusion's --environment (white or sky),
 * whose help comes first in `gtlab render --help`. */
static const reference_option environment_option = {
    .name = "environment",
    .value = "E",
    .help = "env-*: white (default), sky, sun or an equirectangular image file\n"
            "(EXR, .hdr, ...: techniques/environment/README.md, \"The references\")",
    .parse = parse_environment,
};

static const reference_option rotate_option = {
    .name = "env-rotate",
    .value = "DEG",
    .help = "turns the environment about +Y, +Z towards +X\n(default 0)",
    .parse = parse_rotate,
};

static const reference_option intensity_option = {
    .name = "env-intensity",
    .value = "X",
    .help = "multiplies the environment's radiance (default 1)",
    .parse = parse_intensity,
};

static const reference_option f0_option = {
    .name = "f0",
    .value = "F",
    .help = "grey Fresnel F0 in [0, 1] for every surface\n"
            "(1: no Fresnel); default: the glTF material's",
    .parse = parse_f0,
};

/* ---- Shared by both ---------------------------------------------------------------- */

static void set_defaults(reference_request *rq)
{
    environment_render_settings *s = settings_of(rq);
    environment_render_settings_default(s, rq->quantity);
    s->multibounce.bounces = 4; /* as multibounce */
    s->roughness = ROUGHNESS_OF_MATERIAL;
}

/* What prepare allocates: the light, and the plan of either integrator
 * (which points at the light: the block is never moved). */
typedef struct {
    environment_light light;
    union {
        environment_diffuse_plan diffuse;
        environment_specular_plan specular;
    } plan;
} environment_state;

static environment_state *state_with_light(const reference_pass *pass, gt_error *e)
{
    const environment_render_settings *s = settings_of(pass->req);
    if (!s) {
        gt_error_set(e, reference_quantity_name(pass->req->quantity), "no settings");
        return NULL;
    }
    environment_state *st = malloc(sizeof *st);
    if (!st) {
        gt_error_set(e, pass->scene_spec, "out of memory");
        return NULL;
    }
    if (environment_light_init(&st->light, s, e) != 0) {
        free(st);
        return NULL;
    }
    return st;
}

static void release(void *state)
{
    environment_state *st = state;
    if (st)
        environment_light_free(&st->light);
    free(st);
}

/* gtlab.environment, gtlab.environment_rotate, gtlab.environment_intensity. */
static int write_environment(const environment_render_settings *s, image *out)
{
    int rc = image_set_attribute(out, ATTR_ENVIRONMENT, s->environment);
    rc |= schema_set_real(out, ATTR_ENV_ROTATE, s->rotate_degrees);
    rc |= schema_set_real(out, ATTR_ENV_INTENSITY, s->intensity);
    return rc;
}

/* ---- env-diffuse ------------------------------------------------------------------- */

static int prepare_diffuse(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    environment_state *st = state_with_light(pass, e);
    if (!st)
        return -1;
    const environment_render_settings *s = settings_of(pass->req);
    if (environment_diffuse_plan_init(&st->plan.diffuse, &st->light, &s->multibounce, pass->req->normals, e) != 0) {
        release(st);
        return -1;
    }
    if (s->multibounce.scene_albedo)
        multibounce_warn_albedo_range(pass->scene);
    *state = st;
    *it = environment_diffuse_integrator(pass->es, &st->plan.diffuse);
    return 0;
}

static int write_diffuse_settings(const reference_request *rq, image *out)
{
    const environment_render_settings *s = settings_of(rq);
    char albedos[512], bounces[16];
    multibounce_albedos_text(&s->multibounce, albedos, sizeof albedos);
    multibounce_bounces_text(&s->multibounce, bounces, sizeof bounces);
    int rc = write_environment(s, out);
    rc |= image_set_attribute(out, ATTR_ALBEDOS, albedos);
    rc |= image_set_attribute(out, ATTR_BOUNCES, bounces);
    rc |= reference_set_attributef(out, ATTR_SETTINGS,
                                   "environment=%s env_rotate=%.9g env_intensity=%.9g albedos=%s bounces=%s "
                                   "target_stderr=%.9g",
                                   s->environment, s->rotate_degrees, s->intensity, albedos, bounces,
                                   rq->sampling.target_stderr);
    return rc;
}

const reference_quantity_descriptor reference_quantity_env_diffuse = {
    .name = "env-diffuse",
    .help = "the G-buffer plus Lambertian surfaces lit by an environment,\n"
            "as L / albedo (the white dome's multibounce.V under --environment\n"
            "white): env_diffuse.R/G/B with visibility and --bounces\n"
            "inter-reflections, env_diffuse_direct.R/G/B (direct light only) and\n"
            "env_diffuse_unoccluded.R/G/B (visibility off), from the same samples;\n"
            "the header holds gtlab.environment, gtlab.albedos and gtlab.bounces",
    .options = (const reference_option *const[]){&environment_option, &rotate_option, &intensity_option,
                                                 &albedo_option, &bounces_option, NULL},
    .settings_size = sizeof(environment_render_settings),
    .set_defaults = set_defaults,
    .prepare = prepare_diffuse,
    .release = release,
    .write_settings = write_diffuse_settings,
};

/* ---- env-specular ------------------------------------------------------------------ */

static int prepare_specular(const reference_pass *pass, void **state, integrator *it, gt_error *e)
{
    environment_state *st = state_with_light(pass, e);
    if (!st)
        return -1;
    const environment_render_settings *s = settings_of(pass->req);
    if (environment_specular_plan_init(&st->plan.specular, &st->light, s->roughness, s->f0,
                                       pass->gb->view.origin, e) != 0) {
        release(st);
        return -1;
    }
    *state = st;
    *it = environment_specular_integrator(pass->es, &st->plan.specular);
    return 0;
}

static int write_specular_settings(const reference_request *rq, image *out)
{
    const environment_render_settings *s = settings_of(rq);
    char roughness[32], f0[32] = "material";
    int rc = write_environment(s, out);
    rc |= reference_write_roughness(out, s->roughness, roughness, sizeof roughness);
    if (s->f0 >= 0.0f) {
        snprintf(f0, sizeof f0, "%.9g", s->f0);
        rc |= schema_set_real(out, ATTR_F0, s->f0);
    }
    rc |= reference_set_attributef(out, ATTR_SETTINGS,
                                   "environment=%s env_rotate=%.9g env_intensity=%.9g roughness=%s f0=%s "
                                   "target_stderr=%.9g",
                                   s->environment, s->rotate_degrees, s->intensity, roughness, f0,
                                   rq->sampling.target_stderr);
    return rc;
}

const reference_quantity_descriptor reference_quantity_env_specular = {
    .name = "env-specular",
    .help = "the G-buffer plus GGX specular reflection of an environment\n"
            "(Schlick Fresnel, the material's roughness and F0 or --roughness,\n"
            "--f0): env_specular.R/G/B with visibility and\n"
            "env_specular_unoccluded.R/G/B without, from the same samples",
    .options = (const reference_option *const[]){&environment_option, &rotate_option, &intensity_option,
                                                 &roughness_option, &f0_option, NULL},
    .settings_size = sizeof(environment_render_settings),
    .set_defaults = set_defaults,
    .prepare = prepare_specular,
    .release = release,
    .write_settings = write_specular_settings,
};
