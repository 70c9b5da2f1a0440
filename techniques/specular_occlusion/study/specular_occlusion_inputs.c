#include "specular_occlusion/specular_occlusion_inputs.h"

#include <stdio.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "scene/camera.h"

static const float *channel(const image *img, const char *what, const char *name, gt_error *e)
{
    const float *data = image_channel_data(img, name);
    if (!data)
        gt_error_set(e, what, "no channel %s", name);
    return data;
}

double so_reference_roughness(const image *reference)
{
    double value;
    return schema_get_real(reference, ATTR_ROUGHNESS, NULL, &value, NULL) == 1 ? value : -1.0;
}

/* The G-buffer's channels into b; -1 with e when one is missing. */
static int gbuffer_channels(const image *gbuffer, const char *what, so_screen_buffers *b, gt_error *e)
{
    static const char *const names[8] = {CH_N_X, CH_N_Y, CH_N_Z, CH_P_X, CH_P_Y, CH_P_Z, CH_MASK, CH_ROUGHNESS};
    const float **slots[8] = {&b->normal[0], &b->normal[1], &b->normal[2], &b->position[0],
                              &b->position[1], &b->position[2], &b->mask, &b->roughness};
    for (int i = 0; i < 8; ++i)
        if (!(*slots[i] = channel(gbuffer, what, names[i], e)))
            return -1;
    b->width = gbuffer->width, b->height = gbuffer->height;
    return 0;
}

/* The AO image's channels into b (ao.Vuniform optional: GTAO's output has one weighting). */
static int ao_channels(const image *ao, const char *what, so_screen_buffers *b, gt_error *e)
{
    static const char *const names[4] = {CH_AO, CH_BENT_X, CH_BENT_Y, CH_BENT_Z};
    const float **slots[4] = {&b->ao_cosine, &b->bent[0], &b->bent[1], &b->bent[2]};
    for (int i = 0; i < 4; ++i)
        if (!(*slots[i] = channel(ao, what, names[i], e)))
            return -1;
    b->ao_uniform = image_channel_data(ao, CH_AO_UNIFORM);
    return 0;
}

int so_buffers_from_images(const image *gbuffer, const char *what_gbuffer, const image *ao, const char *what_ao,
                           so_screen_buffers *b, vec3 *eye, gt_error *e)
{
    if (gbuffer_channels(gbuffer, what_gbuffer, b, e) != 0 || ao_channels(ao, what_ao, b, e) != 0)
        return -1;
    if (ao->width != gbuffer->width || ao->height != gbuffer->height)
        return gt_error_set(e, what_ao, "size %dx%d differs from the G-buffer's %dx%d", ao->width, ao->height,
                            gbuffer->width, gbuffer->height);
    const char *camera_json = image_get_attribute(gbuffer, ATTR_CAMERA);
    camera cam;
    if (!camera_json)
        return gt_error_set(e, what_gbuffer, "no gtlab.camera header attribute (not a gtlab G-buffer?)");
    if (camera_parse_json(camera_json, what_gbuffer, &cam, e) != 0)
        return -1;
    *eye = cam.position;
    return 0;
}

int so_inputs_from_images(const image *gbuffer, const char *what_gbuffer, const image *ao, const char *what_ao,
                          double roughness, so_pixel_inputs *in, gt_error *e)
{
    so_screen_buffers b;
    vec3 eye;
    if (so_buffers_from_images(gbuffer, what_gbuffer, ao, what_ao, &b, &eye, e) != 0)
        return -1;
    if (so_inputs_compute(&b, eye, roughness, in) != 0)
        return gt_error_set(e, what_gbuffer, "out of memory");
    return 0;
}

int aperture_case_from_images(aperture_case *c, const image *reference, const char *what_reference, const image *ao,
                              const char *what_ao, const char *channel, gt_error *e)
{
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", what_reference);
    if (!(c->reference = image_channel_data(reference, channel)))
        return gt_error_set(e, what_reference, "no channel %s (not a specular-occlusion reference?)", channel);
    return so_inputs_from_images(reference, what_reference, ao, what_ao, so_reference_roughness(reference),
                                 &c->inputs, e);
}

int aperture_cases_load(const char *const *references, const char *const *ao_paths, int count, const char *channel,
                        image *refs, image *aos, aperture_case *cases, int *loaded, gt_error *e)
{
    for (int i = 0; i < count; ++i) {
        if (exr_read(references[i], &refs[i], e) != 0)
            return -1;
        if (exr_read(ao_paths[i], &aos[i], e) != 0) {
            image_free(&refs[i]);
            return -1;
        }
        *loaded = i + 1;
        if (aperture_case_from_images(&cases[i], &refs[i], references[i], &aos[i], ao_paths[i], channel, e) != 0)
            return -1;
    }
    return 0;
}

void aperture_cases_free(image *refs, image *aos, aperture_case *cases, int loaded)
{
    for (int i = 0; i < loaded; ++i) {
        aperture_case_free(&cases[i]);
        image_free(&refs[i]);
        image_free(&aos[i]);
    }
}
