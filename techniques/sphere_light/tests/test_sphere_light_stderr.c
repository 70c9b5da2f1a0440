/* Issue 23's reproduction at a small size: the sphere light at (0.3, 0.6,
 * 0.2), radius 0.5, over builtin:plane, whose lit pixels span three decades
 * and more. Standard errors are right on the dim pixels too:
 *   - no lit pixel reports a standard error of 0 (before the fix 9 in 10
 *     did: their squares fell below the grid set by the brightest pixels);
 *   - the reported errors cover the spread between independent seeds: the
 *     estimators of two seeds differ by more than 4 combined standard errors
 *     at no pixel, bright or dim (scrambled Sobol' points do better than
 *     the independent samples the formula assumes, so this bounds the
 *     errors from below only);
 *   - the standard error is the samples' own, to 1e-6, on every lit pixel:
 *     against the long-double variance of its samples rendered one by one;
 *   - with a target (absolute, or relative to the mean), the pixels that
 *     stop early stop at a power of two >= 64 with the target met, and their
 *     actual errors against a converged render of another seed are within 4
 *     times the target (the usual 4-sigma rule);
 *   - merged sample blocks give the bits of the whole render, also through
 *     EXR files, and the thread count changes no bit. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/statistics/mc_film.h"
#include "core/reference_schema.h"
#include "raytracer/reference_merge.h"
#include "sphere_light/sphere_light_quantity.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

static scene test_scene;

typedef struct {
    int size, spp, threads;
    uint32_t seed, offset;
    double target, target_rel;
} render_setup;

static image render(render_setup r)
{
    camera cam;
    gt_error e;
    image img = {0};
    reference_request req;
    memset(&req, 0, sizeof req);
    req.quantity = QUANTITY_SPHERE_LIGHT;
    req.sampling = (sampling_settings){.spp = r.spp, .sample_offset = r.offset, .seed = r.seed,
                                       .target_stderr = r.target, .threads = r.threads,
                                       .target_rel_stderr = r.target_rel};
    req.normals = NORMAL_SHADING;
    sphere_light_quantity_settings light =
        sphere_light_quantity_settings_of((sphere_light_settings){v3(0.3f, 0.6f, 0.2f), 0.5f, 1.0f, 0});
    req.settings = &light.header;
    render_stats stats;
    if (scene_choose_camera(&test_scene, NULL, r.size, r.size, &cam, &e) != 0 ||
        reference_render(&test_scene, "builtin:plane", &cam, &req, &img, &stats, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        CHECK(0);
    }
    return img;
}

static const float *channel(const image *img, const char *name)
{
    const float *data = image_channel_data(img, name);
    CHECK_MSG(data != NULL, "no channel %s", name);
    return data;
}

/* 2^(E-25): how far the grid moves a mean (core/statistics/mc_film.h), E from the header. */
static double grid_bound(const image *img)
{
    const char *text = image_get_attribute(img, ATTR_EXPONENTS);
    const char *at = text ? strstr(text, CH_SPHERE_R ":") : NULL;
    int exponent = 0;
    CHECK(at && sscanf(at + strlen(CH_SPHERE_R ":"), "%d", &exponent) == 1);
    return ldexp(1.0, exponent - 25);
}

/* The estimator's own means, sum / n from the moment sums, unrounded by
 * the grid of the mean channel (within 2^(E-25) of it: tests/core). */
static double *estimator_means(const image *img)
{
    mc_film film;
    gt_error e;
    if (mc_film_read_channels(img, "render", &film, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        CHECK(0);
        return NULL;
    }
    double *means = calloc(image_pixel_count(img), sizeof *means);
    for (size_t i = 0; means && i < image_pixel_count(img); ++i)
        means[i] = film.count[i] ? moment_sums_total(&film.moments[i]) / film.count[i] : 0.0;
    mc_film_free(&film);
    return means;
}

static void test_dim_pixels_and_seeds(void)
{
    image a = render((render_setup){.size = 40, .spp = 256, .threads = 2, .seed = 1});
    image b = render((render_setup){.size = 40, .spp = 256, .threads = 2, .seed = 2});
    const float *channel_a = channel(&a, CH_SPHERE_R), *err_a = channel(&a, CH_SPHERE_R ".stderr");
    const float *err_b = channel(&b, CH_SPHERE_R ".stderr");
    double *mean_a = estimator_means(&a), *mean_b = estimator_means(&b);
    if (!mean_a || !mean_b)
        return;
    double brightest = 0.0;
    for (size_t i = 0; i < image_pixel_count(&a); ++i)
        brightest = fmax(brightest, mean_a[i]);
    int lit = 0, dim = 0, zero = 0, beyond = 0, dim_beyond = 0;
    double z2 = 0.0, dim_z2 = 0.0;
    for (size_t i = 0; i < image_pixel_count(&a); ++i) {
        if (!(channel_a[i] > 0.0f))
            continue;
        int is_dim = mean_a[i] < 0.01 * brightest;
        double combined = sqrt((double)err_a[i] * err_a[i] + (double)err_b[i] * err_b[i]);
        double z = fabs(mean_a[i] - mean_b[i]) / combined;
        lit++, dim += is_dim, zero += !(err_a[i] > 0.0f);
        beyond += z > 4.0, dim_beyond += is_dim && z > 4.0;
        z2 += z * z, dim_z2 += is_dim ? z * z : 0.0;
    }
    printf("%d lit pixels (%d below 1%% of the brightest, %.3g): %d with standard error 0; seeds differ beyond 4 "
           "sigma at %d (%d dim); mean z^2 %.3g (dim %.3g)\n",
           lit, dim, brightest, zero, beyond, dim_beyond, z2 / lit, dim_z2 / dim);
    CHECK_MSG(lit > 1000 && dim > 300, "the image lacks the issue's dim pixels (%d lit, %d dim)", lit, dim);
    CHECK_MSG(zero == 0, "%d lit pixels report a standard error of 0", zero);
    CHECK_MSG(beyond == 0, "%d pixels differ between seeds by more than 4 standard errors", beyond);
    /* Scrambled Sobol' points do better than independent samples, so z^2
     * averages below 1; above it the errors would be too small. */
    CHECK_MSG(z2 / lit < 1.0 && dim_z2 / dim < 1.0, "mean z^2 %.3g, dim %.3g", z2 / lit, dim_z2 / dim);
    free(mean_a);
    free(mean_b);
    image_free(&a);
    image_free(&b);
}

/* The standard error is the samples' own: 64 renders of one sample each
 * give every pixel's samples (exact in their moment sums: a float is within
 * 2^24 of itself), whose variance in long double must match the 64-sample
 * render's standard error. */
static void test_stderr_of_the_samples(void)
{
    enum { SIZE = 24, N = 64 };
    static double values[N][SIZE * SIZE];
    for (int k = 0; k < N; ++k) {
        image one = render((render_setup){.size = SIZE, .spp = 1, .threads = 2, .seed = 5, .offset = (uint32_t)k});
        double *v = estimator_means(&one);
        if (v)
            memcpy(values[k], v, sizeof values[k]);
        free(v);
        image_free(&one);
    }
    image all = render((render_setup){.size = SIZE, .spp = N, .threads = 2, .seed = 5});
    const float *err = channel(&all, CH_SPHERE_R ".stderr"), *mean = channel(&all, CH_SPHERE_R);
    int compared = 0, off = 0, dim = 0;
    for (int i = 0; i < SIZE * SIZE; ++i) {
        if (!(mean[i] > 0.0f))
            continue;
        long double sum = 0, ss = 0;
        for (int k = 0; k < N; ++k)
            sum += values[k][i];
        for (int k = 0; k < N; ++k)
            ss += (values[k][i] - sum / N) * (values[k][i] - sum / N);
        double want = (double)sqrtl(ss / (N - 1) / N);
        compared++, dim += mean[i] < 1e-3f;
        if (!(fabs(err[i] - want) <= 1e-6 * want) && off++ < 5)
            fprintf(stderr, "pixel %d: standard error %.9g, of the samples %.9g\n", i, err[i], want);
    }
    CHECK_MSG(compared > 300 && dim > 200, "%d pixels compared, %d dim", compared, dim);
    CHECK_MSG(off == 0, "%d standard errors differ from their samples'", off);
    image_free(&all);
}

/* Stopped pixels: at a power of two >= 64, the target met, and the actual
 * error against the converged render within 4 targets (plus the grids). */
static void check_stopped(const image *adaptive, const image *converged, int spp, double target, double target_rel)
{
    const float *mean = channel(adaptive, CH_SPHERE_R), *err = channel(adaptive, CH_SPHERE_R ".stderr");
    const float *n = channel(adaptive, CH_SPP), *truth = channel(converged, CH_SPHERE_R);
    const float *truth_err = channel(converged, CH_SPHERE_R ".stderr"), *mask = channel(adaptive, CH_MASK);
    double grid = grid_bound(adaptive);
    int stopped = 0, unmet = 0, beyond = 0, dim = 0;
    for (size_t i = 0; i < image_pixel_count(adaptive); ++i) {
        int count = (int)n[i];
        if (mask[i] == 0.0f || count >= spp)
            continue;
        double allowed = target > 0.0 ? target : target_rel * fabs(truth[i]);
        stopped++;
        dim += mean[i] < 1e-3f;
        unmet += count < 64 || (count & (count - 1)) != 0 ||
                 !(err[i] <= (target > 0.0 ? target : target_rel * fabs(mean[i]) * (1.0 + 1e-6)));
        beyond += !(fabs((double)mean[i] - truth[i]) <=
                    4.0 * sqrt(allowed * allowed + (double)truth_err[i] * truth_err[i]) + 2.0 * grid);
    }
    printf("target %g, relative %g: %d pixels stopped early (%d dim), %d beyond 4 targets\n", target, target_rel,
           stopped, dim, beyond);
    CHECK_MSG(stopped > 100 && dim > 10, "too few pixels stopped early (%d, %d dim) to test the rule", stopped, dim);
    CHECK_MSG(unmet == 0, "%d pixels stopped without meeting the rule", unmet);
    CHECK_MSG(beyond == 0, "%d stopped pixels are off by more than 4 targets", beyond);
}

static void test_stop_rule(void)
{
    image converged = render((render_setup){.size = 24, .spp = 4096, .threads = 2, .seed = 9});
    image absolute = render((render_setup){.size = 24, .spp = 1024, .threads = 2, .seed = 1, .target = 1e-5});
    image relative = render((render_setup){.size = 24, .spp = 1024, .threads = 2, .seed = 1, .target_rel = 0.03});
    check_stopped(&absolute, &converged, 1024, 1e-5, 0.0);
    check_stopped(&relative, &converged, 1024, 0.0, 0.03);
    image_free(&converged);
    image_free(&absolute);
    image_free(&relative);
}

static int identical(const image *a, const image *b)
{
    if (a->channel_count != b->channel_count)
        return 0;
    for (int c = 0; c < a->channel_count; ++c) {
        const float *x = a->channels[c].data, *y = image_channel_data(b, a->channels[c].name);
        if (!y || memcmp(x, y, sizeof(float) * image_pixel_count(a)) != 0) {
            fprintf(stderr, "channel %s differs\n", a->channels[c].name);
            return 0;
        }
    }
    return 1;
}

/* Blocks whose pixels peak differently merge into the whole render's bits. */
static void test_merge_and_threads(void)
{
    image whole = render((render_setup){.size = 24, .spp = 96, .threads = 2, .seed = 3});
    image one = render((render_setup){.size = 24, .spp = 96, .threads = 1, .seed = 3});
    CHECK_MSG(identical(&whole, &one), "1 and 2 threads differ");
    image parts[3] = {render((render_setup){.size = 24, .spp = 64, .threads = 2, .seed = 3, .offset = 32}),
                      render((render_setup){.size = 24, .spp = 16, .threads = 2, .seed = 3, .offset = 16}),
                      render((render_setup){.size = 24, .spp = 16, .threads = 2, .seed = 3})};
    const char *names[3] = {"samples 32..95", "samples 16..31", "samples 0..15"};
    image merged, reread[3], merged_files;
    gt_error e;
    const reference_registry *quantities = &REFERENCE_REGISTRY_OF(QUANTITY_SPHERE_LIGHT);
    CHECK_MSG(reference_merge(quantities, parts, names, 3, &merged, &e) == 0, "%s", e.message);
    CHECK_MSG(identical(&whole, &merged), "merged blocks differ from the whole render");
    for (int k = 0; k < 3; ++k) {
        char path[512];
        snprintf(path, sizeof path, "%s/sphere_stderr_part%d.exr", check_tmp_dir(), k);
        CHECK(exr_write(path, &parts[2 - k], &e) == 0 && exr_read(path, &reread[k], &e) == 0);
    }
    CHECK_MSG(reference_merge(quantities, reread, names, 3, &merged_files, &e) == 0, "%s", e.message);
    CHECK_MSG(identical(&whole, &merged_files), "blocks merged through files differ from the whole render");
    for (int k = 0; k < 3; ++k) {
        image_free(&parts[k]);
        image_free(&reread[k]);
    }
    image_free(&merged);
    image_free(&merged_files);
    image_free(&whole);
    image_free(&one);
}

int main(void)
{
    gt_error e;
    if (scene_load("builtin:plane", &test_scene, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return 1;
    }
    test_dim_pixels_and_seeds();
    test_stderr_of_the_samples();
    test_stop_rule();
    test_merge_and_threads();
    scene_free(&test_scene);
    return check_report("test_sphere_light_stderr");
}
