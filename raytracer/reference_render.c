#include "raytracer/reference_render.h"

#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raytracer/ao_integrator.h"
#include "raytracer/heightfield_ao_integrator.h"
#include "raytracer/specular_occlusion_integrator.h"
#include "core/reference_schema.h"

/* In the order of reference_quantity. */
static const char *const quantity_names[] = {"gbuffer", "ao", "multibounce", "heightfield-ao", "specular-occlusion",
                                             "sphere-light"};
enum { QUANTITY_COUNT = sizeof quantity_names / sizeof quantity_names[0] };

int reference_quantity_parse(const char *name, reference_quantity *q)
{
    for (int i = 0; i < QUANTITY_COUNT; ++i)
        if (strcmp(name, quantity_names[i]) == 0) {
            *q = (reference_quantity)i;
            return 0;
        }
    return -1;
}

const char *reference_quantity_name(reference_quantity q)
{
    return (int)q >= 0 && (int)q < QUANTITY_COUNT ? quantity_names[q] : "unknown";
}

static int set_attributef(image *img, const char *key, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int set_attributef(image *img, const char *key, const char *fmt, ...)
{
    char text[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    return image_set_attribute(img, key, text);
}

static int write_header(const char *scene_spec, const camera *cam, const reference_request *req, image *img)
{
    char *camera_json = camera_to_json(cam);
    int rc = camera_json ? 0 : -1;
    rc |= image_set_attribute(img, ATTR_VERSION, GTLAB_VERSION);
    rc |= image_set_attribute(img, ATTR_QUANTITY, reference_quantity_name(req->quantity));
    rc |= image_set_attribute(img, ATTR_SCENE, scene_spec);
    if (camera_json)
        rc |= image_set_attribute(img, ATTR_CAMERA, camera_json);
    free(camera_json);
    rc |= image_set_attribute(img, ATTR_NORMAL, req->normals == NORMAL_GEOMETRIC ? "geometric" : "shading");
    if (req->quantity == QUANTITY_GBUFFER)
        return rc;
    const sampling_settings *ss = &req->sampling;
    rc |= set_attributef(img, ATTR_SPP, "%d", ss->spp);
    rc |= set_attributef(img, ATTR_SEED, "%" PRIu32, ss->seed);
    rc |= set_attributef(img, ATTR_BLOCKS, "%" PRIu32 ":%" PRIu32 "+%d", ss->seed, ss->sample_offset, ss->spp);
    if (req->quantity == QUANTITY_MULTIBOUNCE) {
        char albedos[512], bounces[16];
        multibounce_albedos_text(&req->multibounce, albedos, sizeof albedos);
        multibounce_bounces_text(&req->multibounce, bounces, sizeof bounces);
        rc |= image_set_attribute(img, ATTR_ALBEDOS, albedos);
        rc |= image_set_attribute(img, ATTR_BOUNCES, bounces);
        rc |= set_attributef(img, ATTR_SETTINGS, "albedos=%s bounces=%s target_stderr=%.9g", albedos, bounces,
                             ss->target_stderr);
    } else if (req->quantity == QUANTITY_SPHERE_LIGHT) {
        char light[512];
        sphere_light_settings_text(&req->sphere_light, light, sizeof light);
        rc |= set_attributef(img, ATTR_SETTINGS, "%s target_stderr=%.9g", light, ss->target_stderr);
    } else if (req->quantity == QUANTITY_SPECULAR_OCCLUSION) {
        char roughness[32] = "material";
        if (req->roughness >= 0.0f) {
            snprintf(roughness, sizeof roughness, "%.9g", req->roughness);
            rc |= schema_set_real(img, ATTR_ROUGHNESS, req->roughness);
        }
        rc |= set_attributef(img, ATTR_SETTINGS, "roughness=%s environment=%s target_stderr=%.9g", roughness,
                             environment_name(req->environment), ss->target_stderr);
    } else {
        rc |= set_attributef(img, ATTR_SETTINGS, "max_distance=%.9g target_stderr=%.9g", req->max_distance,
                             ss->target_stderr);
    }
    return rc;
}

/* Samples the request's quantity at the G-buffer's surfaces into `out`. */
static int render_quantity(const embree_scene *es, const gbuffer *gb, const reference_request *req,
                           const multibounce_plan *plan, const sphere_light_plan *light, const char *scene_spec,
                           image *out, render_stats *stats, gt_error *e)
{
    ao_settings ao = {req->max_distance};
    specular_occlusion_settings so = {req->roughness, gb->view.origin, req->environment};
    heightfield_settings hf = {0};
    if (req->quantity == QUANTITY_HEIGHTFIELD_AO && heightfield_settings_init(&hf, gb, req->max_distance) != 0)
        return gt_error_set(e, scene_spec, "out of memory for the height field");
    integrator it;
    switch (req->quantity) {
    case QUANTITY_AO: it = ao_integrator(es, &ao); break;
    case QUANTITY_HEIGHTFIELD_AO: it = heightfield_ao_integrator(&hf); break;
    case QUANTITY_SPECULAR_OCCLUSION: it = specular_occlusion_integrator(es, &so); break;
    case QUANTITY_SPHERE_LIGHT: it = sphere_light_integrator(es, light); break;
    default: it = multibounce_integrator(es, plan); break;
    }
    mc_film film;
    int estimated = render_estimates(gb, &it, &req->sampling, &film, stats, e);
    heightfield_settings_free(&hf);
    if (estimated != 0)
        return -1;
    int rc = 0;
    if (mc_film_write_channels(&film, image_channel_data(out, CH_MASK), out) != 0 ||
        (req->quantity == QUANTITY_SPECULAR_OCCLUSION && specular_occlusion_write_ratios(out) != 0))
        rc = gt_error_set(e, scene_spec, "out of memory for the output image");
    mc_film_free(&film);
    return rc;
}

int reference_render(const scene *s, const char *scene_spec, const camera *cam, const reference_request *req,
                     image *out, render_stats *stats, gt_error *e)
{
    memset(stats, 0, sizeof *stats);
    if (camera_validate(cam, scene_spec, e) != 0)
        return -1;
    multibounce_plan plan;
    if (req->quantity == QUANTITY_MULTIBOUNCE) {
        if (multibounce_plan_init(&plan, &req->multibounce, req->normals, e) != 0)
            return -1;
        if (req->multibounce.scene_albedo)
            multibounce_warn_albedo_range(s);
    }
    sphere_light_plan light;
    if (req->quantity == QUANTITY_SPHERE_LIGHT &&
        sphere_light_plan_init(&light, &req->sphere_light, s, cam->position, e) != 0)
        return -1;
    if (image_init(out, cam->width, cam->height) != 0)
        return gt_error_set(e, scene_spec, "invalid image size");
    embree_scene es;
    if (embree_scene_build(s, &es, e) != 0)
        return -1;
    gbuffer gb;
    int rc = gbuffer_render(&es, cam, req->normals, req->sampling.threads, &gb, e);
    if (rc == 0 && gbuffer_write_channels(&gb, s, out) != 0)
        rc = gt_error_set(e, scene_spec, "out of memory for the G-buffer image");
    if (rc == 0 && req->quantity != QUANTITY_GBUFFER)
        rc = render_quantity(&es, &gb, req, &plan, &light, scene_spec, out, stats, e);
    if (rc == 0 && write_header(scene_spec, cam, req, out) != 0)
        rc = gt_error_set(e, scene_spec, "out of memory for the header");
    gbuffer_free(&gb);
    embree_scene_release(&es);
    if (rc != 0)
        image_free(out);
    return rc;
}
