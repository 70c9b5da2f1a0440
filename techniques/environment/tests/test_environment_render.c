/* The environment-lit references (`gtlab render env-diffuse`, `env-specular`;
 * raytracer/environment_*_integrator.h), on small built-in scenes:
 * - under the white dome (constant radiance 1) env-diffuse equals the
 *   multibounce reference bit for bit at the same seed, means and standard
 *   errors: the scene's colours with 4 bounces, and a grey albedo with
 *   Russian roulette; environment_diffuse_direct equals ao.V;
 * - under a sun-only environment (one bright texel of a 512 x 256 map) the
 *   ratio of occluded to unoccluded direct light is exactly the shadow-ray
 *   visibility of the sun wherever rays to the texel's centre and corners
 *   agree (lit and shadowed pixels both present);
 * - env-specular under the white dome with F0 = 1 equals the
 *   specular-occlusion reference's numerator and denominator bit for bit
 *   (the same visible-normal samples and weights);
 * - 1 and 2 threads give the same bits (the sky, mixture sampling), and
 *   two sample blocks merge into the whole render bit for bit;
 * - a bad environment file is refused in one line naming it. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/optics/environment_map.h"
#include "core/reference_schema.h"
#include "environment/environment_diffuse_integrator.h"
#include "environment/environment_light.h"
#include "environment/environment_quantity.h"
#include "multibounce/multibounce_quantity.h"
#include "raytracer/reference_merge.h"
#include "raytracer/reference_render.h"
#include "specular_occlusion/specular_occlusion_quantity.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

static const char *const diffuse[3] = CH_ENV_DIFFUSE_RGB;
static const char *const direct[3] = CH_ENV_DIFFUSE_DIRECT_RGB;
static const char *const unoccluded[3] = CH_ENV_DIFFUSE_UNOCCLUDED_RGB;

typedef struct {
    int spp;
    uint32_t offset;
    int threads;
} sampling;

static int render_request(const scene *s, const camera *cam, reference_request *req, image *out, gt_error *e)
{
    render_stats stats;
    memset(out, 0, sizeof *out);
    return reference_render(s, s->name, cam, req, out, &stats, e);
}

static image render(const scene *s, const camera *cam, reference_quantity quantity, environment_render_settings *env,
                    multibounce_settings mb, float roughness, sampling sm)
{
    multibounce_render_settings white_dome = {{quantity}, mb}; /* multibounce's, without env */
    if (env)
        env->header.quantity = quantity, env->multibounce = mb, env->roughness = roughness;
    reference_request req = {.quantity = quantity,
                             .sampling = {sm.spp, sm.offset, 17, 0.0, sm.threads},
                             .normals = NORMAL_SHADING,
                             .settings = env ? &env->header : &white_dome.header};
    image img;
    gt_error e;
    if (render_request(s, cam, &req, &img, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        CHECK(0);
    }
    return img;
}

static int identical(const image *a, const char *name_a, const image *b, const char *name_b)
{
    const float *x = image_channel_data(a, name_a), *y = image_channel_data(b, name_b);
    return x && y && memcmp(x, y, sizeof(float) * image_pixel_count(a)) == 0;
}

static int identical_with_stderr(const image *a, const char *name_a, const image *b, const char *name_b)
{
    char sa[IMAGE_NAME_MAX + 8], sb[IMAGE_NAME_MAX + 8];
    snprintf(sa, sizeof sa, "%s.stderr", name_a);
    snprintf(sb, sizeof sb, "%s.stderr", name_b);
    return identical(a, name_a, b, name_b) && identical(a, sa, b, sb);
}

static void load(const char *spec, int size, scene *s, camera *cam)
{
    gt_error e;
    if (scene_load(spec, s, &e) != 0 || scene_choose_camera(s, NULL, size, size, cam, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        CHECK(0);
    }
}

static multibounce_settings albedo_of(int scene_albedo, float grey, int bounces)
{
    multibounce_settings m = {0};
    m.scene_albedo = scene_albedo;
    m.albedo_count = scene_albedo ? 0 : 1;
    m.albedos[0] = grey;
    m.bounces = bounces;
    return m;
}

static environment_render_settings named(const char *name)
{
    environment_render_settings s;
    environment_render_settings_default(&s, NULL); /* render() names the quantity */
    snprintf(s.environment, sizeof s.environment, "%s", name);
    return s;
}

static void test_white_dome_is_multibounce(void)
{
    scene s;
    camera cam;
    load("builtin:cornell", 20, &s, &cam);
    environment_render_settings white = named("white");
    const sampling sm = {64, 0, 2};
    image env = render(&s, &cam, &reference_quantity_env_diffuse, &white, albedo_of(1, 0, 4), -1, sm);
    image mb = render(&s, &cam, QUANTITY_MULTIBOUNCE, NULL, albedo_of(1, 0, 4), -1, sm);
    static const char *const colours[3] = CH_MULTIBOUNCE_RGB;
    for (int c = 0; c < 3; ++c) {
        CHECK_MSG(identical_with_stderr(&env, diffuse[c], &mb, colours[c]), "%s vs %s", diffuse[c], colours[c]);
        CHECK_MSG(identical_with_stderr(&env, direct[c], &mb, CH_AO), "%s vs ao.V", direct[c]);
    }
    image_free(&env), image_free(&mb);
    scene_free(&s);

    load("builtin:boxes", 20, &s, &cam);
    env = render(&s, &cam, &reference_quantity_env_diffuse, &white, albedo_of(0, 0.3f, MULTIBOUNCE_UNLIMITED), -1, sm);
    mb = render(&s, &cam, QUANTITY_MULTIBOUNCE, NULL, albedo_of(0, 0.3f, MULTIBOUNCE_UNLIMITED), -1, sm);
    for (int c = 0; c < 3; ++c)
        CHECK_MSG(identical_with_stderr(&env, diffuse[c], &mb, CH_MULTIBOUNCE), "grey %s", diffuse[c]);
    const float *open = image_channel_data(&env, unoccluded[1]), *mask = image_channel_data(&env, CH_MASK);
    int not_one = 0;
    for (size_t i = 0; i < image_pixel_count(&env); ++i)
        not_one += mask[i] != 0.0f && open[i] != 1.0f;
    CHECK_MSG(not_one == 0, "%d pixels with unoccluded white light != 1", not_one);
    image_free(&env), image_free(&mb);
    scene_free(&s);
}

/* The unit direction through (u, v) of the map. */
static vec3 map_direction(float u, float v)
{
    return environment_uv_to_direction(u, v);
}

static int visible(const embree_scene *es, vec3 origin, vec3 d)
{
    _Alignas(16) struct RTCRay ray;
    embree_ray_init(&ray, origin, d, INFINITY);
    embree_unoccluded_stream(es, &ray, 1);
    return ray.tfar >= 0.0f;
}

static void test_sun_only_visibility(void)
{
    enum { W = 512, H = 256, ROW = 100, COLUMN = 330 }; /* 19 degrees up: long shadows */
    static float rgb[3 * W * H];
    for (int c = 0; c < 3; ++c)
        rgb[3 * (ROW * W + COLUMN) + c] = 1000.0f;
    scene s;
    camera cam;
    load("builtin:boxes", 32, &s, &cam);
    /* The light is built from pixels in memory, so the integrator is run
     * through the render loop directly. */
    environment_light light;
    memset(&light, 0, sizeof light);
    gt_error e;
    CHECK(environment_map_from_pixels(&light.map, "sun-only", W, H, rgb, &e) == 0);
    CHECK(environment_sampler_init(&light.sampler, &light.map, &e) == 0);
    light.brdf_fraction = 0.5f;
    light.scale_exponent = 11;
    embree_scene es;
    gbuffer gb;
    CHECK(embree_scene_build(&s, &es, &e) == 0);
    CHECK(gbuffer_render(&es, &cam, NORMAL_SHADING, 2, &gb, &e) == 0);
    environment_diffuse_plan plan;
    multibounce_settings mb = albedo_of(0, 0.5f, 0);
    CHECK(environment_diffuse_plan_init(&plan, &light, &mb, NORMAL_SHADING, &e) == 0);
    integrator it = environment_diffuse_integrator(&es, &plan);
    mc_film film; /* render_estimates initialises it */
    sampling_settings ss = {.spp = 256, .seed = 5, .threads = 2};
    render_stats stats;
    CHECK(render_estimates(&gb, &it, &ss, &film, &stats, &e) == 0);
    const float corners[5][2] = {{0.5f, 0.5f}, {0.02f, 0.02f}, {0.98f, 0.02f}, {0.02f, 0.98f}, {0.98f, 0.98f}};
    int lit = 0, shadowed = 0, penumbra = 0, wrong = 0;
    for (int i = 0; i < gb.width * gb.height; ++i) {
        if (!gb.mask[i])
            continue;
        const surface_hit *hit = &gb.hits[i];
        vec3 origin = offset_ray_origin(hit->p, hit->ng);
        int votes = 0, facing = 1;
        for (int k = 0; k < 5; ++k) {
            vec3 d = map_direction((COLUMN + corners[k][0]) / W, (ROW + corners[k][1]) / H);
            votes += v3_dot(d, hit->ng) > 0.0f && visible(&es, origin, d);
            facing &= v3_dot(d, hit->ns) > 0.0f;
        }
        double open = mc_film_mean(&film, 6 + 1, i), seen = mc_film_mean(&film, 3 + 1, i);
        if (!facing || !(open > 0.0))
            continue;
        if (votes != 0 && votes != 5) {
            ++penumbra;
            continue;
        }
        double expected = votes == 5 ? 1.0 : 0.0;
        wrong += seen / open != expected;
        lit += votes == 5, shadowed += votes == 0;
    }
    printf("  sun only: %d lit, %d shadowed, %d penumbra pixels; %d ratios off\n", lit, shadowed, penumbra, wrong);
    CHECK(wrong == 0);
    CHECK(lit > 20 && shadowed > 20);
    mc_film_free(&film);
    gbuffer_free(&gb);
    embree_scene_release(&es);
    environment_sampler_free(&light.sampler);
    environment_map_free(&light.map);
    scene_free(&s);
}

/* The same visible normals and weights G2 / G1 as specular-occlusion's,
 * times F = 1 and L = 1 exactly: the same sums. */
static void test_specular_white_dome(void)
{
    scene s;
    camera cam;
    load("builtin:corner", 16, &s, &cam);
    environment_render_settings white = named("white");
    white.f0 = 1.0f;
    const sampling sm = {64, 0, 2};
    image env = render(&s, &cam, &reference_quantity_env_specular, &white, albedo_of(1, 0, 0), 0.4f, sm);
    specular_occlusion_render_settings dome = specular_occlusion_render_settings_make(0.4f, ENVIRONMENT_WHITE);
    reference_request req = {.quantity = QUANTITY_SPECULAR_OCCLUSION,
                             .sampling = {64, 0, 17, 0.0, 2},
                             .normals = NORMAL_SHADING,
                             .settings = &dome.header};
    image so;
    gt_error e;
    CHECK(render_request(&s, &cam, &req, &so, &e) == 0);
    static const char *const spec[3] = CH_ENV_SPECULAR_RGB, *const spec_open[3] = CH_ENV_SPECULAR_UNOCCLUDED_RGB;
    const float *a = image_channel_data(&env, spec[1]), *b = image_channel_data(&so, CH_SPECOCC_OCCLUDED);
    const float *ao = image_channel_data(&env, spec_open[1]), *bo = image_channel_data(&so, CH_SPECOCC_UNOCCLUDED);
    const float *mask = image_channel_data(&env, CH_MASK);
    double worst = 0.0;
    for (size_t i = 0; a && b && ao && bo && i < image_pixel_count(&env); ++i)
        if (mask[i] != 0.0f)
            worst = fmax(worst, fmax(fabs(a[i] - b[i]), fabs(ao[i] - bo[i])));
    printf("  env-specular vs specular-occlusion under the white dome: largest difference %.3g\n", worst);
    CHECK(a && b && worst == 0.0);
    CHECK(identical_with_stderr(&env, spec[0], &so, CH_SPECOCC_OCCLUDED));
    CHECK(identical_with_stderr(&env, spec_open[2], &so, CH_SPECOCC_UNOCCLUDED));
    image_free(&env), image_free(&so);
    scene_free(&s);
}

static int all_identical(const image *a, const image *b)
{
    int same = a->channel_count == b->channel_count;
    for (int c = 0; same && c < a->channel_count; ++c)
        same = identical(a, a->channels[c].name, b, a->channels[c].name);
    return same;
}

static void test_determinism_and_merge(void)
{
    scene s;
    camera cam;
    load("builtin:boxes", 16, &s, &cam);
    environment_render_settings sky = named("sky");
    sky.rotate_degrees = 40.0f;
    const multibounce_settings mb = albedo_of(0, 0.5f, 2);
    image one = render(&s, &cam, &reference_quantity_env_diffuse, &sky, mb, -1, (sampling){64, 0, 1});
    image two = render(&s, &cam, &reference_quantity_env_diffuse, &sky, mb, -1, (sampling){64, 0, 2});
    CHECK_MSG(all_identical(&one, &two), "1 and 2 threads differ");
    image halves[2] = {render(&s, &cam, &reference_quantity_env_diffuse, &sky, mb, -1, (sampling){32, 0, 2}),
                       render(&s, &cam, &reference_quantity_env_diffuse, &sky, mb, -1, (sampling){32, 32, 2})};
    const char *names[2] = {"first half", "second half"};
    image merged;
    gt_error e;
    CHECK_MSG(reference_merge(&REFERENCE_REGISTRY_OF(&reference_quantity_env_diffuse), halves, names, 2, &merged,
                              &e) == 0,
              "%s", e.message);
    for (int c = 0; c < 3; ++c) {
        CHECK_MSG(identical_with_stderr(&one, diffuse[c], &merged, diffuse[c]), "merged %s", diffuse[c]);
        CHECK_MSG(identical_with_stderr(&one, unoccluded[c], &merged, unoccluded[c]), "merged %s", unoccluded[c]);
    }
    CHECK(strcmp(image_get_attribute(&merged, ATTR_ENVIRONMENT), "sky") == 0);
    image_free(&merged);
    environment_render_settings specular = named("sky");
    image s1 = render(&s, &cam, &reference_quantity_env_specular, &specular, mb, 0.3f, (sampling){32, 0, 1});
    image s2 = render(&s, &cam, &reference_quantity_env_specular, &specular, mb, 0.3f, (sampling){32, 0, 2});
    CHECK_MSG(all_identical(&s1, &s2), "env-specular: 1 and 2 threads differ");
    image_free(&s1), image_free(&s2);
    image_free(&halves[0]), image_free(&halves[1]), image_free(&one), image_free(&two);
    scene_free(&s);
}

static void test_bad_file(void)
{
    scene s;
    camera cam;
    load("builtin:corner", 8, &s, &cam);
    environment_render_settings bad = named("/nonexistent/sky.exr");
    bad.header.quantity = &reference_quantity_env_diffuse;
    bad.multibounce = albedo_of(0, 0.5f, 1);
    reference_request req = {.quantity = &reference_quantity_env_diffuse,
                             .sampling = {4, 0, 1, 0.0, 1},
                             .normals = NORMAL_SHADING,
                             .settings = &bad.header};
    image out;
    gt_error e;
    CHECK(render_request(&s, &cam, &req, &out, &e) != 0);
    CHECK_MSG(strstr(e.message, "/nonexistent/sky.exr") == e.message && !strchr(e.message, '\n'), "%s", e.message);
    printf("  bad file -> %s\n", e.message);
    scene_free(&s);
}

int main(void)
{
    test_white_dome_is_multibounce();
    test_sun_only_visibility();
    test_specular_white_dome();
    test_determinism_and_merge();
    test_bad_file();
    return check_report("test_environment_render");
}
