/* The AO reference's distance fade (techniques/ao/ao_integrator.h, issue 25,
 * item 12) against a closed form: a floor point at distance d from one wall
 * of the closed box [-1, 1]^3, with every other surface farther than the
 * fade's end, sees
 *     V = 1 - (1/pi) integral over directions towards the wall of
 *         w(d / (sin theta cos phi)) cos theta dw,
 *     w(t) = clamp((D - t) / (D - F), 0, 1),
 * integrated here by the midpoint rule in (theta, phi) in double. The
 * render's estimate must lie within 4 of its standard errors, with the fade
 * and with a hard cutoff at D (fade start 0), and fade start 0 must give
 * bit-identical output to the hard cutoff the renderer had before. */
#include <math.h>

#include "ao/ao_quantity.h"
#include "tests/check.h"
#include "tests/raytracer/closed_box.h"

#define PI 3.14159265358979323846

static double fade_weight(double t, double start, double end)
{
    if (start <= 0.0)
        return t < end ? 1.0 : 0.0;
    return fmin(fmax((end - t) / (end - start), 0.0), 1.0);
}

static double closed_form(double d, double start, double end)
{
    enum { N = 1200 };
    double occluded = 0.0;
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
            double th = 0.5 * PI * (i + 0.5) / N, ph = PI * ((j + 0.5) / N - 0.5); /* cos phi > 0 */
            double toward = sin(th) * cos(ph);
            occluded += fade_weight(d / toward, start, end) * cos(th) * sin(th) * (0.5 * PI / N) * (PI / N);
        }
    return 1.0 - occluded / PI;
}

static image render(const scene *s, float start, float end)
{
    camera cam = {v3(0.5f, 0.5f, 0.0f), v3(0.9f, -1.0f, 0.0f), v3(0.0f, 1.0f, 0.0f), 0.3f, 9, 9};
    ao_render_settings ao = {{QUANTITY_AO}, .max_distance = end, .fade_start = start};
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = 16384, .seed = 3, .threads = 2},
                             .normals = NORMAL_SHADING, .settings = &ao.header};
    gt_error e;
    image img = {0};
    render_stats stats;
    if (reference_render(s, s->name, &cam, &req, &img, &stats, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        CHECK(0);
    }
    return img;
}

static void check_centre(const scene *s, float start, float end)
{
    image img = render(s, start, end);
    const float *v = image_channel_data(&img, "ao.V"), *se = image_channel_data(&img, "ao.V.stderr"),
                *px = image_channel_data(&img, "P.X");
    int c = 4 * 9 + 4;
    if (!v || !se || !px) {
        CHECK(0);
        return;
    }
    double expected = closed_form(1.0 - px[c], start, end);
    CHECK_NEAR(px[c], 0.9, 1e-3);
    CHECK_MSG(fabs(v[c] - expected) < 4.0 * se[c] + 1e-4, "fade %g..%g: V %.5f +- %.5f, closed form %.5f", start,
              end, v[c], se[c], expected);
    CHECK(expected < 0.99 && expected > 0.5); /* the wall matters */
    image_free(&img);
}

static void test_fade_start_zero_is_the_hard_cutoff(const scene *s)
{
    camera cam = {v3(0.5f, 0.5f, 0.0f), v3(0.9f, -1.0f, 0.0f), v3(0.0f, 1.0f, 0.0f), 0.6f, 8, 8};
    ao_render_settings ao = {{QUANTITY_AO}, .max_distance = 0.3f};
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = 64, .seed = 3, .threads = 2},
                             .normals = NORMAL_SHADING, .settings = &ao.header};
    gt_error e;
    image a = {0}, b = {0};
    render_stats stats;
    CHECK(reference_render(s, s->name, &cam, &req, &a, &stats, &e) == 0);
    ao.fade_start = 0.3f; /* at or beyond the end: no fade */
    CHECK(reference_render(s, s->name, &cam, &req, &b, &stats, &e) == 0);
    const float *va = image_channel_data(&a, "ao.V"), *vb = image_channel_data(&b, "ao.V");
    int same = va && vb;
    for (int i = 0; same && i < 64; ++i)
        same = va[i] == vb[i];
    CHECK(same);
    image_free(&a);
    image_free(&b);
}

int main(void)
{
    scene s = {.name = "test:closed-box"};
    CHECK(add_closed_box(&s) == 0);
    check_centre(&s, 0.15f, 0.3f);
    check_centre(&s, 0.0f, 0.3f);
    test_fade_start_zero_is_the_hard_cutoff(&s);
    scene_free(&s);
    return check_report("test_ao_fade");
}
