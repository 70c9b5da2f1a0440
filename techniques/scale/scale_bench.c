/* The scaling bench (scale_bench.h). */
#include "scale/scale_bench.h"

#include "ao/ao_quantity.h"
#include "core/progress.h"
#include "core/threads.h"
#include "raytracer/distributed_render.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"

#define SCALE_BENCH_SCENE "builtin:cornell"

typedef struct {
    render_share share;
    int threads;
    render_stats sampling;
    double film_bytes, reduce_seconds;
} scale_figures;

/* The AO reference under the job: its stats are the job's (rank 0). */
static int time_render(const scene *s, const camera *cam, scale_figures *f, gt_error *e)
{
    reference_request rq = {.quantity = QUANTITY_AO,
                            .sampling = {.spp = SCALE_BENCH_SPP, .seed = 1, .threads = f->threads},
                            .normals = NORMAL_SHADING};
    image out;
    if (reference_render(s, SCALE_BENCH_SCENE, cam, &rq, &out, &f->sampling, e) != 0)
        return -1;
    image_free(&out);
    return 0;
}

/* One AO-sized film reduced to rank 0 on its own: the gather's cost
 * (rank 0's film is added to, which costs the same as the real one's). */
static int time_reduction(scale_figures *f, gt_error *e)
{
    static const mc_quantity quantities[5] = {{"a", 0}, {"b", 0}, {"c", 0}, {"d", 0}, {"e", 0}};
    mc_film film;
    if (mc_film_init(&film, SCALE_BENCH_WIDTH, SCALE_BENCH_HEIGHT, quantities, 5) != 0)
        return gt_error_set(e, "bench scale", "out of memory for the film");
    double pixels = (double)SCALE_BENCH_WIDTH * SCALE_BENCH_HEIGHT;
    f->film_bytes = pixels * (5.0 * (2 * sizeof(int64_t) + sizeof(moment_sums)) + 2 * sizeof(uint64_t));
    render_stats ignored = {0, 0, 0.0};
    /* Twice, timing the second: the first lines the ranks up. */
    int rc = distributed_reduce_film(&film, &ignored, e);
    double start = seconds_now();
    if (rc == 0)
        rc = distributed_reduce_film(&film, &ignored, e);
    f->reduce_seconds = seconds_now() - start;
    mc_film_free(&film);
    return rc;
}

static void print_figures(FILE *out, const scale_figures *f)
{
    const double rate = (double)f->sampling.samples / f->sampling.seconds;
    const double per_film = f->share.ranks > 1 ? f->reduce_seconds / (f->share.ranks - 1) : 0.0;
    fprintf(out, "gtlab bench scale: ao, %s %dx%d, %d spp; %d rank(s) x %d thread(s)\n", SCALE_BENCH_SCENE,
            SCALE_BENCH_WIDTH, SCALE_BENCH_HEIGHT, SCALE_BENCH_SPP, f->share.ranks, f->threads);
    fprintf(out, "  sampling   %.3f s (longest rank), %.3g samples/s in all, %.3g per rank\n", f->sampling.seconds,
            rate, rate / f->share.ranks);
    fprintf(out, "  reduction  %.4f s for %d film(s) of %.2f MB: %.4f s a rank%s\n", f->reduce_seconds,
            f->share.ranks - 1, f->film_bytes / 1e6, per_film,
            f->share.ranks > 1 ? "" : " (run under mpirun -n 2 or more to measure it)");
    static const int nodes[3] = {1, 16, 256};
    for (int i = 0; i < 3; ++i)
        fprintf(out, "  projected  %3d node(s) like this job: %.4f s (sampling / M + (M - 1) x %.4f s)\n", nodes[i],
                f->sampling.seconds / nodes[i] + (nodes[i] - 1) * per_film, per_film);
}

int scale_bench_run(FILE *out, gt_error *e)
{
    if (distributed_begin(e) != 0)
        return -1;
    scale_figures f = {.share = distributed_share(), .threads = threads_default()};
    scene s;
    camera cam;
    if (scene_load(SCALE_BENCH_SCENE, &s, e) != 0)
        return -1;
    int rc = scene_choose_camera(&s, NULL, SCALE_BENCH_WIDTH, SCALE_BENCH_HEIGHT, &cam, e);
    if (rc == 0)
        rc = time_render(&s, &cam, &f, e);
    if (rc == 0)
        rc = time_reduction(&f, e);
    if (rc == 0 && distributed_is_writer())
        print_figures(out, &f);
    scene_free(&s);
    return rc;
}
