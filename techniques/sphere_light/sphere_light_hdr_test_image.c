/* The sphere-light HDR test image: see sphere_light_hdr_test_image.h. */
#include "sphere_light/sphere_light_hdr_test_image.h"

#include <string.h>

#include "sphere_light/sphere_light_quantity.h"
#include "scene/scene_loaders.h"

int hdr_test_image_sphere_light(const study_context *ctx, int width, int height, int spp, unsigned seed, image *out,
                                gt_error *e)
{
    scene s;
    camera cam = {v3(0.0f, 3.0f, 7.0f), v3(0.0f, 0.7f, 0.0f), v3(0.0f, 1.0f, 0.0f), (float)(40.0 * M_PI / 180.0),
                  width, height};
    if (scene_load("builtin:sphere-on-plane", &s, e) != 0)
        return -1;
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = QUANTITY_SPHERE_LIGHT;
    req.sampling = (sampling_settings){.spp = spp, .seed = seed, .threads = ctx->threads};
    req.normals = NORMAL_SHADING;
    sphere_light_quantity_settings light =
        sphere_light_quantity_settings_of((sphere_light_settings){v3(-2.5f, 4.0f, 1.5f), 0.5f, 5.0f, 0});
    req.settings = &light.header;
    render_stats stats;
    int rc = reference_render(&s, "builtin:sphere-on-plane", &cam, &req, out, &stats, e);
    scene_free(&s);
    return rc;
}
