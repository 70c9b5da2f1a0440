/* The height-field multi-bounce reference
 * (heightfield_multibounce_integrator.h) against mathematics:
 *  - a plane: nothing in the height field rises above it, V'_d = V_d = 1
 *    exactly at every pixel, for any albedo (1 included);
 *  - albedo 0 is the height-field AO: multibounce_0.V equals its own ao.V
 *    bit for bit, and ao.V agrees with the heightfield-ao reference (same
 *    rays but for the origin's offset: mean difference within 4 s.e.);
 *  - the energy bound: V_d <= V'_d(rho) <= V_d + rho (1 - V_d) at every
 *    pixel (every sample is 1 if its first ray escapes, else at most rho)
 *    and V'_d grows with rho;
 *  - where the depth buffer is the whole scene (an open box seen from
 *    straight above: every face in view, nothing off screen), the 3-D
 *    multi-bounce reference's V_d and the bounces' light V'_d - V_d per
 *    albedo: the mean over the pixels inside a face within 4 standard
 *    errors plus one 8-bit code value (the pixel discretisation of the
 *    faces' edges), against bounces' light of over 20 code values;
 *  - bit-identical output for 1 and 2 threads. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/reference_schema.h"
#include "multibounce/multibounce_quantity.h"
#include "raytracer/reference_render.h"
#include "scene/quad_mesh.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

static reference_quantity heightfield_multibounce(void)
{
    return QUANTITY_HEIGHTFIELD_MULTIBOUNCE;
}

static image render(reference_quantity q, const scene *s, const camera *cam, const char *albedos, int bounces,
                    int spp, int threads)
{
    multibounce_render_settings mb = {{q}, {.bounces = bounces}}; /* with albedos: q is a multibounce */
    reference_request req = {.quantity = q, .sampling = {.spp = spp, .seed = 7, .threads = threads},
                             .normals = NORMAL_SHADING, .settings = albedos ? &mb.header : NULL};
    gt_error e;
    if (albedos)
        CHECK(multibounce_parse_albedos(albedos, &mb.multibounce, &e) == 0);
    image img = {0};
    render_stats stats;
    if (reference_render(s, s->name, cam, &req, &img, &stats, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        CHECK(0);
    }
    return img;
}

static const float *channel(const image *img, const char *name)
{
    const float *c = image_channel_data(img, name);
    CHECK_MSG(c != NULL, "no channel %s", name);
    return c;
}

static void test_plane(void)
{
    scene s;
    camera cam;
    gt_error e;
    CHECK(scene_load("builtin:plane", &s, &e) == 0);
    CHECK(scene_choose_camera(&s, NULL, 32, 32, &cam, &e) == 0);
    image img = render(heightfield_multibounce(), &s, &cam, "0.3,0.9,1", 4, 16, 2);
    const float *mask = channel(&img, CH_MASK);
    const char *names[] = {"multibounce_0.3.V", "multibounce_0.9.V", "multibounce_1.V", CH_AO};
    long covered = 0, ones = 0;
    for (size_t i = 0; i < image_pixel_count(&img); ++i) {
        if (mask[i] == 0.0f)
            continue;
        ++covered;
        int all = 1;
        for (int c = 0; c < 4; ++c)
            all &= channel(&img, names[c])[i] == 1.0f;
        ones += all;
    }
    CHECK(covered > 0);
    CHECK_MSG(ones == covered, "plane: %ld of %ld pixels are 1 in every channel", ones, covered);
    image_free(&img);
    scene_free(&s);
}

/* Albedo 0, the bounds and the threads on the boxes seen by their camera. */
static void test_albedo_zero_and_bounds(void)
{
    scene s;
    camera cam;
    gt_error e;
    CHECK(scene_load("builtin:boxes", &s, &e) == 0);
    CHECK(scene_choose_camera(&s, NULL, 40, 40, &cam, &e) == 0);
    image mb = render(heightfield_multibounce(), &s, &cam, "0,0.5,0.9", 4, 32, 2);
    image mb1 = render(heightfield_multibounce(), &s, &cam, "0,0.5,0.9", 4, 32, 1);
    image hf = render(QUANTITY_HEIGHTFIELD_AO, &s, &cam, NULL, 0, 32, 2);
    const float *mask = channel(&mb, CH_MASK), *v = channel(&mb, CH_AO), *zero = channel(&mb, "multibounce_0.V");
    const float *half = channel(&mb, "multibounce_0.5.V"), *most = channel(&mb, "multibounce_0.9.V");
    const float *hv = channel(&hf, CH_AO), *hse = channel(&hf, CH_AO_STDERR);
    long n = 0, unequal = 0, unbounded = 0, occluded = 0;
    double diff = 0.0, var = 0.0;
    for (size_t i = 0; i < image_pixel_count(&mb); ++i) {
        if (mask[i] == 0.0f)
            continue;
        ++n;
        unequal += zero[i] != v[i];
        occluded += v[i] < 0.99f;
        const double slack = 1e-6;
        unbounded += !(v[i] <= half[i] + slack && half[i] <= most[i] + slack &&
                       most[i] <= v[i] + 0.9 * (1.0 - v[i]) + slack && half[i] <= v[i] + 0.5 * (1.0 - v[i]) + slack);
        diff += (double)v[i] - hv[i];
        var += 2.0 * (double)hse[i] * hse[i]; /* two renders of the same noise */
    }
    double z = diff / sqrt(var);
    printf("boxes: %ld pixels (%ld occluded), albedo 0 != ao.V at %ld, bounds broken at %ld; "
           "ao.V - heightfield-ao: mean %+.5f, z %+.2f\n", n, occluded, unequal, unbounded, diff / (double)n, z);
    CHECK(n > 0 && occluded > n / 10);
    CHECK(unequal == 0);
    CHECK(unbounded == 0);
    CHECK(fabs(z) < 4.0);
    size_t bytes = image_pixel_count(&mb) * sizeof(float);
    CHECK(memcmp(channel(&mb1, "multibounce_0.9.V"), most, bytes) == 0);
    image_free(&mb);
    image_free(&mb1);
    image_free(&hf);
    scene_free(&s);
}

/* An open box [-1, 1] x [0, 1] x [-1, 1] (floor and four inner walls) seen
 * from straight above: its rim lies inside the image, so the depth buffer
 * holds every face any ray from a visible point can reach. */
static int build_open_box(scene *s, camera *cam)
{
    int white = scene_add_material(s, scene_matte_material(1.0f, 1.0f, 1.0f));
    if (white < 0)
        return -1;
    vec3 corners[8];
    aligned_box_corners(v3(-1.0f, 0.0f, -1.0f), v3(1.0f, 1.0f, 1.0f), corners);
    quad_list l = {0};
    int rc = push_box_faces(&l, corners, ALL_FACES & ~FACE_BIT(FACE_POS_Y), 1);
    if (rc == 0)
        rc = quad_mesh_add(s, &l, white);
    quad_list_free(&l);
    *cam = (camera){{0, 2.2f, 0}, {0, 0, 0}, {0, 0, -1}, 90.0f * 3.14159265f / 180.0f, 128, 128};
    return rc;
}

/* Whether pixel i and its 8 neighbours all see one face (the same normal):
 * a pixel across an edge has its own face's plane over the whole footprint,
 * a difference of the height field's of the order of a pixel. */
static int inside_a_face(const image *img, size_t i)
{
    const float *mask = channel(img, CH_MASK);
    const float *normal[3] = {channel(img, CH_NG_X), channel(img, CH_NG_Y), channel(img, CH_NG_Z)};
    int w = img->width, h = img->height, x = (int)(i % (size_t)w), y = (int)(i / (size_t)w);
    if (x < 1 || y < 1 || x >= w - 1 || y >= h - 1)
        return 0;
    for (int k = 0; k < 9; ++k) {
        size_t j = (size_t)(y + k / 3 - 1) * (size_t)w + (size_t)(x + k % 3 - 1);
        if (mask[j] == 0.0f)
            return 0;
        for (int c = 0; c < 3; ++c)
            if (normal[c][j] != normal[c][i])
                return 0;
    }
    return 1;
}

/* Channel `name` of img minus channel `minus` (NULL: nothing), and a bound
 * of its standard error per pixel (the two errors added). */
typedef struct {
    const float *v, *se, *minus, *minus_se;
} difference_channels;

static difference_channels difference_of(const image *img, const char *name, const char *minus)
{
    char stderr_name[128];
    difference_channels d = {channel(img, name), NULL, NULL, NULL};
    snprintf(stderr_name, sizeof stderr_name, "%s.%s", name, CH_SUFFIX_STDERR);
    d.se = channel(img, stderr_name);
    if (minus) {
        snprintf(stderr_name, sizeof stderr_name, "%s.%s", minus, CH_SUFFIX_STDERR);
        d.minus = channel(img, minus);
        d.minus_se = channel(img, stderr_name);
    }
    return d;
}

static double value(const difference_channels *d, size_t i, double *se)
{
    *se = d->se[i] + (d->minus ? d->minus_se[i] : 0.0f);
    return (double)d->v[i] - (d->minus ? d->minus[i] : 0.0f);
}

/* Whether the mean over the box's pixels inside a face of (name - minus)
 * of x minus the same of y is within `allowance` plus 4 standard errors;
 * prints it under `label`. Returns the difference in standard errors. */
static double mean_z(const image *x, const image *y, const char *name, const char *minus, double allowance,
                     const char *label)
{
    const float *mask = channel(x, CH_MASK);
    const difference_channels dx = difference_of(x, name, minus), dy = difference_of(y, name, minus);
    double diff = 0.0, var = 0.0, n = 0.0;
    for (size_t i = 0; i < image_pixel_count(x); ++i)
        if (mask[i] != 0.0f && inside_a_face(x, i)) {
            double sx, sy;
            diff += value(&dx, i, &sx) - value(&dy, i, &sy);
            var += sx * sx + sy * sy;
            n += 1.0;
        }
    double mean = diff / n, se = sqrt(var) / n;
    printf("open box, %s: mean difference %+.5f +- %.5f over %.0f pixels\n", label, mean, se, n);
    CHECK_MSG(fabs(mean) <= allowance + 4.0 * se, "%s", label);
    return mean / se;
}

static void test_open_box_agrees_with_3d(void)
{
    scene s = {.name = "test:open-box"};
    camera cam;
    CHECK(build_open_box(&s, &cam) == 0);
    image hf = render(heightfield_multibounce(), &s, &cam, "0.5,0.9", 4, 64, 2);
    image d3 = render(QUANTITY_MULTIBOUNCE, &s, &cam, "0.5,0.9", 4, 64, 2);
    /* The height field is exact on every face; at its edges (the walls'
     * corners, the rim) each pixel's plane spans its whole footprint, and
     * rays from inside the faces see that: measured well under a code value
     * at 128^2 (the bounces' light twice as far off at 64^2). The allowance
     * is one 8-bit code value. */
    const double code_value = 1.0 / 255.0;
    mean_z(&hf, &d3, CH_AO, NULL, code_value, "V_d");
    mean_z(&hf, &d3, "multibounce_0.5.V", CH_AO, code_value, "the bounces' light V'_d(0.5) - V_d");
    mean_z(&hf, &d3, "multibounce_0.9.V", CH_AO, code_value, "the bounces' light V'_d(0.9) - V_d");
    /* ... which is large against that allowance: the test sees the bounces */
    const difference_channels bounces = difference_of(&hf, "multibounce_0.9.V", CH_AO);
    const float *mask = channel(&hf, CH_MASK);
    double light = 0.0, se, n = 0.0;
    for (size_t i = 0; i < image_pixel_count(&hf); ++i)
        if (mask[i] != 0.0f && inside_a_face(&hf, i)) {
            light += value(&bounces, i, &se);
            n += 1.0;
        }
    printf("open box: the bounces' light at albedo 0.9, %.4f\n", light / n);
    CHECK(light / n > 20.0 * code_value);
    image_free(&hf);
    image_free(&d3);
    scene_free(&s);
}

int main(void)
{
    test_plane();
    test_albedo_zero_and_bounds();
    test_open_box_agrees_with_3d();
    return check_report("test_heightfield_multibounce");
}
