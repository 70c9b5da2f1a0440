#include "multibounce/multibounce_throughput.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/sampling/hemisphere_sampling.h"
#include "core/progress.h"
#include "raytracer/gbuffer.h"

enum { RAW_STREAM = 64 };

/* The first ray of every path the reference traces at `spp` samples per
 * pixel (cosine-distributed about the shading normal, dimension pair 0,
 * above the geometric surface), in pixel order: incoherent rays like the
 * later bounces'. */
static struct RTCRayHit *make_rays(const gbuffer *gb, int spp, long *count)
{
    long covered = gbuffer_covered_pixels(gb);
    struct RTCRayHit *rays = aligned_alloc(64, sizeof *rays * (size_t)(covered * spp + RAW_STREAM));
    if (!rays)
        return NULL;
    long n = 0;
    for (int i = 0; i < gb->width * gb->height; ++i) {
        if (!gb->mask[i])
            continue;
        pixel_context px = pixel_context_at(gb, i, 1);
        const sample_pair_seeds pair = sample_pair_seeds_for(&px, 0);
        for (int k = 0; k < spp; ++k) {
            float u[2];
            sample_pair_point(&pair, (uint32_t)k, u);
            vec3 d = frame_to_world(&px.shading, sample_cosine_hemisphere(u));
            if (v3_dot(d, px.surface->ng) > 0.0f)
                embree_ray_init(&rays[n++].ray, px.ray_origin, d, INFINITY);
        }
    }
    *count = n;
    return rays;
}

static void reset(struct RTCRayHit *rays, long n)
{
    for (long i = 0; i < n; ++i) {
        rays[i].ray.tfar = INFINITY;
        rays[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rays[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    }
}

/* rays/s of rtcIntersect1 (stream = 1) or rtcIntersect1M (stream > 1). */
static double pass_intersect(RTCScene sc, struct RTCRayHit *rays, long n, int threads, long stream)
{
    reset(rays, n);
    double t0 = seconds_now();
#pragma omp parallel num_threads(threads)
    {
        struct RTCIntersectContext c;
        rtcInitIntersectContext(&c);
        c.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
#pragma omp for schedule(static, 64)
        for (long i = 0; i < n; i += stream) {
            if (stream == 1)
                rtcIntersect1(sc, &c, &rays[i]);
            else
                rtcIntersect1M(sc, &c, &rays[i], (unsigned)(n - i < stream ? n - i : stream), sizeof *rays);
        }
    }
    return (double)n / (seconds_now() - t0);
}

/* One render of the multi-bounce loop; returns its seconds. */
static int time_render(const embree_scene *es, const gbuffer *gb, const multibounce_settings *settings, int spp,
                       int threads, render_stats *stats, gt_error *e)
{
    multibounce_plan plan;
    if (multibounce_plan_init(&plan, settings, NORMAL_SHADING, e) != 0)
        return -1;
    integrator it = multibounce_integrator(es, &plan);
    sampling_settings ss = {.spp = spp, .seed = 1, .threads = threads};
    mc_film film;
    if (render_estimates(gb, &it, &ss, &film, stats, e) != 0)
        return -1;
    mc_film_free(&film);
    return 0;
}

static int measure_loop(const embree_scene *es, const gbuffer *gb, const multibounce_settings *settings, int spp,
                        int repeats, multibounce_benchmark *out, gt_error *e)
{
    const int thread_counts[2] = {1, out->threads};
    for (int t = 0; t < 2; ++t)
        for (int k = 0; k < repeats; ++k) {
            render_stats stats;
            if (time_render(es, gb, settings, spp, thread_counts[t], &stats, e) != 0)
                return -1;
            out->paths_per_s[t] = fmax(out->paths_per_s[t], (double)stats.samples / stats.seconds);
            out->rays_per_s[t] = fmax(out->rays_per_s[t], (double)stats.rays / stats.seconds);
            if (t == 1)
                out->seconds_one_pass = k == 0 ? stats.seconds : fmin(out->seconds_one_pass, stats.seconds);
        }
    return 0;
}

/* The same albedos rendered one at a time, `threads` threads, best of the passes. */
static int measure_separate(const embree_scene *es, const gbuffer *gb, const multibounce_settings *settings, int spp,
                            int repeats, multibounce_benchmark *out, gt_error *e)
{
    for (int k = 0; k < repeats; ++k) {
        double total = 0.0;
        for (int a = 0; a < settings->albedo_count; ++a) {
            multibounce_settings one = *settings;
            one.albedo_count = 1;
            one.albedos[0] = settings->albedos[a];
            render_stats stats;
            if (time_render(es, gb, &one, spp, out->threads, &stats, e) != 0)
                return -1;
            total += stats.seconds;
        }
        out->seconds_separate = k == 0 ? total : fmin(out->seconds_separate, total);
    }
    return 0;
}

int multibounce_benchmark_run(const scene *s, const camera *cam, const multibounce_settings *settings, int spp,
                              int threads, int repeats, multibounce_benchmark *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->threads = threads;
    out->spp = spp;
    embree_scene es;
    if (embree_scene_build(s, &es, e) != 0)
        return -1;
    gbuffer gb;
    int rc = gbuffer_render(&es, cam, NORMAL_SHADING, threads, &gb, e);
    struct RTCRayHit *rays = rc == 0 ? make_rays(&gb, spp, &out->raw_rays) : NULL;
    if (rc == 0 && !rays)
        rc = gt_error_set(e, "bench", "out of memory for the ray set");
    const int thread_counts[2] = {1, threads};
    for (int t = 0; t < 2 && rc == 0; ++t)
        for (int k = 0; k < repeats; ++k) {
            out->raw_intersect1[t] = fmax(out->raw_intersect1[t], pass_intersect(es.rtc, rays, out->raw_rays,
                                                                                 thread_counts[t], 1));
            out->raw_intersect1m[t] = fmax(out->raw_intersect1m[t], pass_intersect(es.rtc, rays, out->raw_rays,
                                                                                   thread_counts[t], RAW_STREAM));
        }
    if (rc == 0)
        rc = measure_loop(&es, &gb, settings, spp, repeats, out, e);
    if (rc == 0)
        rc = measure_separate(&es, &gb, settings, spp, repeats, out, e);
    free(rays);
    gbuffer_free(&gb);
    embree_scene_release(&es);
    return rc;
}
