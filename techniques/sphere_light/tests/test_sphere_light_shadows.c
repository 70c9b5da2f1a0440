/* `gtlab render sphere-light --shadows` (techniques/sphere_light/sphere_light_integrator.c)
 * against geometry whose shadow is known exactly:
 *  - on the open plane nothing blocks the light: shadowed and unshadowed
 *    renders are bit-identical;
 *  - under the sphere of sphere-on-plane, floor points whose whole light cap
 *    lies inside the sphere's cone (umbra) get exactly 0 while the
 *    unshadowed render is positive; floor points whose cap is wholly outside
 *    that cone are bit-identical to the unshadowed render;
 *  - every pixel: shadowed <= unshadowed (visibility only removes light);
 *  - the thread count does not change the shadowed render. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sphere_light/sphere_light_quantity.h"
#include "scene/builtin_scenes.h"
#include "tests/check.h"

static const vec3 light_position = {0.0f, 6.0f, 0.0f};
static const float light_radius = 0.3f;

static int render(const char *name, const camera *cam, int shadows, int threads, image *out)
{
    scene s;
    gt_error e;
    if (builtin_scene_build(name, &s, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return -1;
    }
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = QUANTITY_SPHERE_LIGHT;
    req.sampling = (sampling_settings){.spp = 64, .seed = 3, .threads = threads};
    req.normals = NORMAL_SHADING;
    sphere_light_quantity_settings light =
        sphere_light_quantity_settings_of((sphere_light_settings){light_position, light_radius, 2.0f, shadows});
    req.settings = &light.header;
    render_stats stats;
    char spec[64];
    snprintf(spec, sizeof spec, "builtin:%s", name);
    int rc = reference_render(&s, spec, cam, &req, out, &stats, &e);
    if (rc != 0)
        fprintf(stderr, "%s\n", e.message);
    scene_free(&s);
    return rc;
}

static size_t plane_size(const image *a) { return sizeof(float) * image_pixel_count(a); }

static double angle_between(vec3 a, vec3 b)
{
    return acos(fmax(-1.0, fmin(1.0, v3_dot(v3_normalize(a), v3_normalize(b)))));
}

static void open_plane_is_unchanged(void)
{
    camera cam = {v3(0.0f, 2.0f, 6.0f), v3(0.0f, 0.0f, 0.0f), v3(0.0f, 1.0f, 0.0f), (float)(40.0 * M_PI / 180.0), 32, 24};
    image lit, shadowed;
    if (render("plane", &cam, 0, 2, &lit) != 0 || render("plane", &cam, 1, 2, &shadowed) != 0) {
        CHECK(0);
        return;
    }
    static const char *const channels[3] = {"sphere.R", "sphere.G", "sphere.B"};
    for (int c = 0; c < 3; ++c)
        CHECK_MSG(memcmp(image_channel_data(&lit, channels[c]), image_channel_data(&shadowed, channels[c]),
                         plane_size(&lit)) == 0,
                  "plane: %s differs with --shadows", channels[c]);
    image_free(&lit);
    image_free(&shadowed);
}

static void sphere_casts_its_umbra(void)
{
    camera cam = {v3(0.0f, 4.0f, 6.0f), v3(0.0f, 0.0f, 0.5f), v3(0.0f, 1.0f, 0.0f), (float)(40.0 * M_PI / 180.0), 48, 32};
    image lit, shadowed, one_thread;
    if (render("sphere-on-plane", &cam, 0, 2, &lit) != 0 || render("sphere-on-plane", &cam, 1, 2, &shadowed) != 0 ||
        render("sphere-on-plane", &cam, 1, 1, &one_thread) != 0) {
        CHECK(0);
        return;
    }
    const float *a = image_channel_data(&lit, "sphere.G"), *b = image_channel_data(&shadowed, "sphere.G");
    const float *mask = image_channel_data(&lit, "mask.A");
    const float *px = image_channel_data(&lit, "P.X"), *py = image_channel_data(&lit, "P.Y"),
                *pz = image_channel_data(&lit, "P.Z");
    const vec3 sphere_centre = v3(0.0f, 1.5f, 0.0f);
    const double margin = 0.02; /* radians: the tessellated sphere's silhouette */
    int umbra = 0, clear = 0;
    for (size_t i = 0; i < image_pixel_count(&lit); ++i) {
        if (mask[i] == 0.0f)
            continue;
        CHECK_MSG(b[i] <= a[i], "pixel %zu: shadowed %.6g > unshadowed %.6g", i, b[i], a[i]);
        vec3 p = v3(px[i], py[i], pz[i]);
        if (fabsf(p.y) > 1e-4f)
            continue; /* the sphere itself */
        vec3 to_light = v3_sub(light_position, p), to_sphere = v3_sub(sphere_centre, p);
        double light_cap = asin(light_radius / v3_length(to_light)), sphere_cone = asin(1.0 / v3_length(to_sphere));
        double apart = angle_between(to_light, to_sphere);
        if (apart + light_cap < sphere_cone - margin) {
            CHECK_MSG(b[i] == 0.0f && a[i] > 0.0f, "umbra pixel %zu: shadowed %.6g, unshadowed %.6g", i, b[i], a[i]);
            ++umbra;
        } else if (apart > sphere_cone + light_cap + margin) {
            CHECK_MSG(b[i] == a[i], "clear pixel %zu: shadowed %.9g, unshadowed %.9g", i, b[i], a[i]);
            ++clear;
        }
    }
    printf("umbra %d pixels, clear %d pixels\n", umbra, clear);
    CHECK(umbra >= 5 && clear >= 5);
    CHECK(memcmp(b, image_channel_data(&one_thread, "sphere.G"), plane_size(&lit)) == 0);
    CHECK(strstr(image_get_attribute(&shadowed, "gtlab.settings"), "shadows=traced") != NULL);
    image_free(&lit);
    image_free(&shadowed);
    image_free(&one_thread);
}

int main(void)
{
    open_plane_is_unchanged();
    sphere_casts_its_umbra();
    return check_report("test_sphere_light_shadows");
}
