/* The AO reference with the height-field control variate
 * (`--control-variate heightfield`, techniques/ao/ao_control_variate.h):
 *  - unbiased on every built-in scene: per pixel, the mean over several
 *    seeds equals plain sampling's within standard errors (the image-mean
 *    difference within 4 of its standard errors, no pixel beyond 6 and the
 *    allowance for events none of its samples met);
 *  - on the plane ao.V = ao.Vuniform = 1 exactly with standard error 0;
 *  - on a scene the height field misses entirely (a ceiling above a floor,
 *    out of the camera's view), no worse than plain: standard errors within
 *    the 10% margin, means within standard errors;
 *  - bit-identical for 1 and 2 threads, parts over sample blocks merge into
 *    the whole render's bits, and a plain part does not merge with a
 *    control-variate part. */
#include <math.h>
#include <string.h>

#include "core/reference_schema.h"
#include "raytracer/reference_merge.h"
#include "ao/ao_quantity.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

enum { SIZE = 20, SEEDS = 4, SPP = 128 };

static image render(const scene *s, const camera *cam, ao_control_variate cv, int spp, uint32_t offset, uint32_t seed,
                    int threads)
{
    gt_error e;
    image img = {0};
    ao_render_settings ao = ao_render_settings_defaults();
    ao.control_variate = cv;
    reference_request req = {.quantity = QUANTITY_AO,
                             .sampling = {.spp = spp, .sample_offset = offset, .seed = seed, .threads = threads},
                             .normals = NORMAL_SHADING, .settings = &ao.header};
    render_stats stats;
    if (reference_render(s, s->name, cam, &req, &img, &stats, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        CHECK(0);
    }
    return img;
}

/* Per pixel, the mean of a channel over SEEDS renders and its standard error. */
typedef struct {
    double mean[SIZE * SIZE], se[SIZE * SIZE];
    float mask[SIZE * SIZE];
} seed_means;

static void mean_over_seeds(const scene *s, const camera *cam, ao_control_variate cv, const char *channel,
                            uint32_t first_seed, seed_means *out)
{
    char se_name[64];
    snprintf(se_name, sizeof se_name, "%s.stderr", channel);
    memset(out, 0, sizeof *out);
    for (int k = 0; k < SEEDS; ++k) {
        image img = render(s, cam, cv, SPP, 0, first_seed + (uint32_t)k, 2);
        const float *v = image_channel_data(&img, channel), *se = image_channel_data(&img, se_name);
        memcpy(out->mask, image_channel_data(&img, CH_MASK), sizeof out->mask);
        for (int i = 0; i < SIZE * SIZE; ++i) {
            out->mean[i] += v[i] / SEEDS;
            out->se[i] += (double)se[i] * se[i] / (SEEDS * SEEDS);
        }
        image_free(&img);
    }
    for (int i = 0; i < SIZE * SIZE; ++i)
        out->se[i] = sqrt(out->se[i]);
}

static void check_unbiased(const char *name, const scene *s, const camera *cam, const char *channel)
{
    static seed_means plain, cv;
    mean_over_seeds(s, cam, AO_CONTROL_VARIATE_NONE, channel, 100, &plain);
    mean_over_seeds(s, cam, AO_CONTROL_VARIATE_HEIGHTFIELD, channel, 200, &cv);
    double sum = 0.0, var = 0.0, cv_var = 0.0, plain_var = 0.0;
    int n = 0, far = 0;
    for (int i = 0; i < SIZE * SIZE; ++i) {
        if (plain.mask[i] == 0.0f)
            continue;
        double d = cv.mean[i] - plain.mean[i], se2 = cv.se[i] * cv.se[i] + plain.se[i] * plain.se[i];
        sum += d, var += se2, ++n;
        cv_var += cv.se[i] * cv.se[i], plain_var += plain.se[i] * plain.se[i];
        /* A pixel's standard error misses events its samples never met: a
         * region of g = 0 of measure p goes unseen in N samples with
         * probability (1 - p)^N, leaving a corrected mean off by up to about
         * p with standard error 0. Allow 6 / N on top (p < 6 / N is unseen
         * with probability up to e^-6 only beyond it). */
        far += fabs(d) > 6.0 * sqrt(se2) + 6.0 / (SEEDS * SPP);
    }
    double mean_d = sum / n, se_d = sqrt(var) / n;
    printf("%-16s %-12s mean difference %+.5f (se %.5f), variance cv/plain %.3f\n", name, channel, mean_d, se_d,
           cv_var / plain_var);
    CHECK_MSG(n > 50, "%s: only %d covered pixels", name, n);
    CHECK_MSG(fabs(mean_d) <= 4.0 * se_d, "%s %s: control variate minus plain %+.5f, %.1f standard errors", name,
              channel, mean_d, fabs(mean_d) / se_d);
    CHECK_MSG(far == 0, "%s %s: %d pixels more than 6 standard errors apart", name, channel, far);
}

static void test_unbiased_on_builtin_scenes(void)
{
    for (int b = 0; b < builtin_study_scene_count(); ++b) {
        const char *name = builtin_study_scene_at(b)->name;
        gt_error e;
        scene s;
        camera cam;
        char spec[64];
        snprintf(spec, sizeof spec, "builtin:%s", name);
        CHECK(scene_load(spec, &s, &e) == 0);
        CHECK(scene_choose_camera(&s, NULL, SIZE, SIZE, &cam, &e) == 0);
        check_unbiased(name, &s, &cam, CH_AO);
        check_unbiased(name, &s, &cam, CH_AO_UNIFORM);
        scene_free(&s);
    }
}

static void test_plane_exact(void)
{
    gt_error e;
    scene s;
    camera cam;
    CHECK(scene_load("builtin:plane", &s, &e) == 0);
    CHECK(scene_choose_camera(&s, NULL, 48, 48, &cam, &e) == 0);
    image img = render(&s, &cam, AO_CONTROL_VARIATE_HEIGHTFIELD, 256, 0, 3, 2);
    const char *const channels[4] = {"ao.V", "ao.Vuniform", "ao.V.stderr", "ao.Vuniform.stderr"};
    const float *mask = image_channel_data(&img, CH_MASK);
    int covered = 0, off = 0;
    for (int i = 0; i < 48 * 48; ++i) {
        if (mask[i] == 0.0f)
            continue;
        ++covered;
        for (int c = 0; c < 4; ++c)
            off += image_channel_data(&img, channels[c])[i] != (c < 2 ? 1.0f : 0.0f);
    }
    CHECK_MSG(covered > 1000, "plane: %d covered pixels", covered);
    CHECK_MSG(off == 0, "plane: %d values other than AO 1 with standard error 0", off);
    image_free(&img);
    scene_free(&s);
}

/* A quad at height y, x and z in [-10, 10], its normal +Y or -Y. */
static int add_quad(scene *s, float y, float normal_y)
{
    scene_mesh *m = scene_add_mesh(s, 4, 2, 0);
    if (!m)
        return -1;
    static const float corner[4][2] = {{-10, -10}, {10, -10}, {10, 10}, {-10, 10}};
    for (int k = 0; k < 4; ++k) {
        float *p = &m->positions[3 * k], *n = &m->normals[3 * k];
        p[0] = corner[k][0], p[1] = y, p[2] = corner[k][1];
        n[0] = 0.0f, n[1] = normal_y, n[2] = 0.0f;
    }
    static const uint32_t up[6] = {0, 2, 1, 0, 3, 2}, down[6] = {0, 1, 2, 0, 2, 3};
    memcpy(m->indices, normal_y > 0.0f ? up : down, sizeof up);
    return 0;
}

static void test_hidden_occluder(void)
{
    scene s = {0};
    snprintf(s.name, sizeof s.name, "floor under a hidden ceiling");
    CHECK(add_quad(&s, 0.0f, 1.0f) == 0 && add_quad(&s, 1.5f, -1.0f) == 0);
    /* Looking down 22 degrees, 20 degrees half-field: the ceiling stays out of view. */
    camera cam = {v3(0.0f, 1.2f, 2.0f), v3(0.0f, 0.0f, -1.0f), v3(0.0f, 1.0f, 0.0f), 40.0f * (float)M_PI / 180.0f,
                  32, 32};
    image plain = render(&s, &cam, AO_CONTROL_VARIATE_NONE, 256, 0, 5, 2);
    image cv = render(&s, &cam, AO_CONTROL_VARIATE_HEIGHTFIELD, 256, 0, 6, 2);
    const float *mask = image_channel_data(&plain, CH_MASK);
    double sum_plain = 0.0, sum_cv = 0.0, var_plain = 0.0, var_cv = 0.0;
    int n = 0;
    for (int i = 0; i < 32 * 32; ++i) {
        if (mask[i] == 0.0f)
            continue;
        double sp = image_channel_data(&plain, "ao.V.stderr")[i], sc = image_channel_data(&cv, "ao.V.stderr")[i];
        sum_plain += image_channel_data(&plain, "ao.V")[i], sum_cv += image_channel_data(&cv, "ao.V")[i];
        var_plain += sp * sp, var_cv += sc * sc, ++n;
    }
    double se = sqrt(var_plain + var_cv) / n;
    printf("hidden occluder: AO plain %.4f, control variate %.4f (se %.4f); stderr ratio %.3f\n", sum_plain / n,
           sum_cv / n, se, sqrt(var_cv / var_plain));
    CHECK_MSG(n > 200 && sum_plain / n < 0.8, "the ceiling must occlude (AO %.3f over %d pixels)", sum_plain / n, n);
    CHECK(fabs(sum_cv - sum_plain) / n <= 4.0 * se);
    CHECK_MSG(sqrt(var_cv / var_plain) <= 1.1, "control variate's standard error %.3f times plain's",
              sqrt(var_cv / var_plain));
    image_free(&plain);
    image_free(&cv);
    scene_free(&s);
}

static int identical(const image *a, const image *b)
{
    if (a->channel_count != b->channel_count)
        return 0;
    for (int c = 0; c < a->channel_count; ++c) {
        const float *x = image_channel_data(a, a->channels[c].name), *y = image_channel_data(b, a->channels[c].name);
        if (!y || memcmp(x, y, sizeof(float) * image_pixel_count(a)) != 0) {
            fprintf(stderr, "channel %s differs\n", a->channels[c].name);
            return 0;
        }
    }
    return 1;
}

static void test_determinism_and_merge(void)
{
    gt_error e;
    scene s;
    camera cam;
    CHECK(scene_load("builtin:boxes", &s, &e) == 0);
    CHECK(scene_choose_camera(&s, NULL, 24, 24, &cam, &e) == 0);
    image one = render(&s, &cam, AO_CONTROL_VARIATE_HEIGHTFIELD, 64, 0, 9, 1);
    image two = render(&s, &cam, AO_CONTROL_VARIATE_HEIGHTFIELD, 64, 0, 9, 2);
    CHECK_MSG(identical(&one, &two), "1 and 2 threads differ");
    image parts[2] = {render(&s, &cam, AO_CONTROL_VARIATE_HEIGHTFIELD, 32, 0, 9, 2),
                      render(&s, &cam, AO_CONTROL_VARIATE_HEIGHTFIELD, 32, 32, 9, 2)};
    const char *names[2] = {"first", "second"};
    image merged;
    CHECK(reference_merge(&REFERENCE_REGISTRY_OF(QUANTITY_AO), parts, names, 2, &merged, &e) == 0);
    CHECK_MSG(identical(&merged, &one), "merged parts differ from the whole render");
    CHECK(strcmp(image_get_attribute(&merged, ATTR_CONTROL_VARIATE), "heightfield") == 0);
    image mixed[2] = {parts[0], render(&s, &cam, AO_CONTROL_VARIATE_NONE, 32, 32, 9, 2)};
    image refused = {0};
    CHECK(reference_merge(&REFERENCE_REGISTRY_OF(QUANTITY_AO), mixed, names, 2, &refused, &e) != 0);
    CHECK_MSG(strstr(e.message, ATTR_CONTROL_VARIATE) != NULL, "refusal names the attribute: %s", e.message);
    image_free(&mixed[1]);
    image_free(&merged);
    for (int k = 0; k < 2; ++k)
        image_free(&parts[k]);
    image_free(&one);
    image_free(&two);
    scene_free(&s);
}

int main(void)
{
    test_plane_exact();
    test_hidden_occluder();
    test_determinism_and_merge();
    test_unbiased_on_builtin_scenes();
    return check_report("test_ao_control_variate");
}
