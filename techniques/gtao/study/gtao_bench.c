/* The cost of GTAO; see gtao_bench.h. */
#include "gtao/gtao_bench.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/progress.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "project/gbuffer_input.h"

typedef approx_input bench_gbuffer;

static int render_gbuffer(const scene *s, int width, int height, int threads, bench_gbuffer *b, gt_error *e)
{
    camera cam;
    if (scene_choose_camera(s, NULL, width, height, &cam, e) != 0)
        return -1;
    return approx_render_gbuffer(s, s->name, &cam, threads, b, e);
}

/* Best seconds per frame of p over `repeats` passes. */
static double seconds_per_frame(const bench_gbuffer *b, const gtao_params *p, int repeats, float *ao)
{
    double best = 1e30;
    for (int r = 0; r < repeats; ++r) {
        double t0 = seconds_now();
        gtao_render(&b->g, p, ao, NULL);
        double t = (seconds_now() - t0) / p->frames;
        best = t < best ? t : best;
    }
    return best;
}

static float bench_radius(const camera *cam) { return 0.25f * v3_length(v3_sub(cam->target, cam->position)); }

/* The talk's configuration at half resolution, on 1 and `threads` threads. */
static void time_talk(const bench_gbuffer *half, int threads, int repeats, float *ao, gtao_bench_result *out)
{
    gtao_params talk;
    gtao_preset(gtao_preset_names[GTAO_PRESET_MEDIUM], &talk);
    talk.radius = bench_radius(&half->cam);
    talk.frames = GTAO_BENCH_FRAMES;
    gtao_params_text(&talk, out->settings, sizeof out->settings);
    omp_set_num_threads(1);
    out->talk_seconds_1_thread = seconds_per_frame(half, &talk, repeats, ao);
    omp_set_num_threads(threads);
    out->talk_seconds_threads = seconds_per_frame(half, &talk, repeats, ao);
    vbao_bench_time(&half->g, talk.radius, 0.2f * talk.radius, threads, repeats, ao, &out->vbao);
}

/* ns per pixel of one frame of every preset on the small image. */
static void time_presets(const bench_gbuffer *small, int repeats, float *ao, gtao_bench_result *out)
{
    double pixels = (double)small->g.width * small->g.height;
    for (int i = 0; i < GTAO_PRESET_COUNT; ++i) {
        gtao_params p;
        gtao_preset(gtao_preset_names[i], &p);
        p.radius = bench_radius(&small->cam);
        out->preset_ns[i] = 1e9 * seconds_per_frame(small, &p, repeats, ao) / pixels;
    }
}

/* ns per pixel of the height-field Monte Carlo reference on the small image. */
static int time_heightfield(const scene *s, const char *spec, const bench_gbuffer *small, int threads,
                            gtao_bench_result *out, gt_error *e)
{
    reference_request req = {.quantity = QUANTITY_HEIGHTFIELD_AO,
                             .sampling = {.spp = GTAO_BENCH_HEIGHTFIELD_SPP, .seed = 1, .threads = threads},
                             .normals = NORMAL_SHADING};
    image hf;
    render_stats stats;
    double t0 = seconds_now();
    if (reference_render(s, spec, &small->cam, &req, &hf, &stats, e) != 0)
        return -1;
    out->heightfield_ns = 1e9 * (seconds_now() - t0) / ((double)small->g.width * small->g.height);
    image_free(&hf);
    return 0;
}

static int measure(const scene *s, const char *spec, int threads, int repeats, bench_gbuffer *half,
                   bench_gbuffer *small, float *ao, gtao_bench_result *out, gt_error *e)
{
    if (render_gbuffer(s, GTAO_BENCH_HALF_WIDTH, GTAO_BENCH_HALF_HEIGHT, threads, half, e) != 0 ||
        render_gbuffer(s, GTAO_BENCH_SMALL_WIDTH, GTAO_BENCH_SMALL_HEIGHT, threads, small, e) != 0)
        return -1;
    time_talk(half, threads, repeats, ao, out);
    out->small_width = small->g.width;
    out->small_height = small->g.height;
    time_presets(small, repeats, ao, out);
    return time_heightfield(s, spec, small, threads, out, e);
}

int gtao_bench_run(const char *spec, int threads, int repeats, gtao_bench_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    scene s;
    if (scene_load(spec, &s, e) != 0)
        return -1;
    bench_gbuffer half = {0}, small = {0};
    float *ao = malloc(sizeof *ao * GTAO_BENCH_HALF_WIDTH * GTAO_BENCH_HALF_HEIGHT);
    int status = ao ? measure(&s, spec, threads, repeats, &half, &small, ao, out, e)
                    : gt_error_set(e, spec, "out of memory");
    free(ao);
    image_free(&half.img);
    image_free(&small.img);
    scene_free(&s);
    return status;
}

void gtao_bench_print(FILE *f, const char *spec, int threads, const gtao_bench_result *r)
{
    fprintf(f, "scene %s; GTAO at %dx%d (1920x1080 at half resolution): %s\n\n", spec, GTAO_BENCH_HALF_WIDTH,
            GTAO_BENCH_HALF_HEIGHT, r->settings);
    fprintf(f, "%-44s %12s %12s\n", "per frame (GTAO + denoisers)", "1 thread", "threads");
    fprintf(f, "%-44s %9.2f ms %9.2f ms   (%d threads)\n", "talk's configuration", 1e3 * r->talk_seconds_1_thread,
            1e3 * r->talk_seconds_threads, threads);
    fprintf(f, "%-44s %9.2f ms %9.2f ms\n  (%s)\n\n", "VBAO, the same with 32 sectors", 1e3 * r->vbao.seconds_1_thread,
            1e3 * r->vbao.seconds_threads, r->vbao.settings);
    fprintf(f, "cost per pixel, one frame on %dx%d, %d threads:\n", r->small_width, r->small_height, threads);
    double reference_ns = r->preset_ns[GTAO_PRESET_REFERENCE];
    for (int i = 0; i < GTAO_PRESET_COUNT; ++i)
        fprintf(f, "  GTAO %-12s %12.1f ns/pixel   %8.4f of the brute-force reference\n", gtao_preset_names[i],
                r->preset_ns[i], r->preset_ns[i] / reference_ns);
    fprintf(f, "  height-field MC, %d spp %8.1f ns/pixel   %8.4f of the brute-force reference\n",
            GTAO_BENCH_HEIGHTFIELD_SPP, r->heightfield_ns, r->heightfield_ns / reference_ns);
}
