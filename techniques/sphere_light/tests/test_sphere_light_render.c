/* The sphere-light scene render (techniques/sphere_light/sphere_light_integrator.c) is
 * wired right: on a white metal plane (F0 = 1, so Fresnel is 1 and the
 * diffuse lobe 0) every pixel equals L_e times the parameter-space GGX
 * reference of the same surface point, view and light (independent seeds),
 * within 4 combined standard errors; the output does not depend on the
 * thread count. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/frame.h"
#include "sphere_light/sphere_light_quantity.h"
#include "sphere_light/sphere_light_reference.h"
#include "scene/builtin_scenes.h"
#include "tests/check.h"

static int render(const scene *s, const camera *cam, int threads, image *out)
{
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = QUANTITY_SPHERE_LIGHT;
    req.sampling.spp = 256;
    req.sampling.seed = 7;
    req.sampling.threads = threads;
    req.normals = NORMAL_SHADING;
    sphere_light_quantity_settings light =
        sphere_light_quantity_settings_of((sphere_light_settings){v3(0.0f, 1.5f, -6.0f), 0.8f, 3.0f, 0});
    req.settings = &light.header;
    render_stats stats;
    gt_error e;
    if (reference_render(s, "builtin:plane", cam, &req, out, &stats, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return -1;
    }
    return 0;
}

int main(void)
{
    scene s;
    gt_error e;
    if (builtin_scene_build("plane", &s, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return 1;
    }
    for (int m = 0; m < s.material_count; ++m) {
        s.materials[m].metallic = 1.0f, s.materials[m].roughness = 0.45f;
        for (int c = 0; c < 3; ++c)
            s.materials[m].base_color[c] = 1.0f;
    }
    /* Grazing view towards the light. */
    camera cam = {v3(0.0f, 0.6f, 4.0f), v3(0.0f, 0.0f, -2.0f), v3(0.0f, 1.0f, 0.0f), (float)(40.0 * M_PI / 180.0),
                  24, 16};
    image a, b;
    if (render(&s, &cam, 2, &a) != 0 || render(&s, &cam, 1, &b) != 0)
        return 1;
    const float *mean = image_channel_data(&a, "sphere.G"), *se = image_channel_data(&a, "sphere.G.stderr");
    const float *mask = image_channel_data(&a, "mask.A");
    int compared = 0, bright = 0;
    for (int y = 0; y < a.height; y += 3) {
        for (int x = 0; x < a.width; x += 3) {
            int i = y * a.width + x;
            if (mask[i] == 0.0f)
                continue;
            vec3 p = v3(image_channel_data(&a, "P.X")[i], image_channel_data(&a, "P.Y")[i],
                        image_channel_data(&a, "P.Z")[i]);
            vec3 n = v3(image_channel_data(&a, "N.X")[i], image_channel_data(&a, "N.Y")[i],
                        image_channel_data(&a, "N.Z")[i]);
            frame f = frame_from_normal(v3_normalize(n));
            vec3 to_light = v3_sub(v3(0.0f, 1.5f, -6.0f), p);
            float d = v3_length(to_light);
            sphere_light_config c;
            c.v = frame_to_local(&f, v3_normalize(v3_sub(cam.position, p)));
            c.lc = frame_to_local(&f, v3_scale(to_light, 1.0f / d));
            c.sin_sigma = 0.8 / d;
            c.alpha = 0.45 * 0.45;
            sphere_light_estimate est;
            sphere_light_reference(&c, 4096, 1000u + (uint32_t)i, &est);
            double want = 3.0 * est.spec, want_se = 3.0 * est.spec_stderr;
            double tol = 4.0 * sqrt(se[i] * se[i] + want_se * want_se) + 1e-6 * want;
            CHECK_MSG(fabs(mean[i] - want) <= tol, "pixel (%d, %d): render %.6g +- %.2g, reference %.6g +- %.2g", x,
                      y, mean[i], se[i], want, want_se);
            bright += want > 0.05;
            ++compared;
        }
    }
    printf("compared %d pixels (%d bright)\n", compared, bright);
    CHECK(compared > 10 && bright > 3);
    const float *mb = image_channel_data(&b, "sphere.G");
    CHECK(memcmp(mean, mb, sizeof(float) * (size_t)a.width * a.height) == 0);
    image_free(&a);
    image_free(&b);
    scene_free(&s);
    return check_report("test_sphere_light_render");
}
