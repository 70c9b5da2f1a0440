/* Report section: ray throughput of the AO reference against raw Embree,
 * measured in this run (throughput/ray_throughput_study.h, the figures of `gtlab
 * bench rays`), rendered into the report and summary.json. */
#include <stdio.h>

#include "throughput/ray_throughput_section.h"
#include "report/report_table.h"
#include "throughput/ray_throughput_study.h"

#define COLUMNS(c) (int)(sizeof(c) / sizeof((c)[0]))

/* rays/s, or the ratio to 3 decimals. */
static void rate_cell(double value, int is_ratio, char *text, size_t size)
{
    snprintf(text, size, is_ratio ? "%.3f" : "%.3g", value);
}

static void one_thread_cell(const void *row, char *text, size_t size)
{
    const ray_throughput_row *r = row;
    rate_cell(r->one_thread, r->is_ratio, text, size);
}

static void threads_cell(const void *row, char *text, size_t size)
{
    const ray_throughput_row *r = row;
    rate_cell(r->threads, r->is_ratio, text, size);
}

static const report_column row_columns[] = {
    REPORT_STRING("rays/s", NULL, ray_throughput_row, name),
    REPORT_CELL("1 thread", one_thread_cell),
    REPORT_CELL("threads", threads_cell),
};

static const report_column summary_columns[] = {
    REPORT_STRING(NULL, "scene", ray_throughput_result, scene),
    REPORT_INT(NULL, "threads", ray_throughput_result, threads),
    REPORT_REAL(NULL, "raw_best_1_thread", NULL, ray_throughput_result, raw_best_1_thread),
    REPORT_REAL(NULL, "raw_best_threads", NULL, ray_throughput_result, raw_best_threads),
    REPORT_REAL(NULL, "gtlab_ao_1_thread", NULL, ray_throughput_result, gtlab_ao_1_thread),
    REPORT_REAL(NULL, "gtlab_ao_threads", NULL, ray_throughput_result, gtlab_ao_threads),
    REPORT_REAL(NULL, "ratio_threads", NULL, ray_throughput_result, ratio_threads),
    REPORT_REAL(NULL, "speedup_gtlab", NULL, ray_throughput_result, speedup_gtlab),
};

int ray_throughput_section(report_context *ctx, const ray_throughput_result *r, gt_error *e)
{
    (void)e;
    report_heading(ctx->doc, 2, "Ray throughput");
    report_paragraph(ctx->doc,
                     "Occlusion rays per second on %s, the best of several passes: raw Embree calls on a prepared "
                     "array of %ld rays — the very rays the AO reference traces, incoherent, per sample one "
                     "cosine- and one uniform-distributed direction — and gtlab's AO reference loop end to end "
                     "at 64 samples per pixel (sampling, ray set-up, Embree, exact accumulation). Same run, "
                     "same machine: 'gtlab bench rays' measures the same.",
                     r->scene, r->rays_per_pass);
    report_rows(ctx->doc, NULL, row_columns, COLUMNS(row_columns), r->rows, sizeof r->rows[0], RAY_THROUGHPUT_ROWS);
    report_paragraph(ctx->doc, "Speed-up of %d threads over 1: gtlab %.2fx, raw Embree %.2fx.", r->threads,
                     r->speedup_gtlab, r->speedup_raw);
    report_finding(ctx->doc, "Ray throughput",
                   "the AO reference traces %.3g rays/s on %d threads, %.2f of raw Embree's best on the same rays "
                   "(%s).",
                   r->gtlab_ao_threads, r->threads, r->ratio_threads, r->scene);
    report_object(ctx->summary, "ray_throughput", summary_columns, COLUMNS(summary_columns), r);
    return 0;
}
