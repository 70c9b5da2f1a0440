/* The precision figures of Kaplanyan 2010 (hdr_precision_study.h). */
#include "hdr_precision/hdr_precision_study.h"

#include <math.h>
#include <stdio.h>

#include "core/files/atomic_file.h"
#include "hdr_precision/hdr_precision.h"

/* One 8-bit code's step in linear units at x: 1/255 linear, (dx/dg)/255 in
 * gamma space (dx/dg = 1 / (dg/dx), by the encodes' derivatives). */
static int write_code_steps(const char *dir, gt_error *e)
{
    char path[4096 + 32];
    snprintf(path, sizeof path, "%s/code_steps.dat", dir);
    atomic_file file;
    FILE *f = atomic_file_open(&file, path, "w", e);
    if (!f)
        return -1;
    fprintf(f, "# x  step_linear  step_gamma22  step_srgb (linear units)\n");
    for (int i = 0; i <= 200; ++i) {
        double x = pow(10.0, -3.0 + 3.0 * i / 200.0), h = 1e-7 * x;
        double d22 = (1.0 / 2.2) * pow(x, 1.0 / 2.2 - 1.0);
        double ds = (srgb_encode(x + h) - srgb_encode(x - h)) / (2.0 * h);
        fprintf(f, "%.6e %.6e %.6e %.6e\n", x, 1.0 / 255.0, 1.0 / (255.0 * d22), 1.0 / (255.0 * ds));
    }
    return atomic_file_close(&file, f, e);
}

int hdr_precision_study(const study_context *ctx, hdr_precision_result *out, gt_error *e)
{
    const double y = HDR_DISPLAY_THRESHOLD;
    out->talk_median = 5.0 / 11.0;
    out->gamma22_point = gamma_equal_precision_point(2.2);
    out->srgb_point = srgb_equal_precision_point();
    out->exponential_c_min = exponential_c_min(1.0, y);
    out->exponential_bisection = tonemap_c_min_bisection(tonemap_exponential, 0, 1.0, y);
    out->filmic_c_min = filmic_c_min(1.0, y);
    out->filmic_bisection = tonemap_c_min_bisection(tonemap_filmic_display, 1, 1.0, y);
    out->filmic_transcribed_c_min = tonemap_c_min_bisection(tonemap_filmic_transcribed_display, 1, 1.0, y);
    out->filmic_display_threshold_c_min = tonemap_c_min_bisection(tonemap_filmic_display, 0, 1.0, y);
    char dir[4096];
    return study_make_dir(ctx, HDR_PRECISION_DIR, dir, sizeof dir, e) != 0 ? -1 : write_code_steps(dir, e);
}
