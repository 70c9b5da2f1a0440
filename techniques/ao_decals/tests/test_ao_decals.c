/* INSIDE's AO decals (ao_decals/ao_decals.c) against independent estimators:
 *  - cosine-weighted Monte Carlo with analytic ray-box (slabs) and ray-sphere
 *    intersection, 200000 directions, fixed seeds, within 4 standard errors
 *    sqrt(a (1 - a) / N): the box's Lambert form for a point facing one
 *    face, one seeing three faces, a floor point beside a box standing on
 *    the floor, and a box cut by the tangent plane (horizon clipping); the
 *    exact sphere above, straddling and nearly below the horizon;
 *  - Quilez's sphere equals the exact form while the cap is above the
 *    horizon, and over-occludes or under-occludes once it straddles;
 *  - gtlab's AO reference (raytracer, builtin:sphere-on-plane, 32^2 pixels,
 *    512 spp): 1 - exact sphere within 4 of the render's standard errors on
 *    every floor pixel (the sphere is above every floor point's horizon);
 *  - the point decal: the published three lines are the general form at
 *    exponent 2, wrap 1; 0 outside the unit sphere;
 *  - two overlapping spheres: the multiplied decals occlude more than the
 *    union does (Monte Carlo): reported by the study, checked here. */
#include <math.h>

#include "ao/ao_quantity.h"
#include "ao_decals/ao_decals.h"
#include "core/reference_schema.h"
#include "luts/blue_noise.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

#define MC 200000

typedef int (*hit_fn)(const double *o, const double *d, const double *shape);

static int hit_box(const double *o, const double *d, const double *box)
{
    double t0 = 1e-9, t1 = INFINITY;
    for (int a = 0; a < 3; ++a) {
        double inv = 1.0 / d[a], ta = (box[a] - o[a]) * inv, tb = (box[3 + a] - o[a]) * inv;
        t0 = fmax(t0, fmin(ta, tb)), t1 = fmin(t1, fmax(ta, tb));
    }
    return t0 <= t1;
}

static int hit_sphere(const double *o, const double *d, const double *s)
{
    double oc[3] = {o[0] - s[0], o[1] - s[1], o[2] - s[2]};
    double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2], c = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - s[3] * s[3];
    double disc = b * b - c;
    return disc >= 0.0 && -b + sqrt(disc) > 0.0 && (-b - sqrt(disc) > 0.0 || c < 0.0);
}

/* Share of cosine-weighted directions about n hitting any of the shapes. */
static double mc_occlusion(vec3 p, vec3 n, hit_fn hit, const double *shapes, int count, int stride, uint64_t seed)
{
    double t[3], b[3], nn[3] = {n.x, n.y, n.z}, o[3] = {p.x, p.y, p.z};
    double s = nn[2] >= 0 ? 1.0 : -1.0, a = -1.0 / (s + nn[2]), c = nn[0] * nn[1] * a; /* Duff et al. 2017 */
    t[0] = 1 + s * nn[0] * nn[0] * a, t[1] = s * c, t[2] = -s * nn[0];
    b[0] = c, b[1] = s + nn[1] * nn[1] * a, b[2] = -nn[1];
    long hits = 0;
    for (int i = 0; i < MC; ++i) {
        double u1 = blue_noise_uniform(seed, 2 * i), u2 = blue_noise_uniform(seed, 2 * i + 1);
        double r = sqrt(u1), phi = 2 * M_PI * u2, x = r * cos(phi), y = r * sin(phi), z = sqrt(1 - u1), d[3];
        for (int k = 0; k < 3; ++k)
            d[k] = x * t[k] + y * b[k] + z * nn[k];
        int any = 0;
        for (int sh = 0; sh < count && !any; ++sh)
            any = hit(o, d, shapes + sh * stride);
        hits += any;
    }
    return (double)hits / MC;
}

static void check_against_mc(const char *what, double exact, double mc)
{
    double se = sqrt(fmax(exact * (1 - exact), 1e-12) / MC);
    CHECK_MSG(fabs(exact - mc) <= 4 * se, "%s: exact %.5f, Monte Carlo %.5f (se %.5f)", what, exact, mc, se);
}

static void check_box(const char *what, vec3 p, vec3 n, uint64_t seed)
{
    static const double box[6] = {0, 0, 0, 1, 1, 1};
    double exact = ao_box_exact(p, n, v3(0, 0, 0), v3(1, 1, 1));
    CHECK(exact > 0.005);
    check_against_mc(what, exact, mc_occlusion(p, n, hit_box, box, 1, 6, seed));
}

static void check_sphere(const char *what, vec3 p, vec3 n, vec3 c, float r, uint64_t seed)
{
    double s[4] = {c.x, c.y, c.z, r};
    check_against_mc(what, ao_sphere_exact(p, n, c, r), mc_occlusion(p, n, hit_sphere, s, 1, 4, seed));
}

static void check_analytic(void)
{
    check_box("box, facing one face", v3(0.5f, 0.5f, -1.0f), v3(0, 0, 1), 1);
    check_box("box, three faces", v3(-0.6f, -0.7f, -0.8f), v3_normalize(v3(1, 1, 1)), 2);
    check_box("box, floor beside it", v3(1.5f, 0.0f, 0.3f), v3(0, 1, 0), 3);
    check_box("box, cut by the horizon", v3(0.3f, 0.5f, -0.4f), v3(1, 0, 0), 4);
    check_sphere("sphere above", v3(0, 0, 0), v3(0, 1, 0), v3(0.5f, 1.5f, 0), 1.0f, 5);
    check_sphere("sphere straddling", v3(0, 0, 0), v3(0, 1, 0), v3(2.0f, 0.3f, 0), 1.0f, 6);
    check_sphere("sphere mostly below", v3(0, 0, 0), v3(0, 1, 0), v3(2.0f, -0.8f, 0), 1.0f, 7);
    vec3 up = v3(0, 1, 0), above = v3(0.5f, 1.5f, 0), straddle = v3(2.0f, 0.3f, 0);
    CHECK_NEAR(ao_sphere_quilez(v3(0, 0, 0), up, above, 1.0f), ao_sphere_exact(v3(0, 0, 0), up, above, 1.0f), 1e-6);
    CHECK(fabs(ao_sphere_quilez(v3(0, 0, 0), up, straddle, 1.0f) - ao_sphere_exact(v3(0, 0, 0), up, straddle, 1.0f)) >
          0.01);
}

static void check_point_decal(void)
{
    vec3 n = v3_normalize(v3(0.2f, 1.0f, -0.1f));
    for (float r = 0.1f; r < 1.2f; r += 0.27f) {
        vec3 pos = v3(0.3f * r, -0.8f * r, 0.5f * r);
        CHECK_NEAR(ao_point_decal_published(pos, n), ao_point_decal(pos, n, 2.0f, 1.0f), 1e-6);
    }
    CHECK(ao_point_decal_published(v3(0.9f, 0.9f, 0.0f), n) == 0.0f);
}

/* Two nearly coincident spheres: (1 - a)^2 against the union's 1 - a. */
static void check_overlap(void)
{
    vec3 p = v3(0, 0, 0), n = v3(0, 1, 0), c1 = v3(0.2f, 1.5f, 0), c2 = v3(-0.2f, 1.6f, 0);
    double spheres[8] = {c1.x, c1.y, c1.z, 1.0, c2.x, c2.y, c2.z, 1.0};
    double product = (1 - ao_sphere_exact(p, n, c1, 1.0f)) * (1 - ao_sphere_exact(p, n, c2, 1.0f));
    double union_v = 1 - mc_occlusion(p, n, hit_sphere, spheres, 2, 4, 9);
    CHECK_MSG(product < union_v - 0.05, "product %g, union %g", product, union_v);
}

static void check_reference(void)
{
    gt_error e;
    scene s;
    camera cam;
    image img;
    render_stats stats;
    CHECK(scene_load("builtin:sphere-on-plane", &s, &e) == 0);
    CHECK(scene_choose_camera(&s, NULL, 32, 32, &cam, &e) == 0);
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = 512, .seed = 3, .threads = 2},
                             .normals = NORMAL_SHADING};
    CHECK(reference_render(&s, "builtin:sphere-on-plane", &cam, &req, &img, &stats, &e) == 0);
    const float *mask = image_channel_data(&img, CH_MASK), *py = image_channel_data(&img, CH_P_Y);
    const float *px = image_channel_data(&img, CH_P_X), *pz = image_channel_data(&img, CH_P_Z);
    const float *v = image_channel_data(&img, CH_AO), *ve = image_channel_data(&img, CH_AO_STDERR);
    int compared = 0, outliers = 0;
    for (size_t i = 0; i < image_pixel_count(&img); ++i) {
        if (mask[i] == 0.0f || py[i] != 0.0f)
            continue;
        double expected = 1.0 - ao_sphere_exact(v3(px[i], 0, pz[i]), v3(0, 1, 0), v3(0, 1.5f, 0), 1.0f);
        double se = fmax(ve[i], sqrt(fmax(expected * (1 - expected), 0) / 512));
        outliers += fabs(v[i] - expected) > 4 * fmax(se, 1e-7);
        ++compared;
    }
    CHECK_MSG(compared > 200 && outliers == 0, "%d of %d floor pixels beyond 4 stderr", outliers, compared);
    image_free(&img);
    scene_free(&s);
}

int main(void)
{
    check_analytic();
    check_point_decal();
    check_overlap();
    check_reference();
    return check_report("test_ao_decals");
}
