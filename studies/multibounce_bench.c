/* The multi-bounce reference's throughput; see multibounce_bench.h. */
#include "studies/multibounce_bench.h"

#include "studies/study.h"

int multibounce_bench_run(const char *spec, int width, int height, const multibounce_settings *settings, int spp,
                          int threads, int repeats, multibounce_benchmark *out, gt_error *e)
{
    scene s;
    camera cam;
    if (study_load_view(spec, width, height, &s, &cam, e) != 0)
        return -1;
    int rc = multibounce_benchmark_run(&s, &cam, settings, spp, threads, repeats, out, e);
    scene_free(&s);
    return rc;
}
