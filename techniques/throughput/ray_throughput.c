#include "throughput/ray_throughput.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/frame.h"
#include "core/sampling/hemisphere_sampling.h"
#include "core/progress.h"
#include "core/sampling/sobol.h"
#include "ao/ao_integrator.h"
#include "raytracer/gbuffer.h"

/* gtlab renders GTLAB_SPP samples (2 rays each) per pixel, a short but
 * realistic render; the raw ray set holds the very same rays, in the same
 * pixel-by-pixel order. */
enum { GTLAB_SPP = 64, RAYS_PER_PIXEL = 2 * GTLAB_SPP, LONGEST_STREAM = 128 };

const char *const raw_call_names[RAW_CALL_COUNT] = {"Embree rtcOccluded1", "Embree rtcOccluded1M (stream 64)",
                                                     "Embree rtcOccluded1M (stream 128)", "Embree rtcOccluded8",
                                                     "Embree rtcOccluded16"};

/* The rays the AO integrator traces: per sample one cosine-distributed and
 * one uniform direction about the shading normal, from the offset surface
 * point, from the same Sobol' points. Directions under the geometric surface
 * are traced too (the integrator skips them: that only favours the raw
 * figure). */
static struct RTCRay *make_rays(const gbuffer *gb, long *count)
{
    long covered = gbuffer_covered_pixels(gb);
    struct RTCRay *rays = aligned_alloc(64, sizeof *rays * (size_t)(covered * RAYS_PER_PIXEL + LONGEST_STREAM));
    if (!rays)
        return NULL;
    long n = 0;
    for (int i = 0; i < gb->width * gb->height; ++i) {
        if (!gb->mask[i])
            continue;
        pixel_context px = pixel_context_at(gb, i, 1);
        const sample_pair_seeds pair = sample_pair_seeds_for(&px, 0);
        for (uint32_t k = 0; k < RAYS_PER_PIXEL; ++k) {
            float u[2];
            sample_pair_point(&pair, k / 2, u);
            vec3 local = k % 2 == 0 ? sample_cosine_hemisphere(u) : sample_uniform_hemisphere(u);
            embree_ray_init(&rays[n++], px.ray_origin, frame_to_world(&px.shading, local), INFINITY);
        }
    }
    *count = n;
    return rays;
}

static void reset_tfar(struct RTCRay *rays, long n)
{
    for (long i = 0; i < n; ++i)
        rays[i].tfar = INFINITY;
}

static void init_context(struct RTCIntersectContext *c)
{
    rtcInitIntersectContext(c);
    c->flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
}

static double pass_occluded1(RTCScene sc, struct RTCRay *rays, long n, int threads)
{
    double t0 = seconds_now();
#pragma omp parallel num_threads(threads)
    {
        struct RTCIntersectContext c;
        init_context(&c);
#pragma omp for schedule(static, 4096)
        for (long i = 0; i < n; ++i)
            rtcOccluded1(sc, &c, &rays[i]);
    }
    return (double)n / (seconds_now() - t0);
}

static double pass_occluded1m(RTCScene sc, struct RTCRay *rays, long n, int threads, long stream)
{
    double t0 = seconds_now();
#pragma omp parallel num_threads(threads)
    {
        struct RTCIntersectContext c;
        init_context(&c);
#pragma omp for schedule(static, 64)
        for (long i = 0; i < n; i += stream)
            rtcOccluded1M(sc, &c, &rays[i], (unsigned)(n - i < stream ? n - i : stream), sizeof(struct RTCRay));
    }
    return (double)n / (seconds_now() - t0);
}

/* Packets of W rays in SOA layout; the valid masks aligned as Embree needs. */
#define DEFINE_PACKET_PASS(W)                                                                       \
    static double pass_occluded##W(RTCScene sc, const struct RTCRay *rays, long n, int threads)     \
    {                                                                                               \
        double t0 = seconds_now();                                                                  \
        _Pragma("omp parallel num_threads(threads)")                                                \
        {                                                                                           \
            struct RTCIntersectContext c;                                                           \
            init_context(&c);                                                                       \
            _Pragma("omp for schedule(static, 64)")                                                 \
            for (long i = 0; i < n; i += W) {                                                       \
                _Alignas(64) int valid[W];                                                          \
                _Alignas(64) struct RTCRay##W p;                                                    \
                for (int k = 0; k < W; ++k) {                                                       \
                    const struct RTCRay *r = &rays[i + k < n ? i + k : n - 1];                      \
                    valid[k] = i + k < n ? -1 : 0;                                                  \
                    p.org_x[k] = r->org_x, p.org_y[k] = r->org_y, p.org_z[k] = r->org_z;            \
                    p.dir_x[k] = r->dir_x, p.dir_y[k] = r->dir_y, p.dir_z[k] = r->dir_z;            \
                    p.tnear[k] = 0.0f, p.tfar[k] = INFINITY, p.time[k] = 0.0f;                      \
                    p.mask[k] = 0xffffffffu, p.id[k] = 0, p.flags[k] = 0;                           \
                }                                                                                   \
                rtcOccluded##W(valid, sc, &c, &p);                                                  \
            }                                                                                       \
        }                                                                                           \
        return (double)n / (seconds_now() - t0);                                                    \
    }
DEFINE_PACKET_PASS(8)
DEFINE_PACKET_PASS(16)

static void measure_raw(RTCScene sc, struct RTCRay *rays, long n, int threads, int repeats, raw_throughput *r)
{
    memset(r, 0, sizeof *r);
    for (int k = 0; k < repeats; ++k) {
        reset_tfar(rays, n);
        double pass[RAW_CALL_COUNT];
        pass[RAW_OCCLUDED1] = pass_occluded1(sc, rays, n, threads);
        reset_tfar(rays, n);
        pass[RAW_OCCLUDED1M_64] = pass_occluded1m(sc, rays, n, threads, 64);
        reset_tfar(rays, n);
        pass[RAW_OCCLUDED1M_128] = pass_occluded1m(sc, rays, n, threads, LONGEST_STREAM);
        pass[RAW_OCCLUDED8] = pass_occluded8(sc, rays, n, threads);
        pass[RAW_OCCLUDED16] = pass_occluded16(sc, rays, n, threads);
        for (int call = 0; call < RAW_CALL_COUNT; ++call) {
            r->by_call[call] = fmax(r->by_call[call], pass[call]);
            r->best = fmax(r->best, pass[call]);
        }
    }
}

/* rays/s of the AO reference loop itself (render_estimates), with as many
 * rays per pass as the raw measurement. */
static int measure_gtlab(const embree_scene *es, const gbuffer *gb, int threads, int repeats, double *rays_per_s,
                         gt_error *e)
{
    ao_settings settings = {INFINITY, NULL, 0.0f};
    integrator it = ao_integrator(es, &settings);
    sampling_settings ss = {.spp = GTLAB_SPP, .seed = 1, .threads = threads};
    *rays_per_s = 0.0;
    for (int k = 0; k < repeats; ++k) {
        mc_film film;
        render_stats stats;
        if (render_estimates(gb, &it, &ss, &film, &stats, e) != 0)
            return -1;
        mc_film_free(&film);
        *rays_per_s = fmax(*rays_per_s, (double)stats.rays / stats.seconds);
    }
    return 0;
}

int ray_benchmark_run(const scene *s, const camera *cam, int threads, int repeats, ray_benchmark *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->threads = threads;
    embree_scene es;
    if (embree_scene_build(s, &es, e) != 0)
        return -1;
    gbuffer gb;
    int rc = gbuffer_render(&es, cam, NORMAL_SHADING, threads, &gb, e);
    struct RTCRay *rays = rc == 0 ? make_rays(&gb, &out->rays_per_pass) : NULL;
    if (rc == 0 && !rays)
        rc = gt_error_set(e, "bench", "out of memory for the ray set");
    const int thread_counts[2] = {1, threads};
    for (int t = 0; t < 2 && rc == 0; ++t) {
        measure_raw(es.rtc, rays, out->rays_per_pass, thread_counts[t], repeats, &out->raw[t]);
        rc = measure_gtlab(&es, &gb, thread_counts[t], repeats, &out->gtlab_ao[t], e);
    }
    free(rays);
    gbuffer_free(&gb);
    embree_scene_release(&es);
    return rc;
}
