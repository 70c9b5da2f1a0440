#include "dfg/dfg_study.h"

#include <stdio.h>
#include <string.h>

#include "core/files/atomic_file.h"
#include "core/progress.h"
#include "dfg/dfg_lut_writers.h"
#include "dfg/dfg_quality.h"

dfg_request dfg_default_request(study_quality quality)
{
    const dfg_quality *q = dfg_quality_of(quality);
    dfg_request rq = {DFG_FILAMENT_SIZE, {16, 32, 64, 128, 256}, q->interpolation_sizes, q->interpolation_points, 1};
    return rq;
}

int dfg_write_table(const char *dir, int size, int threads, dfg_result *out, gt_error *e)
{
    dfg_lut lut;
    double t0 = seconds_now();
    if (dfg_lut_build(&lut, size, threads) != 0)
        return gt_error_set(e, "dfg", "cannot build a %d x %d table (sizes %d to %d)", size, size, DFG_MIN_SIZE,
                            DFG_MAX_SIZE);
    out->build_seconds = seconds_now() - t0;
    out->max_error_estimate = lut.max_error_estimate;
    out->e_min = 1.0;
    for (int t = 0; t < lut.size * lut.size; ++t)
        if (lut.data[t * DFG_CHANNELS + DFG_ALBEDO] < out->e_min)
            out->e_min = lut.data[t * DFG_CHANNELS + DFG_ALBEDO];
    char base[64];
    snprintf(base, sizeof base, "dfg_%d", size);
    int rc = dfg_lut_write_all(dir, base, "DFG_LUT", &lut, e);
    dfg_lut_free(&lut);
    return rc;
}

/* One line per size: size, then max and RMS over the square and between
 * the texel centres, for A, B and E. */
static int write_interpolation_data(const char *dir, const dfg_result *r, gt_error *e)
{
    char path[4096], text[8192];
    size_t len = (size_t)snprintf(text, sizeof text, "# size  (max rms interior_max interior_rms) x (A B E)\n");
    for (int k = 0; k < r->request.size_count; ++k) {
        const dfg_interpolation_result *x = &r->by_size[k];
        len += (size_t)snprintf(text + len, sizeof text - len, "%d", x->size);
        for (int c = 0; c < DFG_CHANNELS; ++c)
            len += (size_t)snprintf(text + len, sizeof text - len, " %.6e %.6e %.6e %.6e", x->max_error[c],
                                    x->rms_error[c], x->interior_max_error[c], x->interior_rms_error[c]);
        len += (size_t)snprintf(text + len, sizeof text - len, "\n");
    }
    snprintf(path, sizeof path, "%s/dfg_interpolation.dat", dir);
    return atomic_write_text(path, text, e);
}

int dfg_study(const study_context *ctx, const dfg_request *rq, dfg_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->request = *rq;
    out->filament_row = -1;
    if (rq->size_count < 1 || rq->size_count > DFG_STUDY_MAX_SIZES)
        return gt_error_set(e, "dfg", "1 to %d sizes", DFG_STUDY_MAX_SIZES);
    char dir[2048];
    if (study_make_dir(ctx, DFG_LUTS_DIR, dir, sizeof dir, e) != 0 || dfg_write_table(dir, rq->size, ctx->threads, out, e) != 0)
        return -1;
    if (dfg_interpolation_study(rq->sizes, rq->size_count, rq->points, rq->seed, ctx->threads, out->by_size) != 0)
        return gt_error_set(e, "dfg", "interpolation study: out of memory or a size below 2");
    for (int k = 0; k < rq->size_count; ++k)
        if (rq->sizes[k] == DFG_FILAMENT_SIZE)
            out->filament_row = k;
    return write_interpolation_data(dir, out, e);
}
