/* `gtlab render volumetric-light` wired right (raytracer/
 * volumetric_light_integrator.c) on builtin:cornell with the default spot,
 * whose light the blocks shadow:
 *  - Monte Carlo (equiangular, shadow rays) agrees with the quadrature in
 *    every sampled pixel within 4 standard errors plus the quadrature's
 *    error estimate, and the scene's shadows change the image (in over 2%
 *    of the pixels, by over 2%);
 *  - a point light inside the closed tall block gives exactly 0 everywhere
 *    (both methods), while the same light unshadowed does not;
 *  - the output has the same bits for 1 and 2 threads. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "raytracer/reference_render.h"
#include "volumetric_light/volumetric_light_integrator.h"
#include "scene/builtin_scenes.h"
#include "tests/check.h"

static int render(const scene *s, const camera *cam, const volumetric_light_settings *vs, int threads, int spp,
                  image *out)
{
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = &reference_quantity_volumetric_light;
    req.sampling.spp = spp;
    req.sampling.seed = 5;
    req.sampling.threads = threads;
    volumetric_light_settings settings = *vs;
    settings.header.quantity = req.quantity;
    req.settings = &settings.header;
    render_stats stats;
    gt_error e;
    if (reference_render(s, "builtin:cornell", cam, &req, out, &stats, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return -1;
    }
    return 0;
}

static int same_bits(const image *a, const image *b, const char *channel)
{
    const float *x = image_channel_data(a, channel), *y = image_channel_data(b, channel);
    return x && y && memcmp(x, y, sizeof(float) * (size_t)a->width * (size_t)a->height) == 0;
}

static void check_against_monte_carlo(const scene *s, const camera *cam)
{
    volumetric_light_settings quad, mc, open;
    volumetric_light_settings_default(&quad);
    mc = quad, open = quad;
    mc.method = VLIGHT_MONTE_CARLO;
    open.no_shadows = 1;
    image iq, im, im1, io;
    if (render(s, cam, &quad, 2, 1, &iq) || render(s, cam, &mc, 2, 256, &im) || render(s, cam, &mc, 1, 256, &im1) ||
        render(s, cam, &open, 2, 1, &io)) {
        CHECK(0);
        return;
    }
    const float *mask = image_channel_data(&iq, "mask.A"), *lq = image_channel_data(&iq, "vlight.L.G");
    const float *eq = image_channel_data(&iq, "vlight_quadrature_error.G"), *lo = image_channel_data(&io, "vlight.L.G");
    const float *lm = image_channel_data(&im, "vlight.L.G"), *sm = image_channel_data(&im, "vlight.L.G.stderr");
    int compared = 0, lit = 0, shadowed = 0, worst = -1;
    double worst_z = 0.0;
    for (int i = 0; i < iq.width * iq.height; ++i) {
        if (mask[i] == 0.0f)
            continue;
        ++compared;
        lit += lq[i] > 0.0f;
        shadowed += lo[i] > 1.02f * lq[i] + 1e-6f;
        double z = fabs(lm[i] - lq[i]) / (4.0 * sm[i] + eq[i] + 1e-7 * lq[i] + 1e-30);
        if (z > worst_z)
            worst_z = z, worst = i;
    }
    CHECK_MSG(worst_z <= 1.0, "pixel %d: MC %.6g +- %.2g vs quadrature %.6g +- %.2g", worst, lm[worst], sm[worst],
              lq[worst], eq[worst]);
    CHECK_MSG(compared > 500 && lit > compared / 2 && shadowed > compared / 50, "%d pixels, %d lit, %d shadowed",
              compared, lit, shadowed);
    const char *channels[] = {"vlight.L.R", "vlight.L.G", "vlight.L.B", "vlight.L.G.stderr"};
    for (int k = 0; k < 4; ++k)
        CHECK(same_bits(&im, &im1, channels[k]));
    image_free(&iq), image_free(&im), image_free(&im1), image_free(&io);
}

/* A point light inside the tall block (closed by its walls and the floor). */
static void check_fully_shadowed(const scene *s, const camera *cam)
{
    volumetric_light_settings vs;
    volumetric_light_settings_default(&vs);
    vs.kind = VOLUMETRIC_POINT_LIGHT;
    vs.has_placement = 1;
    vs.position = v3(-0.9f, 1.5f, -0.7f);
    vs.target = v3(0.0f, 0.0f, 0.0f);
    vs.intensity = 50.0;
    vs.sigma_t = 0.2;
    image iq, im, io;
    volumetric_light_settings mc = vs, open = vs;
    mc.method = VLIGHT_MONTE_CARLO;
    open.no_shadows = 1;
    if (render(s, cam, &vs, 2, 1, &iq) || render(s, cam, &mc, 2, 64, &im) || render(s, cam, &open, 2, 1, &io)) {
        CHECK(0);
        return;
    }
    const float *lq = image_channel_data(&iq, "vlight.L.R"), *lm = image_channel_data(&im, "vlight.L.R");
    const float *lo = image_channel_data(&io, "vlight.L.R"), *mask = image_channel_data(&iq, "mask.A");
    int nonzero = 0, open_lit = 0;
    for (int i = 0; i < iq.width * iq.height; ++i) {
        nonzero += lq[i] != 0.0f || lm[i] != 0.0f;
        open_lit += mask[i] != 0.0f && lo[i] > 0.0f;
    }
    CHECK_MSG(nonzero == 0, "%d pixels see a light enclosed in the block", nonzero);
    CHECK_MSG(open_lit > iq.width * iq.height / 2, "%d pixels lit without shadows", open_lit);
    image_free(&iq), image_free(&im), image_free(&io);
}

int main(void)
{
    scene s;
    gt_error e;
    if (builtin_scene_build("cornell", &s, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return 1;
    }
    camera cam = s.camera;
    cam.width = 40, cam.height = 40;
    check_against_monte_carlo(&s, &cam);
    check_fully_shadowed(&s, &cam);
    scene_free(&s);
    return check_report("test_volumetric_light_render");
}
