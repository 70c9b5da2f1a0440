/* The split-sum DFG (environment BRDF) LUT of Karis 2013 (luts/dfg_lut.h) as
 * `gtlab all` studies it: the table an engine ships, written in every format,
 * and the bilinear lookup's interpolation error against the exact quadrature
 * as a function of the table's size, beside Filament's published choice of
 * 128 x 128 (a comparison, not an input: nothing here depends on it).
 *
 * Writes <output>/luts/dfg_<N>.{exr,png,h,hlsl,glsl} and <output>/luts/dfg_
 * interpolation.dat (size, then max and RMS error of A, B, E over the square
 * and between the texel centres), the data of the report's plot. */
#ifndef GTLAB_DFG_STUDY_H
#define GTLAB_DFG_STUDY_H

#include "dfg/dfg_interpolation.h"
#include "project/study_context.h"

#define DFG_LUTS_DIR "luts"
/* Filament's DFG table (libs/ibl, cmgen): 128 x 128, RG16F. */
enum { DFG_FILAMENT_SIZE = 128, DFG_STUDY_MAX_SIZES = 8 };

typedef struct {
    int size;                          /* the table written in every format */
    int sizes[DFG_STUDY_MAX_SIZES];    /* the interpolation study's sizes, increasing */
    int size_count;
    int points;                        /* random (n.v, r) points the lookup is scored at */
    unsigned seed;
} dfg_request;

typedef struct {
    dfg_request request;
    double max_error_estimate;  /* the written table's quadrature error bound */
    double build_seconds;       /* of the written table */
    double e_min;               /* smallest texel of E: the most energy single scattering loses */
    dfg_interpolation_result by_size[DFG_STUDY_MAX_SIZES];
    int filament_row;           /* index of DFG_FILAMENT_SIZE in by_size, or -1 */
} dfg_result;

/* Preview: sizes 16 to 128, 1024 points; production adds 256, 4096 points.
 * Both write the 128 x 128 table. */
dfg_request dfg_default_request(study_quality quality);

/* Builds the size x size table and writes <dir>/dfg_<size>.{exr,png,h,hlsl,glsl}
 * (`gtlab lut dfg` and the study): fills out's max_error_estimate,
 * build_seconds and e_min. */
int dfg_write_table(const char *dir, int size, int threads, dfg_result *out, gt_error *e);

int dfg_study(const study_context *ctx, const dfg_request *rq, dfg_result *out, gt_error *e);

#endif
