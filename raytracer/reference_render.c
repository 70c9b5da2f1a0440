#include "raytracer/reference_render.h"

#include <inttypes.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/number_parse.h"
#include "core/progress.h"
#include "core/reference_schema.h"
#include "core/roughness_setting.h"
#include "raytracer/distributed_render.h"
#include "raytracer/render_checkpoint.h"
#include "scene/scene_hash.h"

int reference_set_attributef(image *img, const char *key, const char *fmt, ...)
{
    char text[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    return image_set_attribute(img, key, text);
}

int reference_parse_roughness(const char *value, float *roughness, gt_error *e)
{
    double r;
    if (parse_real_in("--roughness", value, 0.0, 1.0, &r, e) != 0)
        return -1;
    *roughness = (float)r;
    return 0;
}

int reference_write_roughness(image *out, float roughness, char *text, size_t size)
{
    snprintf(text, size, "material");
    if (roughness_is_material(roughness))
        return 0;
    snprintf(text, size, "%.9g", roughness);
    return schema_set_real(out, ATTR_ROUGHNESS, roughness);
}

/* A zeroed request (quantity NULL) renders the G-buffer. */
static reference_quantity quantity_of(const reference_request *req)
{
    return req->quantity ? req->quantity : QUANTITY_GBUFFER;
}

/* Version, quantity, scene (its spec and content hash), camera and normals; for a sampled quantity the
 * sampling (spp, seed, sample blocks) and the quantity's own settings. */
static int write_header(const scene *s, const char *scene_spec, const camera *cam, const reference_request *req,
                        image *img)
{
    reference_quantity q = quantity_of(req);
    char *camera_json = camera_to_json(cam), hash[SCENE_HASH_HEX];
    int rc = camera_json ? 0 : -1;
    rc |= scene_content_hash(s, hash);
    if (rc == 0)
        rc |= image_set_attribute(img, ATTR_SCENE_HASH, hash);
    rc |= image_set_attribute(img, ATTR_VERSION, GTLAB_VERSION);
    rc |= image_set_attribute(img, ATTR_QUANTITY, q->name);
    rc |= image_set_attribute(img, ATTR_SCENE, scene_spec);
    if (camera_json)
        rc |= image_set_attribute(img, ATTR_CAMERA, camera_json);
    free(camera_json);
    rc |= image_set_attribute(img, ATTR_NORMAL, req->normals == NORMAL_GEOMETRIC ? "geometric" : "shading");
    if (!q->prepare)
        return rc;
    const sampling_settings *ss = &req->sampling;
    rc |= reference_set_attributef(img, ATTR_SPP, "%d", ss->spp);
    rc |= reference_set_attributef(img, ATTR_SEED, "%" PRIu32, ss->seed);
    rc |= reference_set_attributef(img, ATTR_BLOCKS, "%" PRIu32 ":%" PRIu32 "+%d", ss->seed, ss->sample_offset,
                                   ss->spp);
    if (ss->target_stderr > 0.0)
        rc |= schema_set_real(img, ATTR_TARGET_STDERR, ss->target_stderr);
    if (ss->target_rel_stderr > 0.0)
        rc |= schema_set_real(img, ATTR_TARGET_REL_STDERR, ss->target_rel_stderr);
    if (q->write_settings)
        rc |= q->write_settings(req, img);
    return rc;
}

/* The render's header as text ("key=value" lines): what a checkpoint must
 * belong to. malloc'd, NULL when out of memory. */
static char *render_identity(const reference_pass *pass)
{
    image header;
    if (image_init(&header, 1, 1) != 0)
        return NULL;
    char *text = NULL;
    size_t size = 1;
    if (write_header(pass->scene, pass->scene_spec, pass->cam, pass->req, &header) == 0) {
        for (int a = 0; a < header.attribute_count; ++a)
            size += strlen(header.attributes[a].key) + strlen(header.attributes[a].value) + 2;
        text = calloc(size, 1);
    }
    for (int a = 0; text && a < header.attribute_count; ++a)
        strcat(strcat(strcat(strcat(text, header.attributes[a].key), "="), header.attributes[a].value), "\n");
    image_free(&header);
    return text;
}

/* With a checkpoint path (this process's; under mpirun each rank's own):
 * in blocks (of samples, or of rows when adaptive) that survive an
 * interruption (raytracer/render_checkpoint.h); else in one pass. */
static int render_samples(const reference_pass *pass, const integrator *it, mc_film *film, render_stats *stats,
                          gt_error *e)
{
    const reference_request *req = pass->req;
    const sampling_settings *ss = &req->sampling;
    if (!req->checkpoint)
        return render_estimates(pass->gb, it, ss, film, stats, e);
    char *identity = render_identity(pass);
    if (!identity)
        return gt_error_set(e, pass->scene_spec, "out of memory");
    render_checkpoint cp = {req->checkpoint, identity, req->resume};
    int rc = render_estimates_checkpointed(pass->gb, it, ss, &cp, film, stats, e);
    free(identity);
    return rc;
}

/* Samples the request's quantity at the G-buffer's surfaces into `out`:
 * the descriptor's integrator through the shared loop, then its derived
 * channels. */
static int render_quantity(const reference_pass *pass, image *out, render_stats *stats, gt_error *e)
{
    reference_quantity q = pass->req->quantity;
    void *state = NULL;
    integrator it;
    if (q->prepare(pass, &state, &it, e) != 0)
        return -1;
    mc_film film;
    int estimated = render_samples(pass, &it, &film, stats, e);
    if (q->release)
        q->release(state);
    if (estimated != 0)
        return -1;
    int rc = 0;
    if (mc_film_write_channels(&film, out) != 0 || (q->finish && q->finish(out) != 0))
        rc = gt_error_set(e, pass->scene_spec, "out of memory for the output image");
    mc_film_free(&film);
    return rc;
}

/* The scene's name on the progress bar: builtin:boxes as "boxes", a file
 * by its name. */
static const char *scene_short_name(const char *scene_spec)
{
    const char *slash = strrchr(scene_spec, '/');
    if (slash)
        return slash + 1;
    return strncmp(scene_spec, "builtin:", 8) == 0 ? scene_spec + 8 : scene_spec;
}

int reference_render(const scene *s, const char *scene_spec, const camera *cam, const reference_request *req,
                     image *out, render_stats *stats, gt_error *e)
{
    memset(stats, 0, sizeof *stats);
    progress_set_subject(scene_short_name(scene_spec));
    if (camera_validate(cam, scene_spec, e) != 0)
        return -1;
    if (image_init(out, cam->width, cam->height) != 0)
        return gt_error_set(e, scene_spec, "invalid image size");
    embree_scene es;
    if (embree_scene_build(s, &es, e) != 0) {
        image_free(out);
        return -1;
    }
    gbuffer gb;
    int rc = gbuffer_render(&es, cam, req->normals, req->sampling.threads, &gb, e);
    if (rc == 0 && gbuffer_write_channels(&gb, s, out) != 0)
        rc = gt_error_set(e, scene_spec, "out of memory for the G-buffer image");
    reference_pass pass = {s, scene_spec, cam, &es, &gb, req};
    if (rc == 0 && quantity_of(req)->prepare)
        rc = render_quantity(&pass, out, stats, e);
    if (rc == 0 && write_header(s, scene_spec, cam, req, out) != 0)
        rc = gt_error_set(e, scene_spec, "out of memory for the header");
    if (rc == 0 && quantity_of(req)->warn_about && distributed_is_writer())
        quantity_of(req)->warn_about(out, scene_spec, cam);
    gbuffer_free(&gb);
    embree_scene_release(&es);
    progress_set_subject(NULL);
    if (rc != 0)
        image_free(out);
    return rc;
}
