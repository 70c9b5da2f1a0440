/* The height-field AO reference with a finite thickness T
 * (techniques/ao/heightfield_ao_integrator.h, `render heightfield-ao
 * --thickness T`):
 *  - closed form: a floor seen from above with a raised band (its top face
 *    at height 1); a ray from the floor towards the band passes under the
 *    band's slab (heights 1 - T to 1) iff it stays below 1 - T across it,
 *    and a ray that rises through the top face is blocked for any T, even
 *    when it crosses the slab within one pixel;
 *  - the option absent and T = INFINITY give today's reference bit for bit;
 *  - with the same seed, AO is non-increasing in T at every pixel (the
 *    slabs are nested), and T = 1e30 matches the infinite height field;
 *  - heightfield_first_hit (the multi-bounce reference's hits) on the band:
 *    the side of its column, its top face, nothing above it. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/reference_schema.h"
#include "ao/heightfield_ao_integrator.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

enum { SIZE = 64 };
static const float band_lo = 1.0f, band_hi = 3.0f; /* the band's x extent; its top face at y = 1 */

/* Camera at height 10 looking straight down; each pixel sees the band's top
 * (y = 1) where that point's x lies in the band, else the floor (y = 0). */
static void band_gbuffer(gbuffer *gb, surface_hit *hits, unsigned char *mask)
{
    camera cam = {{0, 10, 0}, {0, 0, 0}, {0, 0, -1}, 40.0f * 3.14159265f / 180.0f, SIZE, SIZE};
    gb->width = gb->height = SIZE;
    gb->hits = hits;
    gb->mask = mask;
    gb->view = camera_view_from(&cam);
    for (int j = 0; j < SIZE; ++j)
        for (int i = 0; i < SIZE; ++i) {
            vec3 o, d;
            camera_ray(&gb->view, (float)i + 0.5f, (float)j + 0.5f, &o, &d);
            float t = (1.0f - o.y) / d.y;
            vec3 top = v3_add(o, v3_scale(d, t));
            if (!(top.x >= band_lo && top.x <= band_hi))
                t = -o.y / d.y;
            surface_hit *h = &hits[j * SIZE + i];
            memset(h, 0, sizeof *h);
            h->p = v3_add(o, v3_scale(d, t));
            h->ng = h->ns = v3(0, 1, 0);
            h->t = t;
            mask[j * SIZE + i] = 1;
        }
}

static int unoccluded(heightfield_settings *hs, vec3 p, float elevation, float thickness)
{
    hs->thickness = thickness;
    return heightfield_unoccluded(hs, p, v3_normalize(v3(1.0f, elevation, 0.0f)));
}

static void test_band_closed_form(void)
{
    static surface_hit hits[SIZE * SIZE];
    static unsigned char mask[SIZE * SIZE];
    gbuffer gb;
    band_gbuffer(&gb, hits, mask);
    heightfield_settings hs;
    CHECK(heightfield_settings_init(&hs, &gb, INFINITY) == 0);
    CHECK(isinf(hs.thickness));
    vec3 p = hits[(SIZE / 2) * SIZE + SIZE / 2].p; /* a floor point near x = 0 */
    CHECK(p.y == 0.0f && p.x < band_lo);
    /* Elevation e: across the band the ray's height runs from e (1 - p.x) to
     * e (3 - p.x) (pixel edges move the band by < 0.12 in x). */
    CHECK(unoccluded(&hs, p, 0.2f, 0.3f));      /* heights 0.19..0.59 under the slab 0.7..1 */
    CHECK(!unoccluded(&hs, p, 0.2f, 0.5f));     /* enters the slab 0.5..1 */
    CHECK(!unoccluded(&hs, p, 0.2f, INFINITY)); /* solid behind */
    CHECK(unoccluded(&hs, p, 0.05f, 0.8f));     /* heights 0.05..0.15 under 0.2..1 */
    CHECK(!unoccluded(&hs, p, 0.05f, 0.9f));    /* enters 0.1..1 */
    CHECK(!unoccluded(&hs, p, 0.5f, 0.01f));    /* rises through the top face at x ~ 2.06: a 0.01 slab */
    CHECK(!unoccluded(&hs, p, 0.5f, INFINITY));
    CHECK(unoccluded(&hs, p, 1.5f, 0.01f));     /* passes above the band */
    CHECK(unoccluded(&hs, p, 1.5f, INFINITY));
    heightfield_settings_free(&hs);
}

/* heightfield_first_hit on the band (infinite thickness): a low ray from the
 * floor meets the side of the band's column at x ~ 1 (the plane through the
 * eye and a pixel edge, nearly vertical here), facing -x, even a steep one
 * (the solid is infinitely deep); one from above meets the top face y = 1
 * where the line does, normal +y; one passing above the band meets nothing. */
static void test_band_first_hit(void)
{
    static surface_hit hits[SIZE * SIZE];
    static unsigned char mask[SIZE * SIZE];
    gbuffer gb;
    band_gbuffer(&gb, hits, mask);
    heightfield_settings hs;
    CHECK(heightfield_settings_init(&hs, &gb, INFINITY) == 0);
    vec3 p = hits[(SIZE / 2) * SIZE + SIZE / 2].p, d = v3_normalize(v3(1.0f, 0.2f, 0.0f)), h = {0};
    surface_hit hit;
    CHECK(heightfield_first_hit(&hs, p, d, &hit));
    h = hit.p;
    CHECK_MSG(fabsf(h.x - band_lo) < 0.12f && fabsf(h.y - 0.2f * (h.x - p.x)) < 1e-3f && hit.ng.x < -0.95f,
              "side: (%g %g %g), normal (%g %g %g)", h.x, h.y, h.z, hit.ng.x, hit.ng.y, hit.ng.z);
    CHECK(fabsf(hit.t - v3_length(v3_sub(h, p))) < 1e-5f);
    CHECK(heightfield_first_hit(&hs, p, v3_normalize(v3(1.0f, 0.5f, 0.0f)), &hit) && hit.ng.x < -0.95f);
    /* from a point above the floor, down onto the top face at x = 1.5 */
    CHECK(heightfield_first_hit(&hs, v3(0.5f, 2.0f, 0.0f), v3_normalize(v3(1.0f, -1.0f, 0.0f)), &hit));
    CHECK_MSG(fabsf(hit.p.y - 1.0f) < 1e-4f && fabsf(hit.p.x - 1.5f) < 1e-3f && hit.ng.y == 1.0f,
              "top: (%g %g %g)", hit.p.x, hit.p.y, hit.p.z);
    CHECK(!heightfield_first_hit(&hs, p, v3_normalize(v3(1.0f, 1.5f, 0.0f)), &hit));
    heightfield_settings_free(&hs);
}

/* heightfield-ao on the boxes seen from above; thickness < 0: the option absent. */
static int render_hf(const scene *s, const camera *cam, float thickness, image *out)
{
    heightfield_ao_options o = heightfield_ao_thickness(thickness);
    reference_request req = {.quantity = QUANTITY_HEIGHTFIELD_AO,
                             .sampling = {.spp = 32, .seed = 3, .threads = 2},
                             .normals = NORMAL_SHADING, .settings = thickness < 0.0f ? NULL : &o.header};
    render_stats stats;
    gt_error e;
    int rc = reference_render(s, "builtin:boxes", cam, &req, out, &stats, &e);
    if (rc != 0)
        fprintf(stderr, "%s\n", e.message);
    return rc;
}

static void test_boxes(void)
{
    static const float thickness[] = {-1.0f, INFINITY, 1e30f, 4.0f, 1.0f, 0.25f};
    enum { RUNS = sizeof thickness / sizeof thickness[0] };
    scene s;
    camera cam;
    gt_error e;
    CHECK(scene_load("builtin:boxes", &s, &e) == 0);
    CHECK(camera_parse_json("{\"position\":[0,26,0],\"target\":[0,0,0],\"up\":[0,0,-1],\"yfov_deg\":40,"
                            "\"width\":40,\"height\":40}", "camera", &cam, &e) == 0);
    image img[RUNS];
    const float *v[RUNS];
    for (int r = 0; r < RUNS; ++r) {
        CHECK(render_hf(&s, &cam, thickness[r], &img[r]) == 0);
        v[r] = image_channel_data(&img[r], CH_AO);
    }
    size_t n = image_pixel_count(&img[0]);
    CHECK(memcmp(v[0], v[1], n * sizeof(float)) == 0);
    long same_far = 0, rising = 0;
    double mean[RUNS] = {0};
    for (size_t i = 0; i < n; ++i) {
        same_far += v[2][i] == v[1][i];
        for (int r = 3; r < RUNS; ++r)
            rising += v[r][i] < v[r - 1][i]; /* thinner must not be darker */
        for (int r = 0; r < RUNS; ++r)
            mean[r] += v[r][i] / (double)n;
    }
    printf("boxes: T = 1e30 equals the infinite field at %ld of %zu pixels; mean V: inf %.4f, 4 %.4f, 1 %.4f, "
           "0.25 %.4f\n", same_far, n, mean[1], mean[3], mean[4], mean[5]);
    CHECK(rising == 0);
    CHECK(same_far == (long)n);
    CHECK(mean[5] > mean[1] + 0.01); /* thin boxes let light through */
    CHECK(strstr(image_get_attribute(&img[5], ATTR_SETTINGS), "thickness=0.25") != NULL);
    CHECK(strstr(image_get_attribute(&img[0], ATTR_SETTINGS), "thickness") == NULL);
    for (int r = 0; r < RUNS; ++r)
        image_free(&img[r]);
    scene_free(&s);
}

int main(void)
{
    test_band_closed_form();
    test_band_first_hit();
    test_boxes();
    return check_report("test_heightfield_thickness");
}
