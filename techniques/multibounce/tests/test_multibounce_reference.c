/* The multi-bounce reference (V'_d = L / rho) against exact answers:
 *  - an open plane: nothing to occlude or inter-reflect, V'_d = V_d = 1
 *    exactly, for any albedo and depth;
 *  - a closed box: no path ever escapes, V'_d = V_d = 0 exactly, including
 *    albedo 1 with unlimited bounces (the path limit ends those paths);
 *  - an integrating sphere (a sphere with a cap cut off): the geometric
 *    series of integrating-sphere theory, for fixed depth, Russian roulette
 *    and coloured scene albedos, within 4 standard errors per pixel and in
 *    an aggregate z-test;
 *  - Russian roulette agrees with fixed depth 64 on the Cornell box at
 *    albedo 0.9 (and the same comparison tells depth 4 apart);
 *  - several albedos in one pass give bit for bit the single-albedo renders
 *    (one geometric path serves every albedo); V_d <= V'_d(rho) <= 1 and
 *    V'_d grows with rho in every pixel, as holds path by path; ao.V agrees
 *    with the AO integrator's;
 *  - bit-identical output for 1 and 2 threads, exact merge of sample blocks,
 *    and merge refusing renders of different settings. */
#include <math.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/sampling/hemisphere_sampling.h"
#include "multibounce/multibounce_quantity.h"
#include "raytracer/reference_merge.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"
#include "tests/raytracer/closed_box.h"
#include "core/reference_schema.h"

/* ---- Rendering helpers ------------------------------------------------------------- */

static multibounce_settings grey(int bounces, int count, const float *albedos)
{
    multibounce_settings s = {0};
    s.albedo_count = count;
    if (count > 0)
        memcpy(s.albedos, albedos, sizeof(float) * (size_t)count);
    s.bounces = bounces;
    return s;
}

static multibounce_settings scene_albedo(int bounces)
{
    multibounce_settings s = {0};
    s.scene_albedo = 1;
    s.bounces = bounces;
    return s;
}

typedef struct {
    int spp;
    uint32_t offset, seed;
    int threads;
} sampling;

static image render_request(const scene *s, const camera *cam, const reference_request *req)
{
    gt_error e;
    image img = {0};
    render_stats stats;
    if (reference_render(s, s->name, cam, req, &img, &stats, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        CHECK(0);
    }
    return img;
}

static image render(const scene *s, const camera *cam, multibounce_settings mb, sampling sm)
{
    multibounce_render_settings settings = {{QUANTITY_MULTIBOUNCE}, mb};
    reference_request req = {.quantity = QUANTITY_MULTIBOUNCE,
                             .sampling = {sm.spp, sm.offset, sm.seed, 0.0, sm.threads},
                             .normals = NORMAL_SHADING,
                             .settings = &settings.header};
    return render_request(s, cam, &req);
}

static const float *channel(const image *img, const char *name)
{
    const float *c = image_channel_data(img, name);
    CHECK_MSG(c != NULL, "no channel %s", name);
    return c;
}

static int channels_identical(const image *a, const char *name_a, const image *b, const char *name_b)
{
    const float *x = image_channel_data(a, name_a), *y = image_channel_data(b, name_b);
    return x && y && memcmp(x, y, sizeof(float) * image_pixel_count(a)) == 0;
}

static int covered_pixels(const image *img)
{
    const float *mask = channel(img, "mask.A");
    int n = 0;
    for (size_t i = 0; i < image_pixel_count(img); ++i)
        n += mask[i] != 0.0f;
    return n;
}

/* Counts covered pixels of `name` that are not exactly `expected`. */
static int pixels_not(const image *img, const char *name, float expected)
{
    const float *mask = channel(img, "mask.A"), *v = channel(img, name);
    int n = 0;
    for (size_t i = 0; v && i < image_pixel_count(img); ++i)
        n += mask[i] != 0.0f && v[i] != expected;
    return n;
}

static void load(const char *spec, int size, scene *s, camera *cam)
{
    gt_error e;
    if (scene_load(spec, s, &e) != 0 || scene_choose_camera(s, NULL, size, size, cam, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        CHECK(0);
    }
}

/* ---- z statistics ------------------------------------------------------------------ */

/* Per-pixel comparisons within 4 standard errors, and the aggregate test:
 * pixels have independent seeds, so their errors add in quadrature and the
 * mean error must be within 4 of its standard errors, which sees a bias far
 * below what one pixel can. */
typedef struct {
    int compared, outliers;
    double worst_z, sum_error, sum_variance;
} z_summary;

static void z_add(z_summary *z, double difference, double stderr_)
{
    double dz = fabs(difference) / fmax(stderr_, 1e-12);
    z->compared++;
    z->outliers += dz > 4.0;
    z->worst_z = fmax(z->worst_z, dz);
    z->sum_error += difference;
    z->sum_variance += stderr_ * stderr_;
}

static double aggregate_z(const z_summary *z) { return fabs(z->sum_error) / sqrt(fmax(z->sum_variance, 1e-300)); }

static void z_check(const z_summary *z, int min_compared, const char *label)
{
    CHECK_MSG(z->compared >= min_compared, "%s: only %d pixels compared", label, z->compared);
    CHECK_MSG(z->outliers == 0, "%s: %d of %d pixels beyond 4 standard errors (worst %.2f)", label, z->outliers,
              z->compared, z->worst_z);
    CHECK_MSG(aggregate_z(z) < 4.0, "%s: mean error %.2e is %.2f standard errors", label,
              z->sum_error / fmax(z->compared, 1), aggregate_z(z));
}

/* ---- Open plane and closed box ----------------------------------------------------- */

static void test_open_plane(void)
{
    scene s;
    camera cam;
    load("builtin:plane", 32, &s, &cam);
    const multibounce_settings cases[] = {grey(4, 2, (const float[]){0.5f, 1.0f}),
                                          grey(MULTIBOUNCE_UNLIMITED, 2, (const float[]){0.5f, 0.9f}),
                                          scene_albedo(MULTIBOUNCE_UNLIMITED)};
    const char *const names[][3] = {{"multibounce_0.5.V", "multibounce_1.V"},
                                    {"multibounce_0.5.V", "multibounce_0.9.V"},
                                    {"multibounce.R", "multibounce.G", "multibounce.B"}};
    for (int c = 0; c < 3; ++c) {
        image img = render(&s, &cam, cases[c], (sampling){256, 0, 3, 2});
        CHECK_MSG(covered_pixels(&img) > 500, "plane: %d pixels", covered_pixels(&img));
        CHECK_MSG(pixels_not(&img, "ao.V", 1.0f) == 0, "plane case %d: V_d != 1", c);
        for (int k = 0; k < 3 && names[c][k]; ++k)
            CHECK_MSG(pixels_not(&img, names[c][k], 1.0f) == 0, "plane case %d: %s != 1", c, names[c][k]);
        image_free(&img);
    }
    scene_free(&s);
}

static void test_closed_box(void)
{
    scene s = {.name = "test:closed-box"};
    CHECK(add_closed_box(&s) == 0);
    camera cam = {v3(0.1f, -0.2f, 0.3f), v3(0.9f, 0.3f, -0.5f), v3(0.0f, 1.0f, 0.0f), 1.5f, 4, 4};
    const multibounce_settings cases[] = {grey(0, 2, (const float[]){0.5f, 1.0f}),
                                          grey(4, 3, (const float[]){0.0f, 0.5f, 1.0f}),
                                          grey(MULTIBOUNCE_UNLIMITED, 2, (const float[]){0.5f, 1.0f}),
                                          scene_albedo(MULTIBOUNCE_UNLIMITED)};
    for (int c = 0; c < 4; ++c) {
        image img = render(&s, &cam, cases[c], (sampling){16, 0, 5, 2});
        CHECK_MSG(covered_pixels(&img) == 16, "box case %d: %d pixels see the box", c, covered_pixels(&img));
        CHECK_MSG(pixels_not(&img, "spp.N", 16.0f) == 0, "box case %d: sample counts", c);
        int nonzero = 0;
        for (int ch = 0; ch < img.channel_count; ++ch)
            if (strncmp(img.channels[ch].name, "multibounce", 11) == 0 || strncmp(img.channels[ch].name, "ao.", 3) == 0)
                nonzero += pixels_not(&img, img.channels[ch].name, 0.0f);
        CHECK_MSG(nonzero == 0, "box case %d: %d non-zero estimates", c, nonzero);
        image_free(&img);
    }
    scene_free(&s);
}

/* ---- The integrating sphere --------------------------------------------------------- */

/* A sphere of radius 1 about the origin cut open around +Y: seen from any
 * point of its inner surface, a surface element dA of the sphere has view
 * factor dA / (4 pi R^2), whatever the point (the distance between two
 * points of a sphere is 2 R cos(theta) with theta the angle both normals
 * make with the chord, so cos^2 / (pi d^2) is constant; Goebel 1967,
 * "Generalized integrating-sphere theory", Appl. Opt. 6(1)). Every ray
 * through the opening would have hit the missing cap of half-angle alpha,
 * so from EVERY inner point a cosine-distributed ray escapes with the same
 * probability f = cap area / sphere area = (1 - cos alpha) / 2, and
 * otherwise lands on the sphere again. The number of inter-reflections
 * before escape is geometric:
 *   V_d = f,  V'_d(N bounces) = f sum_{k=0..N} (rho (1 - f))^k
 *                             = f (1 - (rho (1 - f))^(N+1)) / (1 - rho (1 - f)),
 *   V'_d(inf) = f / (1 - rho (1 - f))   (the "sphere multiplier").
 * The mesh: latitude-longitude, vertices on the sphere, exact radial
 * normals; alpha = 60 deg, so f = 1/4. Its facets lie within 2e-5 of the
 * sphere, far below what the test resolves. */
enum { SPHERE_RINGS = 192, SPHERE_SEGMENTS = 384, SPHERE_OPEN_RINGS = 64 };
static const double sphere_f = 0.25; /* (1 - cos 60 deg) / 2 */

static int add_open_sphere(scene *s, int material, int with_texcoords)
{
    const int rings = SPHERE_RINGS - SPHERE_OPEN_RINGS, row = SPHERE_SEGMENTS + 1;
    uint32_t vertices = (uint32_t)((rings + 1) * row);
    uint32_t triangles = (uint32_t)(2 * rings * SPHERE_SEGMENTS - SPHERE_SEGMENTS); /* one per quad at the pole */
    scene_mesh *m = scene_add_mesh(s, vertices, triangles, with_texcoords);
    if (!m)
        return -1;
    m->material = material;
    for (int i = 0; i <= rings; ++i) {
        double theta = M_PI * (SPHERE_OPEN_RINGS + i) / SPHERE_RINGS;
        for (int j = 0; j < row; ++j) {
            double phi = 2.0 * M_PI * j / SPHERE_SEGMENTS;
            float n[3] = {(float)(sin(theta) * cos(phi)), (float)cos(theta), (float)(sin(theta) * sin(phi))};
            memcpy(&m->positions[3 * (i * row + j)], n, sizeof n);
            memcpy(&m->normals[3 * (i * row + j)], n, sizeof n);
            if (with_texcoords) {
                m->texcoords[2 * (i * row + j)] = (float)j / SPHERE_SEGMENTS;
                m->texcoords[2 * (i * row + j) + 1] = (float)i / (float)rings;
            }
        }
    }
    uint32_t *t = m->indices;
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < SPHERE_SEGMENTS; ++j) {
            uint32_t a = (uint32_t)(i * row + j), b = a + 1, c = a + (uint32_t)row, d = c + 1;
            if (i + 1 < rings) { /* the last ring's c and d are both the south pole */
                *t++ = a, *t++ = c, *t++ = d;
            }
            *t++ = a, *t++ = d, *t++ = b;
        }
    return 0;
}

/* Mean and second moment of one sample: the path escapes after exactly k
 * inter-reflections with probability ((1 - f) q)^k f (q: Russian roulette's
 * survival probability, 1 at fixed depth) and then carries (rho / q)^k. */
typedef struct {
    double mean, second_moment;
} moments;

static moments sphere_sample_moments(double rho, double q, int max_bounces)
{
    moments m = {0.0, 0.0};
    for (int k = 0; k <= max_bounces; ++k) {
        double p = pow((1.0 - sphere_f) * q, k) * sphere_f, w = pow(rho / q, k);
        m.mean += p * w;
        m.second_moment += p * w * w;
    }
    return m;
}

/* The closed forms above. */
static double sphere_closed_form(double rho, int bounces)
{
    double r = rho * (1.0 - sphere_f);
    return bounces == MULTIBOUNCE_UNLIMITED ? sphere_f / (1.0 - r) : sphere_f * (1.0 - pow(r, bounces + 1)) / (1.0 - r);
}

/* Compares a channel with the closed form. A pixel's standard error is the
 * larger of its own and the one the exact sample variance gives, so a pixel
 * whose samples happen to agree is not judged on a zero error. */
static void check_sphere_channel(const image *img, const char *name, double rho, double q, int bounces, int spp)
{
    double expected = sphere_closed_form(rho, bounces);
    moments m = sphere_sample_moments(rho, q, bounces == MULTIBOUNCE_UNLIMITED ? MULTIBOUNCE_PATH_LIMIT : bounces);
    CHECK_NEAR(m.mean, expected, 1e-12);
    double null_stderr = sqrt((m.second_moment - m.mean * m.mean) / spp);
    const float *mask = channel(img, "mask.A"), *v = channel(img, name);
    char stderr_name[IMAGE_NAME_MAX + 8];
    snprintf(stderr_name, sizeof stderr_name, "%s.stderr", name);
    const float *se = channel(img, stderr_name);
    if (!v || !se)
        return;
    z_summary z = {0};
    for (size_t i = 0; i < image_pixel_count(img); ++i)
        if (mask[i] != 0.0f)
            z_add(&z, v[i] - expected, fmax(se[i], null_stderr));
    char label[128];
    snprintf(label, sizeof label, "sphere %s, rho %g, bounces %d (expected %.4f)", name, rho, bounces, expected);
    z_check(&z, 700, label);
}

/* The sphere in a material of base colour factor `factor`, times a uniform
 * 2 x 2 sRGB texture of colour `texel` if given. */
static void build_integrating_sphere(scene *s, const float factor[3], const unsigned char *texel)
{
    *s = (scene){.name = "test:integrating-sphere"};
    scene_material m = {{factor[0], factor[1], factor[2], 1.0f}, -1, 0.0f, 1.0f, -1};
    if (texel) {
        s->textures = calloc(1, sizeof *s->textures);
        unsigned char *rgba = malloc(16);
        CHECK(s->textures && rgba);
        if (!s->textures || !rgba)
            return;
        for (int k = 0; k < 16; ++k)
            rgba[k] = k % 4 == 3 ? 255 : texel[k % 4];
        s->textures[0] = (scene_texture){2, 2, rgba};
        s->texture_count = 1;
        m.base_color_texture = 0;
    }
    int material = scene_add_material(s, m);
    CHECK(material >= 0 && add_open_sphere(s, material, texel != NULL) == 0);
}

/* The sRGB transfer function's inverse (IEC 61966-2-1), on 8-bit values. */
static double srgb8_to_linear(unsigned char c)
{
    double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

static void test_integrating_sphere(void)
{
    scene s;
    const float white[3] = {1.0f, 1.0f, 1.0f};
    build_integrating_sphere(&s, white, NULL);
    /* From the centre, looking sideways: the top rows look out through the
     * opening (background), the rest sees the sphere, up to the rim. */
    camera cam = {v3(0.0f, 0.0f, 0.0f), v3(1.0f, 0.0f, 0.0f), v3(0.0f, 1.0f, 0.0f), (float)(M_PI / 2), 32, 32};
    const int spp = 256;
    const float albedos[2] = {0.3f, 0.9f};
    const int depths[3] = {4, 64, MULTIBOUNCE_UNLIMITED};
    for (int d = 0; d < 3; ++d) {
        image img = render(&s, &cam, grey(depths[d], 2, albedos), (sampling){spp, 0, 17u + (uint32_t)d, 2});
        CHECK_MSG(covered_pixels(&img) < 1024, "the opening is not in view");
        check_sphere_channel(&img, "ao.V", 0.0, 1.0, 0, spp);
        /* Roulette survives with the largest albedo, 0.9. */
        double q = depths[d] == MULTIBOUNCE_UNLIMITED ? 0.9 : 1.0;
        check_sphere_channel(&img, "multibounce_0.3.V", 0.3, q, depths[d], spp);
        check_sphere_channel(&img, "multibounce_0.9.V", 0.9, q, depths[d], spp);
        image_free(&img);
    }
    scene_free(&s);

    /* Coloured: the base colour at every vertex, from the material factor
     * (unlimited bounces, roulette with the largest channel) or from a
     * texture (4 bounces). */
    const char *const rgb[3] = {"multibounce.R", "multibounce.G", "multibounce.B"};
    const float factor[3] = {0.9f, 0.5f, 0.1f};
    build_integrating_sphere(&s, factor, NULL);
    image img = render(&s, &cam, scene_albedo(MULTIBOUNCE_UNLIMITED), (sampling){spp, 0, 23, 2});
    for (int c = 0; c < 3; ++c)
        check_sphere_channel(&img, rgb[c], factor[c], factor[0], MULTIBOUNCE_UNLIMITED, spp);
    image_free(&img);
    scene_free(&s);
    const unsigned char texel[3] = {240, 180, 90};
    build_integrating_sphere(&s, white, texel);
    img = render(&s, &cam, scene_albedo(4), (sampling){spp, 0, 29, 2});
    for (int c = 0; c < 3; ++c)
        check_sphere_channel(&img, rgb[c], srgb8_to_linear(texel[c]), 1.0, 4, spp);
    image_free(&img);
    scene_free(&s);
}

/* ---- Deep inter-reflection: roulette against fixed depth ----------------------------- */

/* z statistics of channel a of one render against channel b of another,
 * independent, render. */
static z_summary compare_renders(const image *x, const char *a, const image *y, const char *b)
{
    char ea[IMAGE_NAME_MAX + 8], eb[IMAGE_NAME_MAX + 8];
    snprintf(ea, sizeof ea, "%s.stderr", a);
    snprintf(eb, sizeof eb, "%s.stderr", b);
    const float *mask = channel(x, "mask.A"), *va = channel(x, a), *vb = channel(y, b);
    const float *sa = channel(x, ea), *sb = channel(y, eb);
    z_summary z = {0};
    for (size_t i = 0; va && vb && sa && sb && i < image_pixel_count(x); ++i)
        if (mask[i] != 0.0f)
            z_add(&z, va[i] - vb[i], hypot(sa[i], sb[i]));
    return z;
}

static void test_roulette_matches_fixed_depth(void)
{
    scene s;
    camera cam;
    load("builtin:cornell", 24, &s, &cam);
    const float albedo = 0.9f;
    image roulette = render(&s, &cam, grey(MULTIBOUNCE_UNLIMITED, 1, &albedo), (sampling){256, 0, 1, 2});
    image deep = render(&s, &cam, grey(64, 1, &albedo), (sampling){256, 0, 2, 2});
    image shallow = render(&s, &cam, grey(4, 1, &albedo), (sampling){256, 0, 3, 2});
    z_summary z = compare_renders(&roulette, "multibounce.V", &deep, "multibounce.V");
    z_check(&z, 400, "cornell, albedo 0.9: roulette vs 64 bounces");
    /* The same test does see the missing energy of 4 bounces. */
    z_summary shallow_z = compare_renders(&roulette, "multibounce.V", &shallow, "multibounce.V");
    CHECK_MSG(aggregate_z(&shallow_z) > 20.0, "roulette vs 4 bounces: only %.1f standard errors apart",
              aggregate_z(&shallow_z));
    image_free(&roulette);
    image_free(&deep);
    image_free(&shallow);
    scene_free(&s);
}

/* ---- One pass for several albedos ---------------------------------------------------- */

static void check_pathwise_order(const image *img, const char *const *names, int count)
{
    const float *mask = channel(img, "mask.A"), *vd = channel(img, "ao.V");
    int disorder = 0;
    for (size_t i = 0; i < image_pixel_count(img); ++i) {
        if (mask[i] == 0.0f)
            continue;
        float previous = vd[i];
        for (int k = 0; k < count; ++k) {
            float v = image_channel_data(img, names[k])[i];
            disorder += v < previous || v > 1.0f;
            previous = v;
        }
    }
    CHECK_MSG(disorder == 0, "%d pixels break V_d <= V'_d(0.2) <= V'_d(0.6) <= V'_d(0.9) <= 1", disorder);
}

static void test_shared_paths(void)
{
    scene s;
    camera cam;
    load("builtin:cornell", 24, &s, &cam);
    const sampling sm = {64, 0, 9, 2};
    const float albedos[3] = {0.2f, 0.6f, 0.9f};
    const char *const names[3] = {"multibounce_0.2.V", "multibounce_0.6.V", "multibounce_0.9.V"};
    const int depths[2] = {4, MULTIBOUNCE_UNLIMITED};
    for (int d = 0; d < 2; ++d) {
        image all = render(&s, &cam, grey(depths[d], 3, albedos), sm);
        for (int k = 0; k < 3; ++k) {
            /* Roulette survives with the largest albedo of the pass: only
             * the largest one's single render makes the same decisions. */
            if (depths[d] == MULTIBOUNCE_UNLIMITED && k < 2)
                continue;
            image one = render(&s, &cam, grey(depths[d], 1, &albedos[k]), sm);
            char se[IMAGE_NAME_MAX + 8];
            snprintf(se, sizeof se, "%s.stderr", names[k]);
            CHECK_MSG(channels_identical(&all, names[k], &one, "multibounce.V"), "bounces %d: %s", depths[d],
                      names[k]);
            CHECK_MSG(channels_identical(&all, se, &one, "multibounce.V.stderr"), "bounces %d: %s", depths[d], se);
            CHECK(channels_identical(&all, "ao.V", &one, "ao.V"));
            image_free(&one);
        }
        if (depths[d] != MULTIBOUNCE_UNLIMITED)
            check_pathwise_order(&all, names, 3);
        image_free(&all);
    }

    /* ao.V is the AO integrator's estimator of V_d. */
    image mb = render(&s, &cam, grey(4, 1, albedos), (sampling){256, 0, 4, 2});
    reference_request ao_req = {.quantity = QUANTITY_AO,
                                .sampling = {256, 0, 5, 0.0, 2},
                                .normals = NORMAL_SHADING};
    image ao = render_request(&s, &cam, &ao_req);
    z_summary z = compare_renders(&mb, "ao.V", &ao, "ao.V");
    z_check(&z, 400, "cornell: multibounce ao.V vs the AO integrator");
    image_free(&mb);
    image_free(&ao);
    scene_free(&s);
}

/* ---- Determinism and merge ----------------------------------------------------------- */

static int all_channels_identical(const image *a, const image *b)
{
    if (a->channel_count != b->channel_count)
        return 0;
    for (int c = 0; c < a->channel_count; ++c)
        if (!channels_identical(a, a->channels[c].name, b, a->channels[c].name)) {
            fprintf(stderr, "channel %s differs\n", a->channels[c].name);
            return 0;
        }
    return 1;
}

static void test_determinism_and_merge(void)
{
    scene s;
    camera cam;
    load("builtin:cornell", 20, &s, &cam);
    const multibounce_settings coloured = scene_albedo(MULTIBOUNCE_UNLIMITED);
    image one = render(&s, &cam, coloured, (sampling){64, 0, 13, 1});
    image two = render(&s, &cam, coloured, (sampling){64, 0, 13, 2});
    CHECK_MSG(all_channels_identical(&one, &two), "1 and 2 threads differ");

    image halves[2] = {render(&s, &cam, coloured, (sampling){32, 0, 13, 2}),
                       render(&s, &cam, coloured, (sampling){32, 32, 13, 2})};
    const char *names[2] = {"first half", "second half"};
    image merged;
    gt_error e;
    CHECK(reference_merge(&REFERENCE_REGISTRY_OF(QUANTITY_MULTIBOUNCE), halves, names, 2, &merged, &e) == 0);
    static const char *const compared[] = {"multibounce.R", "multibounce.G", "multibounce.B", "ao.V",
                                           "multibounce.R.stderr", "multibounce.B.stderr", "ao.V.stderr"};
    for (size_t c = 0; c < sizeof compared / sizeof compared[0]; ++c)
        CHECK_MSG(channels_identical(&one, compared[c], &merged, compared[c]), "merged %s", compared[c]);
    CHECK(strcmp(image_get_attribute(&merged, ATTR_ALBEDOS), "scene") == 0);
    CHECK(strcmp(image_get_attribute(&merged, ATTR_BOUNCES), "inf") == 0);
    image_free(&merged);

    /* A block rendered with other settings is not part of the same render. */
    image other = render(&s, &cam, scene_albedo(4), (sampling){32, 32, 13, 2});
    image parts[2] = {halves[0], other};
    CHECK(reference_merge(&REFERENCE_REGISTRY_OF(QUANTITY_MULTIBOUNCE), parts, names, 2, &merged, &e) != 0);
    CHECK_MSG(strstr(e.message, ATTR_SETTINGS) != NULL, "unexpected refusal: %s", e.message);

    image_free(&other);
    for (int h = 0; h < 2; ++h)
        image_free(&halves[h]);
    image_free(&one);
    image_free(&two);
    scene_free(&s);
}

/* ---- Settings ------------------------------------------------------------------------ */

static void test_settings(void)
{
    gt_error e;
    multibounce_settings s = {0};
    char text[256];
    CHECK(multibounce_parse_albedos("0.1,0.3,0.5", &s, &e) == 0 && s.albedo_count == 3 && !s.scene_albedo);
    multibounce_albedos_text(&s, text, sizeof text);
    CHECK_MSG(strcmp(text, "0.1 0.3 0.5") == 0, "albedos text '%s'", text);
    CHECK(multibounce_parse_albedos("scene", &s, &e) == 0 && s.scene_albedo);
    static const char *const bad_albedos[] = {"", "0.1,", ",0.1", "1.5", "-0.1", "nan", "0.2,0.20", "x"};
    for (size_t i = 0; i < sizeof bad_albedos / sizeof bad_albedos[0]; ++i)
        CHECK_MSG(multibounce_parse_albedos(bad_albedos[i], &s, &e) != 0 && strncmp(e.message, "--albedo: ", 10) == 0,
                  "'%s' accepted", bad_albedos[i]);
    CHECK(multibounce_parse_bounces("inf", &s, &e) == 0 && s.bounces == MULTIBOUNCE_UNLIMITED);
    CHECK(multibounce_parse_bounces("0", &s, &e) == 0 && s.bounces == 0);
    static const char *const bad_bounces[] = {"", "-1", "4.5", "1025", "infinite"};
    for (size_t i = 0; i < sizeof bad_bounces / sizeof bad_bounces[0]; ++i)
        CHECK_MSG(multibounce_parse_bounces(bad_bounces[i], &s, &e) != 0, "'%s' accepted", bad_bounces[i]);
    multibounce_plan plan;
    multibounce_settings none = grey(4, 0, NULL);
    CHECK(multibounce_plan_init(&plan, &none, NORMAL_SHADING, &e) != 0);
    multibounce_settings fine = grey(2, 2, (const float[]){0.125f, 0.7f});
    CHECK(multibounce_plan_init(&plan, &fine, NORMAL_SHADING, &e) == 0 && plan.quantity_count == 3);
    CHECK(strcmp(plan.quantities[0].name, "multibounce_0.125.V") == 0);
    CHECK(strcmp(plan.quantities[2].name, "ao.V") == 0);
}

/* Issue 25: a per-object-albedo reference (--albedo scene) of a scene whose
 * materials all have one grey albedo is bit-identical to the single-albedo
 * reference at that albedo: the Cornell box (three materials) made all
 * 0.73, at 4 and unlimited bounces, 1 and 2 threads. */
static void test_equal_albedos_reduce_to_grey(void)
{
    scene s;
    camera cam;
    load("builtin:cornell", 24, &s, &cam);
    for (int m = 0; m < s.material_count; ++m)
        for (int c = 0; c < 3; ++c)
            s.materials[m].base_color[c] = 0.73f;
    const int bounces[2] = {4, MULTIBOUNCE_UNLIMITED};
    for (int b = 0; b < 2; ++b) {
        image coloured = render(&s, &cam, scene_albedo(bounces[b]), (sampling){16, 0, 5, 1 + b});
        image single = render(&s, &cam, grey(bounces[b], 1, (const float[]){0.73f}), (sampling){16, 0, 5, 2 - b});
        CHECK(covered_pixels(&single) > 300);
        CHECK(channels_identical(&coloured, "ao.V", &single, "ao.V"));
        const char *const rgb[3] = CH_MULTIBOUNCE_RGB;
        for (int c = 0; c < 3; ++c)
            CHECK_MSG(channels_identical(&coloured, rgb[c], &single, CH_MULTIBOUNCE), "bounces %d: %s", bounces[b],
                      rgb[c]);
        image_free(&coloured);
        image_free(&single);
    }
    scene_free(&s);
}

int main(void)
{
    test_settings();
    test_open_plane();
    test_closed_box();
    test_integrating_sphere();
    test_roulette_matches_fixed_depth();
    test_shared_paths();
    test_determinism_and_merge();
    test_equal_albedos_reduce_to_grey();
    return check_report("test_multibounce");
}
