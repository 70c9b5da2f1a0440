/* `gtlab all` stage: ray throughput of the AO reference against raw Embree,
 * measured in this run (the figures of `gtlab bench rays`). */
#include <stdio.h>

#include "cli/all_stages.h"
#include "raytracer/ray_throughput.h"
#include "scene/scene_loaders.h"

int all_stage_ray_throughput(all_context *ctx, gt_error *e)
{
    const char *spec = "builtin:menger";
    scene s;
    if (scene_load(spec, &s, e) != 0)
        return -1;
    camera cam;
    ray_benchmark b;
    int rc = scene_choose_camera(&s, NULL, 256, 256, &cam, e);
    if (rc == 0)
        rc = ray_benchmark_run(&s, &cam, ctx->threads, ctx->quality == QUALITY_PREVIEW ? 2 : 5, &b, e);
    scene_free(&s);
    if (rc != 0)
        return -1;
    report_heading(ctx->doc, 2, "Ray throughput");
    report_paragraph(ctx->doc,
                     "Occlusion rays per second on %s, the best of several passes: raw Embree calls on a prepared "
                     "array of %ld rays — the very rays the AO reference traces, incoherent, per sample one "
                     "cosine- and one uniform-distributed direction — and gtlab's AO reference loop end to end "
                     "at 64 samples per pixel (sampling, ray set-up, Embree, exact accumulation). Same run, "
                     "same machine: 'gtlab bench rays' measures the same.",
                     spec, b.rays_per_pass);
    static const char *const headers[3] = {"rays/s", "1 thread", "threads"};
    report_table_begin(ctx->doc, 3, headers);
    char cells[3][64];
    const char *row[3] = {cells[0], cells[1], cells[2]};
    for (int call = 0; call < RAW_CALL_COUNT; ++call) {
        snprintf(cells[0], 64, "%s", raw_call_names[call]);
        snprintf(cells[1], 64, "%.3g", b.raw[0].by_call[call]);
        snprintf(cells[2], 64, "%.3g", b.raw[1].by_call[call]);
        report_table_row(ctx->doc, row);
    }
    snprintf(cells[0], 64, "gtlab AO reference");
    snprintf(cells[1], 64, "%.3g", b.gtlab_ao[0]);
    snprintf(cells[2], 64, "%.3g", b.gtlab_ao[1]);
    report_table_row(ctx->doc, row);
    snprintf(cells[0], 64, "ratio gtlab / best raw");
    snprintf(cells[1], 64, "%.3f", b.gtlab_ao[0] / b.raw[0].best);
    snprintf(cells[2], 64, "%.3f", b.gtlab_ao[1] / b.raw[1].best);
    report_table_row(ctx->doc, row);
    report_table_end(ctx->doc);
    report_paragraph(ctx->doc, "Speed-up of %d threads over 1: gtlab %.2fx, raw Embree %.2fx.", b.threads,
                     b.gtlab_ao[1] / b.gtlab_ao[0], b.raw[1].best / b.raw[0].best);
    report_finding(ctx->doc, "Ray throughput",
                   "the AO reference traces %.3g rays/s on %d threads, %.2f of raw Embree's best on the same rays "
                   "(%s).",
                   b.gtlab_ao[1], b.threads, b.gtlab_ao[1] / b.raw[1].best, spec);
    cJSON *o = cJSON_AddObjectToObject(ctx->summary, "ray_throughput");
    cJSON_AddStringToObject(o, "scene", spec);
    cJSON_AddNumberToObject(o, "threads", b.threads);
    cJSON_AddNumberToObject(o, "raw_best_1_thread", b.raw[0].best);
    cJSON_AddNumberToObject(o, "raw_best_threads", b.raw[1].best);
    cJSON_AddNumberToObject(o, "gtlab_ao_1_thread", b.gtlab_ao[0]);
    cJSON_AddNumberToObject(o, "gtlab_ao_threads", b.gtlab_ao[1]);
    cJSON_AddNumberToObject(o, "ratio_threads", b.gtlab_ao[1] / b.raw[1].best);
    cJSON_AddNumberToObject(o, "speedup_gtlab", b.gtlab_ao[1] / b.gtlab_ao[0]);
    return 0;
}
