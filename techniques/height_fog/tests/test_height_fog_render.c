/* `gtlab render fog` wired right (techniques/height_fog/height_fog_integrator.c): on a
 * built-in scene in dense fog, the Monte Carlo single scattering of every
 * sampled pixel agrees with the quadrature within 4 standard errors, the
 * transmittance channels agree between the modes and lie in (0, 1), the
 * multiple-scattering estimate is finite with a positive standard error,
 * and the output has the same bits for 1 and 2 threads. Background pixels
 * (the primary ray escapes) get the fog of the whole ray: the same
 * agreement of Monte Carlo and quadrature, and a transmittance equal to the
 * closed form of an infinite ray, exp(-beta_t H e^{-y0/H} / v_y) upwards
 * and 0 level or downwards (an infinite layer without a floor). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/optics/height_fog_medium.h"
#include "height_fog/height_fog_integrator.h"
#include "raytracer/reference_render.h"
#include "scene/builtin_scenes.h"
#include "tests/check.h"

static int render(const scene *s, const camera *cam, height_fog_scattering_mode mode, int threads, int spp, image *out)
{
    height_fog_settings fs = {.header = {&reference_quantity_fog}, .sun_elevation_deg = 20.0, .scattering = mode,
                       .max_scatterings = 1024};
    snprintf(fs.weather, sizeof fs.weather, "dense");
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = &reference_quantity_fog;
    req.sampling.spp = spp;
    req.sampling.seed = 3;
    req.sampling.threads = threads;
    req.settings = &fs.header;
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

/* The background pixels (primary ray escapes) of one camera: quadrature and
 * Monte Carlo single scattering agree within 4 standard errors, fog.T is the
 * infinite ray's closed form, and the multiple-scattering estimate (if
 * given) is finite with a positive standard error. Returns how many there
 * are, and in *rising how many rose (v_y > 0). */
static int check_background(const camera *cam, const image *quad, const image *single, const image *multi,
                            int *rising)
{
    height_fog_param p;
    double beta_t[3];
    height_fog_weather("dense", 20.0, &p);
    height_fog_extinction(&p, beta_t);
    camera_view view = camera_view_from(cam);
    const float *mask = image_channel_data(quad, "mask.A"), *lq = image_channel_data(quad, "fog.L.G");
    const float *tq = image_channel_data(quad, "fog.T.G"), *ls = image_channel_data(single, "fog.L.G");
    const float *ses = image_channel_data(single, "fog.L.G.stderr"), *ts = image_channel_data(single, "fog.T.G");
    int count = 0;
    *rising = 0;
    for (int i = 0; i < quad->width * quad->height; ++i) {
        if (mask[i] != 0.0f)
            continue;
        ++count;
        vec3 o, d;
        camera_ray(&view, (float)(i % quad->width) + 0.5f, (float)(i / quad->width) + 0.5f, &o, &d);
        double t = d.y > 0.0f ? exp(-beta_t[1] * p.scale_height * exp(-o.y / p.scale_height) / d.y) : 0.0;
        *rising += d.y > 0.0f;
        CHECK_MSG(fabs(tq[i] - t) <= 1e-5 * t && ts[i] == tq[i], "pixel %d: T %.8g, closed form %.8g", i, tq[i], t);
        CHECK_MSG(fabsf(ls[i] - lq[i]) <= 4.0f * ses[i] && ses[i] > 0.0f, "background %d (o %.9g %.9g %.9g d %.9g %.9g %.9g): %.6g +- %.2g vs %.6g", i, o.x, o.y, o.z, d.x, d.y, d.z,
                  ls[i], ses[i], lq[i]);
        if (multi)
            CHECK(isfinite(image_channel_data(multi, "fog.L.G")[i]) &&
                  image_channel_data(multi, "fog.L.G.stderr")[i] > 0.0f);
    }
    return count;
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
    if (render(&s, &cam, HEIGHT_FOG_QUADRATURE, 2, 1, &quad) || render(&s, &cam, HEIGHT_FOG_SINGLE, 2, 512, &single) ||
        render(&s, &cam, HEIGHT_FOG_MULTIPLE, 2, 512, &multi) || render(&s, &cam, HEIGHT_FOG_MULTIPLE, 1, 512, &multi1))
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
    int rising, background = check_background(&cam, &quad, &single, &multi, &rising);
    /* Looking up over the boxes: the top rows are sky (rays rising). */
    camera up = cam;
    up.target.y = up.position.y + 0.3f * (up.position.y - up.target.y);
    image up_quad, up_single;
    if (render(&s, &up, HEIGHT_FOG_QUADRATURE, 2, 1, &up_quad) || render(&s, &up, HEIGHT_FOG_SINGLE, 2, 256, &up_single))
        return 1;
    check_background(&up, &up_quad, &up_single, NULL, &rising);
    CHECK_MSG(background > 20 && rising > 20, "%d background pixels looking down, %d rising looking up", background,
              rising);
    image_free(&up_quad), image_free(&up_single);
    const char *channels[] = {"fog.L.R", "fog.L.G", "fog.L.B", "fog.L.B.stderr", "fog.T.R"};
    for (int k = 0; k < 5; ++k)
        CHECK(same_bits(&multi, &multi1, channels[k]));
    image_free(&quad), image_free(&single), image_free(&multi), image_free(&multi1);
    scene_free(&s);
    return check_report("test_height_fog_render");
}
