#include "raytracer/render_loop.h"

#include <limits.h>
#include <math.h>
#include <signal.h>

#include "core/progress.h"
#include "raytracer/distributed_render.h"

enum { MAX_QUANTITIES = MC_FILM_MAX_QUANTITIES, MIN_ADAPTIVE_SPP = 64 };

static int adaptive(const sampling_settings *ss) { return ss->target_stderr > 0.0 || ss->target_rel_stderr > 0.0; }

/* The stop rule at a checkpoint (a power of two >= MIN_ADAPTIVE_SPP): the
 * standard error of quantity 0 within the absolute target, or within the
 * relative one of the mean (the moment sums' mean, precise however dim the
 * pixel). */
static int reached_target(const mc_pixel *acc, int taken, const sampling_settings *ss)
{
    if (!adaptive(ss) || taken < MIN_ADAPTIVE_SPP || (taken & (taken - 1)) != 0)
        return 0;
    double err = mc_pixel_stderr(acc, 0);
    double mean = moment_sums_total(&acc->moments[0]) / taken;
    return (ss->target_stderr > 0.0 && err <= ss->target_stderr) ||
           (ss->target_rel_stderr > 0.0 && err <= ss->target_rel_stderr * fabs(mean));
}

/* The next batch: up to SAMPLE_BATCH samples, ending at the next checkpoint
 * of the stop rule (taken is 0 or a power of two >= MIN_ADAPTIVE_SPP there). */
static int batch_size(int taken, const sampling_settings *ss)
{
    int count = ss->spp - taken < SAMPLE_BATCH ? ss->spp - taken : SAMPLE_BATCH;
    if (adaptive(ss)) {
        int to_checkpoint = taken < MIN_ADAPTIVE_SPP ? MIN_ADAPTIVE_SPP - taken : taken;
        count = count < to_checkpoint ? count : to_checkpoint;
    }
    return count;
}

pixel_context pixel_context_prepare(const surface_hit *surface, uint32_t seed)
{
    pixel_context px = {surface,
                        frame_from_normal(surface->ns),
                        offset_ray_origin(surface->p, surface->ng),
                        {hash_combine(seed, 0u), hash_combine(seed, 1u)},
                        -1};
    return px;
}

pixel_context pixel_context_at(const gbuffer *gb, int pixel, uint32_t seed)
{
    uint32_t x = (uint32_t)(pixel % gb->width), y = (uint32_t)(pixel / gb->width);
    pixel_context px = pixel_context_prepare(&gb->hits[pixel], pixel_seed(seed, x, y));
    px.pixel = pixel;
    return px;
}

void sample_pair_points(const sample_pair_seeds *s, uint32_t first, int count, float *u0, float *u1)
{
    /* Even samples are points of sequence 0, odd ones of sequence 1. */
    float even[2][SAMPLE_BATCH / 2 + 1], odd[2][SAMPLE_BATCH / 2 + 1];
    uint32_t first_even = (first + 1) >> 1, first_odd = first >> 1;
    int n_even = (count + (int)(~first & 1u)) / 2, n_odd = count - n_even;
    sobol_owen_points(&s->half[0], first_even, n_even, even[0], even[1]);
    sobol_owen_points(&s->half[1], first_odd, n_odd, odd[0], odd[1]);
    for (int k = 0; k < count; ++k) {
        uint32_t index = first + (uint32_t)k;
        int j = (int)((index >> 1) - ((index & 1u) ? first_odd : first_even));
        u0[k] = (index & 1u) ? odd[0][j] : even[0][j];
        u1[k] = (index & 1u) ? odd[1][j] : even[1][j];
    }
}

/* Samples one pixel to completion; returns the rays traced. */
static uint64_t render_pixel(const gbuffer *gb, const integrator *it, const sampling_settings *ss, mc_film *film,
                             int x, int y, uint64_t *samples)
{
    int pixel = y * gb->width + x;
    pixel_context px = pixel_context_at(gb, pixel, ss->seed);
    float values[SAMPLE_BATCH * MAX_QUANTITIES];
    mc_pixel acc;
    mc_pixel_clear(&acc, film);
    uint64_t rays = 0;
    int taken = 0;
    while (taken < ss->spp && !reached_target(&acc, taken, ss)) {
        uint32_t first = ss->sample_offset + (uint32_t)taken;
        int count = batch_size(taken, ss);
        rays += (uint64_t)it->sample_batch(it, &px, first, count, values);
        mc_pixel_add_samples(&acc, film, first, count, values, SAMPLE_BATCH);
        taken += count;
    }
    mc_film_add_pixel(film, pixel, &acc);
    *samples += (uint64_t)taken;
    return rays;
}

/* This process's share of the render (raytracer/distributed_render.h): all
 * of it alone; under MPI a block of every pixel's samples, or with a
 * stopping target whole rows. */
typedef struct {
    sampling_settings samples;
    int first_row, row_step, end_row; /* rows first_row, first_row + row_step, ... below end_row */
} work_share;

static work_share share_of(const sampling_settings *ss)
{
    render_share share = distributed_share();
    work_share w = {*ss, 0, 1, INT_MAX};
    if (share.ranks > 1 && adaptive(ss))
        w.first_row = share.rank, w.row_step = share.ranks;
    else if (share.ranks > 1)
        w.samples = distributed_sample_share(ss, share);
    return w;
}

/* The share's rows of the film, each pixel's samples ss; skips the rows
 * left once *stop is set (stop may be NULL). */
static void render_rows(const gbuffer *gb, const integrator *it, const work_share *w, mc_film *film,
                        render_stats *stats, const volatile sig_atomic_t *stop)
{
    const int end = w->end_row < gb->height ? w->end_row : gb->height;
    const int rows = end > w->first_row ? (end - w->first_row + w->row_step - 1) / w->row_step : 0;
    progress bar;
    progress_begin(&bar, it->label, rows);
    double start = seconds_now();
    uint64_t rays = 0, samples = 0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(w->samples.threads) reduction(+ : rays, samples)
    for (int row = 0; row < rows; ++row) {
        int y = w->first_row + row * w->row_step;
        for (int x = 0; x < gb->width && !(stop && *stop); ++x)
            if (gb->mask[y * gb->width + x] || it->covers_background)
                rays += render_pixel(gb, it, &w->samples, film, x, y, &samples);
        if (!(stop && *stop)) /* a stopped render's bar stays where it stopped */
            progress_advance(&bar, 1);
    }
    progress_end(&bar);
    stats->rays += rays;
    stats->samples += samples;
    stats->seconds += seconds_now() - start;
}

static int init_film(const gbuffer *gb, const integrator *it, mc_film *film, gt_error *e)
{
    if (it->quantity_count > MAX_QUANTITIES)
        return gt_error_set(e, it->label, "too many quantities");
    if (mc_film_init(film, gb->width, gb->height, it->quantities, it->quantity_count) != 0)
        return gt_error_set(e, it->label, "out of memory for the film");
    if (it->normalized_layer)
        mc_film_normalize_layer(film, it->normalized_layer);
    return 0;
}

int render_estimates(const gbuffer *gb, const integrator *it, const sampling_settings *ss, mc_film *film,
                     render_stats *stats, gt_error *e)
{
    if (init_film(gb, it, film, e) != 0)
        return -1;
    const work_share w = share_of(ss);
    *stats = (render_stats){0, 0, 0.0};
    render_rows(gb, it, &w, film, stats, NULL);
    if (distributed_reduce_film(film, stats, e) != 0) {
        mc_film_free(film);
        return -1;
    }
    return 0;
}

int render_estimates_film(const gbuffer *gb, const integrator *it, mc_film *film, gt_error *e)
{
    return init_film(gb, it, film, e);
}

int render_estimates_add(const gbuffer *gb, const integrator *it, const sampling_settings *ss, mc_film *film,
                         render_stats *stats, const volatile sig_atomic_t *stop)
{
    return render_estimates_add_rows(gb, it, ss, 0, 1, gb->height, film, stats, stop);
}

int render_estimates_add_rows(const gbuffer *gb, const integrator *it, const sampling_settings *ss, int first_row,
                              int row_step, int end_row, mc_film *film, render_stats *stats,
                              const volatile sig_atomic_t *stop)
{
    const work_share w = {*ss, first_row, row_step, end_row};
    render_rows(gb, it, &w, film, stats, stop);
    return stop && *stop ? 1 : 0;
}
