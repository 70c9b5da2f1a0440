/* `gtlab render fog` wired right (raytracer/fog_integrator.c): on a
 * built-in scene in dense fog, the Monte Carlo single scattering of every
 * sampled pixel agrees with the quadrature within 4 standard errors, the
 * transmittance channels agree between the modes and lie in (0, 1), the
 * multiple-scattering estimate is finite with a positive standard error,
 * and the output has the same bits for 1 and 2 threads. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "raytracer/fog_integrator.h"
#include "raytracer/reference_render.h"
#include "scene/builtin_scenes.h"
#include "tests/check.h"

static int render(const scene *s, const camera *cam, fog_scattering mode, int threads, int spp, image *out)
{
    fog_settings fs = {.sun_elevation_deg = 20.0, .scattering = mode, .max_scatterings = 1024};
    snprintf(fs.weather, sizeof fs.weather, "dense");
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = reference_quantity_find("fog");
    req.sampling.spp = spp;
    req.sampling.seed = 3;
    req.sampling.threads = threads;
    req.settings = &fs;
    render_stats stats;
    gt_error e;
    if (reference_render(s, "builtin:boxes", cam, &req, out, &stats, &e) != 0) {
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

int main(void)
{
    scene s;
    gt_error e;
    if (builtin_scene_build("boxes", &s, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return 1;
    }
    vec3 lo, hi;
    scene_bounds(&s, &lo, &hi);
    camera cam = camera_auto_framing(lo, hi, 24, 18);
    image quad, single, multi, multi1;
    if (render(&s, &cam, FOG_QUADRATURE, 2, 1, &quad) || render(&s, &cam, FOG_SINGLE, 2, 512, &single) ||
        render(&s, &cam, FOG_MULTIPLE, 2, 512, &multi) || render(&s, &cam, FOG_MULTIPLE, 1, 512, &multi1))
        return 1;
    const float *mask = image_channel_data(&quad, "mask.A"), *lq = image_channel_data(&quad, "fog.L.G");
    const float *ls = image_channel_data(&single, "fog.L.G"), *ses = image_channel_data(&single, "fog.L.G.stderr");
    const float *lm = image_channel_data(&multi, "fog.L.G"), *sem = image_channel_data(&multi, "fog.L.G.stderr");
    const float *tq = image_channel_data(&quad, "fog.T.G"), *tm = image_channel_data(&multi, "fog.T.G");
    int compared = 0;
    for (int i = 0; i < quad.width * quad.height; ++i) {
        if (mask[i] == 0.0f)
            continue;
        ++compared;
        CHECK_MSG(fabsf(ls[i] - lq[i]) <= 4.0f * ses[i] && ses[i] > 0.0f, "pixel %d: %.6g +- %.2g vs %.6g", i, ls[i],
                  ses[i], lq[i]);
        CHECK(tq[i] == tm[i] && tq[i] > 0.0f && tq[i] < 1.0f);
        CHECK(isfinite(lm[i]) && sem[i] > 0.0f && isfinite(sem[i]));
    }
    CHECK_MSG(compared > 40, "%d pixels", compared);
    const char *channels[] = {"fog.L.R", "fog.L.G", "fog.L.B", "fog.L.B.stderr", "fog.T.R"};
    for (int k = 0; k < 5; ++k)
        CHECK(same_bits(&multi, &multi1, channels[k]));
    image_free(&quad), image_free(&single), image_free(&multi), image_free(&multi1);
    scene_free(&s);
    return check_report("test_fog_render");
}
