/* Ray throughput; see ray_throughput.h. */
#include "throughput/ray_throughput_study.h"

#include <string.h>

#include "throughput/throughput_quality.h"

enum { STUDY_WIDTH = 256, STUDY_HEIGHT = 256 }; /* the stage's view of builtin:menger */

/* The table's rows: each raw call, gtlab's AO loop, and their ratio. */
static void fill_rows(const ray_benchmark *b, ray_throughput_row *rows)
{
    for (int call = 0; call < RAW_CALL_COUNT; ++call)
        rows[call] = (ray_throughput_row){raw_call_names[call], 0, b->raw[0].by_call[call], b->raw[1].by_call[call]};
    rows[RAY_THROUGHPUT_GTLAB_ROW] = (ray_throughput_row){"gtlab AO reference", 0, b->gtlab_ao[0], b->gtlab_ao[1]};
    rows[RAY_THROUGHPUT_RATIO_ROW] = (ray_throughput_row){"ratio gtlab / best raw", 1, b->gtlab_ao[0] / b->raw[0].best,
                                                    b->gtlab_ao[1] / b->raw[1].best};
}

static void fill_result(const ray_benchmark *b, ray_throughput_result *out)
{
    out->threads = b->threads;
    out->rays_per_pass = b->rays_per_pass;
    fill_rows(b, out->rows);
    out->raw_best_1_thread = b->raw[0].best;
    out->raw_best_threads = b->raw[1].best;
    out->gtlab_ao_1_thread = b->gtlab_ao[0];
    out->gtlab_ao_threads = b->gtlab_ao[1];
    out->ratio_threads = b->gtlab_ao[1] / b->raw[1].best;
    out->speedup_gtlab = b->gtlab_ao[1] / b->gtlab_ao[0];
    out->speedup_raw = b->raw[1].best / b->raw[0].best;
}

int ray_throughput_measure(const char *spec, int width, int height, int threads, int repeats,
                           ray_throughput_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->scene = spec;
    out->repeats = repeats;
    scene s;
    camera cam;
    if (study_load_view(spec, width, height, &s, &cam, e) != 0)
        return -1;
    ray_benchmark b;
    int rc = ray_benchmark_run(&s, &cam, threads, repeats, &b, e);
    scene_free(&s);
    if (rc == 0)
        fill_result(&b, out);
    return rc;
}

int ray_throughput_study(const study_context *ctx, ray_throughput_result *out, gt_error *e)
{
    return ray_throughput_measure("builtin:menger", STUDY_WIDTH, STUDY_HEIGHT, ctx->threads,
                                  throughput_quality_of(ctx->quality)->repeats, out, e);
}
