/* The multi-bounce reference's throughput; see multibounce_bench.h. */
#include "multibounce/multibounce_bench.h"

#include "project/study_context.h"

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

void multibounce_benchmark_print(FILE *out, const char *spec, const multibounce_settings *s, const multibounce_benchmark *b)
{
    fprintf(out, "scene %s, %d albedos, %d spp, 1 and %d threads\n\n", spec, s->albedo_count, b->spp, b->threads);
    fprintf(out, "%-44s %14s %14s\n", "", "1 thread", "threads");
    fprintf(out, "%-44s %14.4g %14.4g\n", "gtlab multibounce paths/s", b->paths_per_s[0], b->paths_per_s[1]);
    fprintf(out, "%-44s %14.4g %14.4g\n", "gtlab multibounce rays/s", b->rays_per_s[0], b->rays_per_s[1]);
    fprintf(out, "%-44s %14.4g %14.4g\n", "raw Embree rtcIntersect1 rays/s", b->raw_intersect1[0], b->raw_intersect1[1]);
    fprintf(out, "%-44s %14.4g %14.4g\n", "raw Embree rtcIntersect1M (64) rays/s", b->raw_intersect1m[0],
           b->raw_intersect1m[1]);
    fprintf(out, "%-44s %14.3f %14.3f\n", "ratio gtlab / raw rtcIntersect1", b->rays_per_s[0] / b->raw_intersect1[0],
           b->rays_per_s[1] / b->raw_intersect1[1]);
    fprintf(out, "\n%d albedos in one pass: %.3f s; one render per albedo: %.3f s in all; ratio %.2f\n", s->albedo_count,
           b->seconds_one_pass, b->seconds_separate, b->seconds_separate / b->seconds_one_pass);
}
