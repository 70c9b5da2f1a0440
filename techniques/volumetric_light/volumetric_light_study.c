/* The volumetric-light study; see volumetric_light_study.h. */
#include "volumetric_light/volumetric_light_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/atomic_file.h"
#include "core/files/image_io.h"
#include "core/progress.h"
#include "core/reference_schema.h"
#include "metrics/dither_metrics.h"
#include "metrics/image_error.h"
#include "metrics/flip.h"
#include "metrics/ssim.h"
#include "volumetric_light/volumetric_light_quality.h"
#include "volumetric_light/volumetric_light_upsample.h"
#include "volumetric_light/volumetric_light_shadow_map_render.h"
#include "volumetric_light/volumetric_light_setup.h"

volumetric_light_request volumetric_light_default_request(study_quality quality)
{
    const volumetric_light_quality *q = volumetric_light_quality_of(quality);
    volumetric_light_request rq = {.width = q->image_size, .height = q->image_size, .seeds = q->seeds,
                         .frames = q->frames, .alpha = 0.1, .shadow_size = 512, .shadow_bias = 0.01, .spp_count = 12,
                         .spp = {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 64, 128}, .blue_noise_size = q->blue_noise_size,
                         .reference_rel_tol = 1e-4, .cost_width = q->cost_width, .cost_height = q->cost_height,
                         .cost_reference_rel_tol = 1e-3};
    return rq;
}

/* What every measurement reads. */
typedef struct {
    const volumetric_light_request *rq;
    volumetric_light_setup v;
    float *reference, *frame, *history, *half, *half_distance;
    shadow_map shadows;
    blue_noise_texture blue[VOLUMETRIC_LIGHT_MAX_SEEDS];
    raymarch_lighting lighting;
    double reference_mean;
    float ssim_scale; /* SSIM sees values times 1 / the reference's 99th percentile */
    float *scaled[2], *blurred_reference;
    int threads;
    int score_flip; /* score() also computes FLIP (the equal-cost images) */
} volumetric_light_run;

typedef struct {
    double rmse, dssim, blurred, flip;
} image_score;

/* A Gaussian blur (sigma 1 pixel, 5 taps) of `in` over the mask's pixels,
 * the weights renormalised where taps leave the mask; tmp and out hold w*h. */
static void blur_masked(const float *in, const float *mask, int w, int h, float *tmp, float *out)
{
    static const double g[5] = {0.0544886845, 0.2442013420, 0.4026199469, 0.2442013420, 0.0544886845};
    for (int pass = 0; pass < 2; ++pass) {
        const float *src = pass ? tmp : in;
        float *dst = pass ? out : tmp;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double sum = 0.0, weight = 0.0;
                for (int k = -2; k <= 2; ++k) {
                    int xx = pass ? x : x + k, yy = pass ? y + k : y;
                    if (xx < 0 || yy < 0 || xx >= w || yy >= h || mask[yy * w + xx] == 0.0f)
                        continue;
                    sum += g[k + 2] * src[yy * w + xx], weight += g[k + 2];
                }
                dst[y * w + x] = weight > 0.0 ? (float)(sum / weight) : 0.0f;
            }
    }
}

static int score(volumetric_light_run *r, const float *image, image_score *out, gt_error *e)
{
    image_error_stats stats;
    ssim_result ssim;
    const volumetric_light_setup *v = &r->v;
    for (long p = 0; p < (long)v->gb.width * v->gb.height; ++p)
        r->scaled[0][p] = image[p] * r->ssim_scale, r->scaled[1][p] = r->reference[p] * r->ssim_scale;
    if (image_error_compute(image, r->reference, v->mask, v->gb.width, v->gb.height, "volumetric", &stats, e) != 0 ||
        ssim_compute(r->scaled[0], r->scaled[1], v->mask, v->gb.width, v->gb.height, "volumetric", NULL, &ssim, e) != 0)
        return -1;
    out->rmse = stats.rmse / r->reference_mean;
    out->dssim = ssim.dssim;
    out->flip = 0.0;
    if (r->score_flip) {
        flip_result f;
        if (flip_grey(r->scaled[1], r->scaled[0], v->mask, v->gb.width, v->gb.height, "volumetric", NULL, &f, e) != 0)
            return -1;
        out->flip = f.mean;
    }
    blur_masked(image, v->mask, v->gb.width, v->gb.height, r->scaled[0], r->scaled[1]);
    blur_masked(r->reference, v->mask, v->gb.width, v->gb.height, r->scaled[0], r->blurred_reference);
    if (image_error_compute(r->scaled[1], r->blurred_reference, v->mask, v->gb.width, v->gb.height, "volumetric",
                            &stats, e) != 0)
        return -1;
    out->blurred = stats.rmse / r->reference_mean;
    return 0;
}

/* Mean and standard error over the seeds. */
static volumetric_light_error summarise(const image_score *s, int n)
{
    double m[4] = {0.0, 0.0, 0.0, 0.0}, v[4] = {0.0, 0.0, 0.0, 0.0};
    for (int k = 0; k < n; ++k)
        m[0] += s[k].rmse / n, m[1] += s[k].dssim / n, m[2] += s[k].blurred / n, m[3] += s[k].flip / n;
    for (int k = 0; k < n && n > 1; ++k) {
        v[0] += pow(s[k].rmse - m[0], 2) / (n - 1), v[1] += pow(s[k].dssim - m[1], 2) / (n - 1);
        v[2] += pow(s[k].blurred - m[2], 2) / (n - 1), v[3] += pow(s[k].flip - m[3], 2) / (n - 1);
    }
    volumetric_light_error out = {m[0], sqrt(v[0] / n), m[1], sqrt(v[1] / n), m[2], sqrt(v[2] / n), m[3], sqrt(v[3] / n)};
    return out;
}

static int start_frame(int seed) { return 1009 * seed; }

/* One frame of the given noise and spp, full or half resolution (half 1:
 * bilinear depth-aware upsample, 2: the talk's noisy one). */
static void render_frame(volumetric_light_run *r, raymarch_noise noise, int spp, int seed, int frame, int half)
{
    const blue_noise_texture *blue = &r->blue[seed];
    if (!half) {
        raymarch_image(&r->lighting, &r->v.view, spp, noise, blue, frame, r->threads, r->frame);
        return;
    }
    raymarch_image_half(&r->lighting, &r->v.view, spp, noise, blue, frame, r->threads, r->half, r->half_distance);
    if (half == 2)
        raymarch_upsample_noisy(r->half, r->half_distance, &r->v.view, blue, frame, r->frame);
    else
        raymarch_upsample(r->half, r->half_distance, &r->v.view, r->frame);
}

/* The single frame and the accumulated history of one (noise, spp, seed). */
static int measure(volumetric_light_run *r, raymarch_noise noise, int spp, int seed, int half, image_score *single,
                   image_score *accumulated, gt_error *e)
{
    long n = (long)r->v.gb.width * r->v.gb.height;
    int frames = noise == RAYMARCH_NOISE_NONE ? 1 : r->rq->frames;
    for (int f = 0; f < frames; ++f) {
        render_frame(r, noise, spp, seed, start_frame(seed) + f, half);
        raymarch_accumulate(r->history, r->frame, n, r->rq->alpha, f == 0);
        if (f == 0 && score(r, r->frame, single, e) != 0)
            return -1;
    }
    return score(r, r->history, accumulated, e);
}

/* log-log interpolation of the spp at which the error curve reaches target. */
static double spp_to_reach(const volumetric_light_request *rq, const volumetric_light_error *curve, double target)
{
    for (int k = 0; k < rq->spp_count; ++k) {
        if (curve[k].rmse > target)
            continue;
        if (k == 0)
            return rq->spp[0];
        double a = log(curve[k - 1].rmse), b = log(curve[k].rmse), t = (log(target) - a) / (b - a);
        return exp(log(rq->spp[k - 1]) + t * (log(rq->spp[k]) - log(rq->spp[k - 1])));
    }
    return INFINITY;
}

static int measure_noises(volumetric_light_run *r, volumetric_light_result *out, image_score (*ratio_scores)[VOLUMETRIC_LIGHT_MAX_SEEDS],
                          image_score (*single_scores)[VOLUMETRIC_LIGHT_MAX_SEEDS], gt_error *e)
{
    const volumetric_light_request *rq = r->rq;
    for (int n = 0; n < RAYMARCH_NOISE_COUNT; ++n)
        for (int k = 0; k < rq->spp_count; ++k) {
            image_score single[VOLUMETRIC_LIGHT_MAX_SEEDS] = {{0}}, acc[VOLUMETRIC_LIGHT_MAX_SEEDS] = {{0}};
            int seeds = n == RAYMARCH_NOISE_NONE ? 1 : rq->seeds;
            for (int s = 0; s < seeds; ++s)
                if (measure(r, (raymarch_noise)n, rq->spp[k], s, 0, &single[s], &acc[s], e) != 0)
                    return -1;
            out->single[n][k] = summarise(single, seeds);
            out->accumulated[n][k] = summarise(acc, seeds);
            if (rq->spp[k] != 3)
                continue;
            memcpy(ratio_scores[n], acc, sizeof acc), memcpy(single_scores[n], single, sizeof single);
            for (int s = 0; s < VOLUMETRIC_LIGHT_MAX_SEEDS; ++s)
                out->rmse3_accumulated_by_seed[n][s] = s < seeds ? acc[s].rmse : NAN;
        }
    return 0;
}

/* Blue's accumulated RMSE and single-frame blurred RMSE over each other
 * noise's at 3 spp, per seed. */
static void blue_ratios(const volumetric_light_request *rq, image_score (*acc)[VOLUMETRIC_LIGHT_MAX_SEEDS],
                        image_score (*single)[VOLUMETRIC_LIGHT_MAX_SEEDS], volumetric_light_result *out)
{
    for (int n = RAYMARCH_NOISE_WHITE; n < RAYMARCH_NOISE_COUNT; ++n) {
        image_score ratio[VOLUMETRIC_LIGHT_MAX_SEEDS];
        for (int s = 0; s < rq->seeds; ++s) {
            ratio[s].rmse = acc[RAYMARCH_NOISE_BLUE][s].rmse / acc[n][s].rmse, ratio[s].dssim = ratio[s].flip = 0.0;
            ratio[s].blurred = single[RAYMARCH_NOISE_BLUE][s].blurred / single[n][s].blurred;
        }
        volumetric_light_error sum = summarise(ratio, rq->seeds);
        out->blue_ratio[n] = sum.rmse, out->blue_ratio_se[n] = sum.rmse_se;
        out->blue_blurred_ratio[n] = sum.blurred, out->blue_blurred_ratio_se[n] = sum.blurred_se;
        for (int s = 0; s < rq->seeds; ++s)
            ratio[s].blurred = single[RAYMARCH_NOISE_BLUE][s].blurred - single[n][s].blurred;
        sum = summarise(ratio, rq->seeds);
        out->blue_blurred_gap[n] = sum.blurred, out->blue_blurred_gap_se[n] = sum.blurred_se;
    }
}

/* The periodogram peak ratio of frame 0's error at 3 spp (relative to the
 * reference's mean, 0 off the surface). */
static int error_peak_ratio(volumetric_light_run *r, raymarch_noise noise, int seed, double *ratio, gt_error *e)
{
    const volumetric_light_setup *v = &r->v;
    int n = v->gb.width;
    if (v->gb.height != n)
        return gt_error_set(e, "volumetric", "the error spectrum needs a square image, not %dx%d", n, v->gb.height);
    double *error = malloc(sizeof(double) * (size_t)n * n);
    if (!error)
        return gt_error_set(e, "volumetric", "out of memory");
    render_frame(r, noise, 3, seed, start_frame(seed), 0);
    for (long p = 0; p < (long)n * n; ++p)
        error[p] = v->mask[p] != 0.0f ? (r->frame[p] - r->reference[p]) / r->reference_mean : 0.0;
    int rc = dither_spectrum_peak_ratio(error, n, ratio, e);
    free(error);
    return rc;
}

/* Each noise's error peak ratio at 3 spp, mean over the seeds, and over blue's per seed. */
static int measure_structure(volumetric_light_run *r, volumetric_light_result *out, gt_error *e)
{
    double peak[RAYMARCH_NOISE_COUNT][VOLUMETRIC_LIGHT_MAX_SEEDS];
    int seeds = r->rq->seeds;
    for (int n = 0; n < RAYMARCH_NOISE_COUNT; ++n)
        for (int s = 0; s < seeds; ++s)
            if (error_peak_ratio(r, (raymarch_noise)n, s, &peak[n][s], e) != 0)
                return -1;
    for (int n = 0; n < RAYMARCH_NOISE_COUNT; ++n) {
        image_score own[VOLUMETRIC_LIGHT_MAX_SEEDS] = {{0}}, over[VOLUMETRIC_LIGHT_MAX_SEEDS] = {{0}};
        for (int s = 0; s < seeds; ++s)
            own[s].rmse = peak[n][s], over[s].rmse = peak[n][s] / peak[RAYMARCH_NOISE_BLUE][s];
        volumetric_light_error a = summarise(own, seeds), b = summarise(over, seeds);
        out->peak_ratio[n] = a.rmse, out->peak_ratio_se[n] = a.rmse_se;
        out->peak_over_blue[n] = b.rmse, out->peak_over_blue_se[n] = b.rmse_se;
    }
    return 0;
}

static int measure_talk(volumetric_light_run *r, volumetric_light_result *out, gt_error *e)
{
    static const int talk_spp[VOLUMETRIC_LIGHT_TALK_SPP] = {3, 6, 9};
    for (int k = 0; k < VOLUMETRIC_LIGHT_TALK_SPP; ++k) {
        image_score single[VOLUMETRIC_LIGHT_MAX_SEEDS], acc[VOLUMETRIC_LIGHT_MAX_SEEDS];
        for (int s = 0; s < r->rq->seeds; ++s)
            if (measure(r, RAYMARCH_NOISE_BLUE, talk_spp[k], s, 1, &single[s], &acc[s], e) != 0)
                return -1;
        out->talk_spp[k] = talk_spp[k];
        out->talk[k] = summarise(acc, r->rq->seeds);
        out->talk_single[k] = summarise(single, r->rq->seeds);
        for (int s = 0; s < r->rq->seeds; ++s)
            if (measure(r, RAYMARCH_NOISE_BLUE, talk_spp[k], s, 2, &single[s], &acc[s], e) != 0)
                return -1;
        out->talk_noisy[k] = summarise(acc, r->rq->seeds);
    }
    return 0;
}

/* The shadow map's floor: 1024 steps per size. */
static int measure_shadow_sizes(volumetric_light_run *r, volumetric_light_result *out, gt_error *e)
{
    static const int sizes[VOLUMETRIC_LIGHT_SHADOW_SIZES] = {128, 256, 512, 1024};
    for (int k = 0; k < VOLUMETRIC_LIGHT_SHADOW_SIZES; ++k) {
        shadow_map m;
        double t0 = seconds_now();
        if (shadow_map_render(&r->v.es, &r->v.light, sizes[k], r->rq->shadow_bias, r->threads, &m, e) != 0)
            return -1;
        out->shadow_seconds[k] = seconds_now() - t0;
        raymarch_lighting l = {&r->v.light, &r->v.medium, &m, NULL};
        raymarch_image(&l, &r->v.view, 1024, RAYMARCH_NOISE_NONE, NULL, 0, r->threads, r->frame);
        shadow_map_free(&m);
        image_score sc;
        if (score(r, r->frame, &sc, e) != 0)
            return -1;
        out->shadow_sizes[k] = sizes[k];
        out->shadow_rmse[k] = sc.rmse;
    }
    return 0;
}

/* ---- Outputs: the image strip and the plot's data ---------------------------- */

static int write_png(const volumetric_light_run *r, const char *dir, const char *name, const float *plane, gt_error *e)
{
    char path[1024 + 64];
    snprintf(path, sizeof path, "%s/%s.png", dir, name);
    return image_write_preview(path, &plane, 1, r->v.gb.width, r->v.gb.height, (float)(0.5 / r->reference_mean), e);
}

static int write_strip(volumetric_light_run *r, const char *dir, gt_error *e)
{
    static const struct {
        const char *name;
        raymarch_noise noise;
        int spp, half, accumulate;
    } strip[] = {{"uniform_128", RAYMARCH_NOISE_NONE, 128, 0, 0}, {"uniform_24", RAYMARCH_NOISE_NONE, 24, 0, 0},
                 {"white_3", RAYMARCH_NOISE_WHITE, 3, 0, 0},      {"bayer_3", RAYMARCH_NOISE_BAYER, 3, 0, 0},
                 {"ign_3", RAYMARCH_NOISE_IGN, 3, 0, 0},          {"blue_3", RAYMARCH_NOISE_BLUE, 3, 0, 0},
                 {"blue_3_accumulated", RAYMARCH_NOISE_BLUE, 3, 0, 1}, {"talk_half_blue_6_accumulated", RAYMARCH_NOISE_BLUE, 6, 2, 1}};
    if (write_png(r, dir, "reference", r->reference, e) != 0)
        return -1;
    long n = (long)r->v.gb.width * r->v.gb.height;
    for (size_t k = 0; k < sizeof strip / sizeof strip[0]; ++k) {
        int frames = strip[k].accumulate ? r->rq->frames : 1;
        for (int f = 0; f < frames; ++f) {
            render_frame(r, strip[k].noise, strip[k].spp, 0, f, strip[k].half);
            raymarch_accumulate(r->history, r->frame, n, r->rq->alpha, f == 0);
        }
        if (write_png(r, dir, strip[k].name, r->history, e) != 0)
            return -1;
    }
    return 0;
}

static int write_plot_data(const volumetric_light_request *rq, const volumetric_light_result *out, const char *dir, gt_error *e)
{
    char path[1024 + 64];
    snprintf(path, sizeof path, "%s/error_vs_spp.dat", dir);
    atomic_file file;
    FILE *f = atomic_file_open(&file, path, "w", e);
    if (!f)
        return -1;
    fprintf(f, "# spp; then per noise (none white bayer ign blue): single-frame relative RMSE, accumulated\n");
    for (int k = 0; k < rq->spp_count; ++k) {
        fprintf(f, "%d", rq->spp[k]);
        for (int n = 0; n < RAYMARCH_NOISE_COUNT; ++n)
            fprintf(f, " %.6g %.6g", out->single[n][k].rmse, out->accumulated[n][k].rmse);
        fputc('\n', f);
    }
    return atomic_file_close(&file, f, e);
}

/* ---- The run ------------------------------------------------------------------ */

static int run_alloc(volumetric_light_run *r, const study_context *ctx, const volumetric_light_request *rq, gt_error *e)
{
    memset(r, 0, sizeof *r);
    r->rq = rq;
    r->threads = ctx->threads;
    if (rq->seeds < 1 || rq->seeds > VOLUMETRIC_LIGHT_MAX_SEEDS || rq->spp_count < 2 || rq->spp_count > VOLUMETRIC_LIGHT_MAX_SPP)
        return gt_error_set(e, "volumetric", "1..%d seeds and 2..%d spp counts", VOLUMETRIC_LIGHT_MAX_SEEDS, VOLUMETRIC_LIGHT_MAX_SPP);
    if (volumetric_light_setup_init(&r->v, rq->width, rq->height, ctx->threads, e) != 0)
        return -1;
    long n = (long)rq->width * rq->height;
    r->reference = malloc(sizeof(float) * n), r->frame = malloc(sizeof(float) * n);
    r->history = malloc(sizeof(float) * n), r->half = malloc(sizeof(float) * n);
    r->half_distance = malloc(sizeof(float) * n);
    r->scaled[0] = malloc(sizeof(float) * n), r->scaled[1] = malloc(sizeof(float) * n);
    r->blurred_reference = malloc(sizeof(float) * n);
    if (!r->reference || !r->frame || !r->history || !r->half || !r->half_distance || !r->scaled[0] || !r->scaled[1] ||
        !r->blurred_reference)
        return gt_error_set(e, "volumetric", "out of memory");
    for (int s = 0; s < rq->seeds; ++s)
        if (blue_noise_build(rq->blue_noise_size, 1, 1 + (uint64_t)s, &r->blue[s], e) != 0)
            return -1;
    if (shadow_map_render(&r->v.es, &r->v.light, rq->shadow_size, rq->shadow_bias, ctx->threads, &r->shadows, e) != 0)
        return -1;
    r->lighting = (raymarch_lighting){&r->v.light, &r->v.medium, &r->shadows, NULL};
    return 0;
}

static void run_free(volumetric_light_run *r)
{
    free(r->reference), free(r->frame), free(r->history), free(r->half), free(r->half_distance);
    free(r->scaled[0]), free(r->scaled[1]), free(r->blurred_reference);
    for (int s = 0; s < VOLUMETRIC_LIGHT_MAX_SEEDS; ++s)
        if (r->blue[s].values)
            blue_noise_free(&r->blue[s]);
    shadow_map_free(&r->shadows);
    volumetric_light_setup_free(&r->v);
}

static int reference_figures(volumetric_light_run *r, volumetric_light_result *out, gt_error *e)
{
    long n = (long)r->rq->width * r->rq->height;
    float *error = malloc(sizeof(float) * n);
    if (!error)
        return gt_error_set(e, "volumetric", "out of memory");
    double t0 = seconds_now(), sum = 0.0, worst = 0.0;
    out->reference_rays = volumetric_light_reference(&r->v, r->rq->reference_rel_tol, r->threads, r->reference, error);
    out->reference_seconds = seconds_now() - t0;
    for (long p = 0; p < n; ++p)
        if (r->v.mask[p] != 0.0f)
            sum += r->reference[p], worst = fmax(worst, error[p]), ++out->pixels;
    float p99 = 0.0f;
    int rc = metrics_percentile(r->reference, r->v.mask, (size_t)n, 99.0, "volumetric", &p99, e);
    free(error);
    if (rc != 0)
        return -1;
    r->ssim_scale = p99 > 0.0f ? 1.0f / p99 : 1.0f;
    r->reference_mean = out->pixels > 0 ? sum / out->pixels : 0.0;
    out->reference_mean = r->reference_mean;
    out->reference_max_error = worst;
    return r->reference_mean > 0.0 ? 0 : gt_error_set(e, "volumetric", "the light reaches no pixel");
}

/* The talk's configuration (6 spp at half resolution, blue noise, noisy
 * upsample, accumulated) per seed against 2 and 24 uniform steps, by
 * DSSIM and FLIP, on an image of cost_width x cost_height. */
static int measure_cost_configurations(volumetric_light_run *r, volumetric_light_result *out, gt_error *e)
{
    image_score talk[VOLUMETRIC_LIGHT_MAX_SEEDS], single, uniform2, uniform24, gap[VOLUMETRIC_LIGHT_MAX_SEEDS] = {{0}};
    int seeds = r->rq->seeds;
    if (measure(r, RAYMARCH_NOISE_NONE, 2, 0, 0, &uniform2, &single, e) != 0 ||
        measure(r, RAYMARCH_NOISE_NONE, 24, 0, 0, &uniform24, &single, e) != 0)
        return -1;
    for (int s = 0; s < seeds; ++s) {
        if (measure(r, RAYMARCH_NOISE_BLUE, 6, s, 2, &single, &talk[s], e) != 0)
            return -1;
        gap[s].dssim = talk[s].dssim - uniform2.dssim, gap[s].flip = talk[s].flip - uniform2.flip;
    }
    out->cost_talk = summarise(talk, seeds);
    out->cost_uniform2 = summarise(&uniform2, 1), out->cost_uniform24 = summarise(&uniform24, 1);
    volumetric_light_error g = summarise(gap, seeds);
    out->cost_dssim_gap = g.dssim, out->cost_dssim_gap_se = g.dssim_se;
    out->cost_flip_gap = g.flip, out->cost_flip_gap_se = g.flip_se;
    return 0;
}

static int measure_equal_cost(const study_context *ctx, const volumetric_light_request *rq, volumetric_light_result *out, gt_error *e)
{
    volumetric_light_request big = *rq;
    big.width = rq->cost_width, big.height = rq->cost_height, big.reference_rel_tol = rq->cost_reference_rel_tol;
    if (big.width < 2 || big.height < 2)
        return gt_error_set(e, "volumetric", "equal-cost image %dx%d too small", big.width, big.height);
    volumetric_light_result *scratch = calloc(1, sizeof *scratch); /* the reference's figures at this size */
    if (!scratch)
        return gt_error_set(e, "volumetric", "out of memory");
    volumetric_light_run r;
    int rc = run_alloc(&r, ctx, &big, e);
    r.score_flip = 1;
    rc = rc == 0 && reference_figures(&r, scratch, e) == 0 ? measure_cost_configurations(&r, out, e) : -1;
    out->cost_pixels = scratch->pixels, out->cost_reference_seconds = scratch->reference_seconds;
    run_free(&r);
    free(scratch);
    return rc;
}

static int run_study(volumetric_light_run *r, const study_context *ctx, volumetric_light_result *out, gt_error *e)
{
    char dir[1024];
    image_score ratio_scores[RAYMARCH_NOISE_COUNT][VOLUMETRIC_LIGHT_MAX_SEEDS];
    image_score single_scores[RAYMARCH_NOISE_COUNT][VOLUMETRIC_LIGHT_MAX_SEEDS];
    image_score single, acc;
    if (study_make_dir(ctx, VOLUMETRIC_LIGHT_DIR, dir, sizeof dir, e) != 0 || reference_figures(r, out, e) != 0 ||
        measure(r, RAYMARCH_NOISE_NONE, 128, 0, 0, &single, &acc, e) != 0)
        return -1;
    out->uniform128 = summarise(&single, 1);
    if (measure_noises(r, out, ratio_scores, single_scores, e) != 0 || measure_talk(r, out, e) != 0 ||
        measure_shadow_sizes(r, out, e) != 0)
        return -1;
    for (int n = 0; n < RAYMARCH_NOISE_COUNT; ++n) {
        out->spp_needed_single[n] = spp_to_reach(r->rq, out->single[n], out->uniform128.rmse);
        out->spp_needed_accumulated[n] = spp_to_reach(r->rq, out->accumulated[n], out->uniform128.rmse);
    }
    blue_ratios(r->rq, ratio_scores, single_scores, out);
    if (measure_structure(r, out, e) != 0 || write_strip(r, dir, e) != 0 ||
        write_plot_data(r->rq, out, dir, e) != 0 || measure_equal_cost(ctx, r->rq, out, e) != 0)
        return -1;
    return volumetric_light_bench(r->rq->width, r->rq->height, 32, &out->ns_per_pixel_sample, e);
}

int volumetric_light_study(const study_context *ctx, const volumetric_light_request *rq, volumetric_light_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->request = *rq;
    volumetric_light_run r;
    int rc = run_alloc(&r, ctx, rq, e) == 0 ? run_study(&r, ctx, out, e) : -1;
    run_free(&r);
    return rc;
}

/* Repeats frames for at least 0.2 s on one thread. */
static double time_frames(const volumetric_light_setup *v, const shadow_map *m, const blue_noise_texture *blue, int steps,
                          float *out)
{
    raymarch_lighting l = {&v->light, &v->medium, m, NULL};
    double t0 = seconds_now();
    int frames = 0;
    do
        raymarch_image(&l, &v->view, steps, RAYMARCH_NOISE_BLUE, blue, frames++, 1, out);
    while (seconds_now() - t0 < 0.2);
    return 1e9 * (seconds_now() - t0) / ((double)frames * v->gb.width * v->gb.height * steps);
}

int volumetric_light_bench(int width, int height, int steps, double *ns_per_pixel_sample, gt_error *e)
{
    volumetric_light_setup v;
    shadow_map m = {0};
    blue_noise_texture blue = {0};
    if (volumetric_light_setup_init(&v, width, height, 1, e) != 0)
        return -1;
    float *out = malloc(sizeof(float) * (size_t)width * height);
    int rc = out ? 0 : gt_error_set(e, "volumetric", "out of memory");
    if (rc == 0)
        rc = shadow_map_render(&v.es, &v.light, 512, 0.01, 1, &m, e);
    if (rc == 0)
        rc = blue_noise_build(64, 1, 1, &blue, e);
    if (rc == 0)
        *ns_per_pixel_sample = time_frames(&v, &m, &blue, steps, out);
    free(out);
    if (blue.values)
        blue_noise_free(&blue);
    shadow_map_free(&m);
    volumetric_light_setup_free(&v);
    return rc;
}

static int approx_frames(const volumetric_light_approx_request *rq, const volumetric_light_setup *v, const shadow_map *m,
                         const blue_noise_texture *blue, float *history, gt_error *e)
{
    long n = (long)rq->width * rq->height;
    float *frame = malloc(sizeof(float) * n), *half = malloc(sizeof(float) * n), *half_d = malloc(sizeof(float) * n);
    int rc = frame && half && half_d ? 0 : gt_error_set(e, "volumetric", "out of memory");
    raymarch_lighting l = {&v->light, &v->medium, m, NULL};
    for (int f = 0; f < rq->frames && rc == 0; ++f) {
        if (rq->half) {
            raymarch_image_half(&l, &v->view, rq->steps, rq->noise, blue, f, rq->threads, half, half_d);
            if (rq->half == 2)
                raymarch_upsample_noisy(half, half_d, &v->view, blue, f, frame);
            else
                raymarch_upsample(half, half_d, &v->view, frame);
        } else
            raymarch_image(&l, &v->view, rq->steps, rq->noise, blue, f, rq->threads, frame);
        raymarch_accumulate(history, frame, n, rq->alpha, f == 0);
    }
    free(frame), free(half), free(half_d);
    return rc;
}

static int approx_channels(const volumetric_light_setup *v, const float *history, image *out, gt_error *e)
{
    static const char *const names[3] = CH_VLIGHT_L_RGB;
    if (image_init(out, v->gb.width, v->gb.height) != 0)
        return gt_error_set(e, "volumetric", "out of memory");
    for (int c = 0; c < 3; ++c) {
        float *plane = image_add_channel(out, names[c]);
        if (!plane) {
            image_free(out);
            return gt_error_set(e, "volumetric", "out of memory");
        }
        for (size_t p = 0; p < image_pixel_count(out); ++p)
            plane[p] = (float)(v->light.intensity[c] * history[p]);
    }
    return 0;
}

int volumetric_light_approx_image(const volumetric_light_approx_request *rq, image *out, gt_error *e)
{
    volumetric_light_setup v;
    shadow_map m = {0};
    blue_noise_texture blue = {0};
    if (volumetric_light_setup_init(&v, rq->width, rq->height, rq->threads, e) != 0)
        return -1;
    float *history = malloc(sizeof(float) * (size_t)rq->width * rq->height);
    int rc = history ? 0 : gt_error_set(e, "volumetric", "out of memory");
    if (rc == 0)
        rc = shadow_map_render(&v.es, &v.light, rq->shadow_size, 0.01, rq->threads, &m, e);
    if (rc == 0)
        rc = blue_noise_build(64, 1, 1, &blue, e);
    if (rc == 0)
        rc = approx_frames(rq, &v, &m, &blue, history, e);
    if (rc == 0)
        rc = approx_channels(&v, history, out, e);
    free(history);
    if (blue.values)
        blue_noise_free(&blue);
    shadow_map_free(&m);
    volumetric_light_setup_free(&v);
    return rc;
}
