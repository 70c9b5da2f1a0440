#include "raytracer/reference_render.h"

#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raytracer/ao_integrator.h"

int reference_quantity_parse(const char *name, reference_quantity *q)
{
    if (strcmp(name, "gbuffer") == 0)
        *q = QUANTITY_GBUFFER;
    else if (strcmp(name, "ao") == 0)
        *q = QUANTITY_AO;
    else
        return -1;
    return 0;
}

const char *reference_quantity_name(reference_quantity q) { return q == QUANTITY_AO ? "ao" : "gbuffer"; }

static int set_attributef(image *img, const char *key, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static int set_attributef(image *img, const char *key, const char *fmt, ...)
{
    char text[512];
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
    rc |= image_set_attribute(img, REF_ATTR_VERSION, GTLAB_VERSION);
    rc |= image_set_attribute(img, REF_ATTR_QUANTITY, reference_quantity_name(req->quantity));
    rc |= image_set_attribute(img, REF_ATTR_SCENE, scene_spec);
    if (camera_json)
        rc |= image_set_attribute(img, REF_ATTR_CAMERA, camera_json);
    free(camera_json);
    rc |= image_set_attribute(img, "gtlab.normal", req->normals == NORMAL_GEOMETRIC ? "geometric" : "shading");
    if (req->quantity == QUANTITY_GBUFFER)
        return rc;
    const sampling_settings *ss = &req->sampling;
    rc |= set_attributef(img, REF_ATTR_SPP, "%d", ss->spp);
    rc |= set_attributef(img, REF_ATTR_SEED, "%" PRIu32, ss->seed);
    rc |= set_attributef(img, REF_ATTR_BLOCKS, "%" PRIu32 ":%" PRIu32 "+%d", ss->seed, ss->sample_offset, ss->spp);
    rc |= set_attributef(img, REF_ATTR_SETTINGS, "max_distance=%.9g target_stderr=%.9g", req->max_distance,
                         ss->target_stderr);
    return rc;
}

int reference_render(const scene *s, const char *scene_spec, const camera *cam, const reference_request *req,
                     image *out, render_stats *stats, gt_error *e)
{
    memset(stats, 0, sizeof *stats);
    if (camera_validate(cam, scene_spec, e) != 0)
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
    if (rc == 0 && req->quantity == QUANTITY_AO) {
        ao_settings settings = {req->max_distance};
        integrator it = ao_integrator(&es, &settings);
        mc_film film;
        rc = render_estimates(&gb, &it, &req->sampling, &film, stats, e);
        if (rc == 0) {
            if (mc_film_write_channels(&film, image_channel_data(out, "mask.A"), out) != 0)
                rc = gt_error_set(e, scene_spec, "out of memory for the output image");
            mc_film_free(&film);
        }
    }
    if (rc == 0 && write_header(scene_spec, cam, req, out) != 0)
        rc = gt_error_set(e, scene_spec, "out of memory for the header");
    gbuffer_free(&gb);
    embree_scene_release(&es);
    if (rc != 0)
        image_free(out);
    return rc;
}
