/* The Kulla-Conty energy compensation (kulla_conty_lut.h) as `gtlab all`
 * studies it: the average-albedo table an engine ships beside its DFG table,
 * written as luts/kulla_conty_eavg_<N>.{exr,png,h}, and what its size costs
 * the white furnace: with E exact, the compensated albedo
 *   E(mu_o) + (1 - E(mu_o)) (1 - E_avg(r)) / (1 - E_avg_table(r))
 * is 1 only when the table's E_avg is exact, so its distance from 1 at
 * points between the texel centres is the table's own error, in the units
 * a viewer judges (relative reflected energy of a white surface). */
#ifndef GTLAB_KULLA_CONTY_STUDY_H
#define GTLAB_KULLA_CONTY_STUDY_H

#include "kulla_conty/kulla_conty_lut.h"
#include "project/study_context.h"

#define KULLA_CONTY_DIR "luts"
enum { KULLA_CONTY_MAX_SIZES = 8, KULLA_CONTY_LOSS_ROWS = 5 };

typedef struct {
    int size;                           /* the table written */
    int sizes[KULLA_CONTY_MAX_SIZES];   /* the sizes scored, increasing */
    int size_count;
    int roughness_points;               /* test roughnesses (j + 0.37) / K, off every size's centres */
    int mu_points;                      /* viewing cosines (m + 0.5) / M of the furnace */
} kulla_conty_request;

typedef struct {
    int size;
    double max_error, rms_error;  /* |E_avg_table - E_avg| over the test roughnesses */
    double max_furnace_error;     /* max |compensated albedo - 1| over the (mu_o, r) grid */
} kulla_conty_size_row;

typedef struct {
    double roughness, average_albedo, energy_lost; /* 1 - E_avg: what single scattering loses on average */
} kulla_conty_loss_row;

typedef struct {
    kulla_conty_request request;
    double max_error_estimate;  /* the written table's quadrature bound */
    kulla_conty_loss_row loss[KULLA_CONTY_LOSS_ROWS];
    kulla_conty_size_row by_size[KULLA_CONTY_MAX_SIZES];
    double seconds;
} kulla_conty_result;

/* The request of `gtlab all` at a quality: how many of the sizes 4 to 256 it
 * scores, its roughnesses and cosines are the quality table's (kulla_conty
 * rows of techniques/quality_table.txt). Both write the 32-entry table. */
kulla_conty_request kulla_conty_default_request(study_quality quality);

/* Builds the size-entry table and writes <dir>/kulla_conty_eavg_<size>.{exr,png,h}
 * (`gtlab lut kulla-conty` and the study); *bound (may be NULL): its quadrature bound. */
int kulla_conty_write_table(const char *dir, int size, int threads, double *bound, gt_error *e);

int kulla_conty_study(const study_context *ctx, const kulla_conty_request *rq, kulla_conty_result *out,
                      gt_error *e);

#endif
