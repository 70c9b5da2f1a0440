/* VBAO's cost per frame; see vbao_bench.h. */
#include "gtao/vbao_bench.h"

#include <omp.h>

#include "core/progress.h"

static double seconds_per_frame(const ss_gbuffer *g, const vbao_params *p, int repeats, float *ao)
{
    double best = 1e30;
    for (int r = 0; r < repeats; ++r) {
        double t0 = seconds_now();
        vbao_render(g, p, ao, NULL);
        double t = (seconds_now() - t0) / p->gtao.frames;
        best = t < best ? t : best;
    }
    return best;
}

void vbao_bench_time(const ss_gbuffer *g, float radius, float thickness, int threads, int repeats, float *ao,
                     vbao_bench_result *out)
{
    vbao_params p = vbao_preset(GTAO_PRESET_MEDIUM, thickness, VBAO_PAPER);
    p.gtao.radius = radius;
    p.gtao.frames = 24;
    vbao_params_text(&p, out->settings, sizeof out->settings);
    omp_set_num_threads(1);
    out->seconds_1_thread = seconds_per_frame(g, &p, repeats, ao);
    omp_set_num_threads(threads);
    out->seconds_threads = seconds_per_frame(g, &p, repeats, ao);
}
