/* The Decima atmosphere LUTs (atmosphere/atmosphere_luts.h) as `gtlab all` studies
 * them (issue 16 items 3 and 5): the talk's tables for the two weathers,
 * written in every format, and "do the sizes suffice?": the error of each
 * table against direct integration at random points (atmosphere/atmosphere_lut_
 * errors.h: interpolation and quadrature apart) as one axis at a time
 * departs from the talk's size, (8, 64, 8, 4) = 128 KB and (64, 1, 4) =
 * 4 KB, against the memory it takes.
 *
 * Tolerance: a table suffices when the 95th percentile of its relative
 * error is within ATMOSPHERE_TOLERANCE = 2% (the eye's contrast threshold
 * for luminance, Weber's fraction, is 1-2%; banding shows at about 2% steps)
 * or within the quadrature's own 95th percentile if that is larger (the
 * reference's floor), with its 95% interval (p95 +- 1.96 s.e.): an interval
 * that straddles the tolerance is undecided (too few points). The points'
 * day (sun 10 deg or more above the horizon) and twilight (the rest, to 6
 * deg below) are also scored apart.
 *
 * The sky (issue 42): the in-scatter table under each parametrization
 * (atmosphere/atmosphere_lut_axes.h: gtlab's linear one, Yusov 2013's, the talk's
 * "[Yus13]", and Bruneton & Neyret 2008's) at the talk's size and one axis
 * at a time around it, scored on sky-dome pixels (atmosphere/atmosphere_lut_
 * errors.h, atmosphere_sky_errors: the table's interpolation alone) by day
 * (sun 10 deg or more above the horizon) and in twilight (10 deg above to
 * 6 deg below) apart, each as the 95th percentile of the pixels' relative
 * error with its bootstrap standard error.
 *
 * Writes <output>/luts/atmosphere/ (the talk-size tables: the linear set
 * as EXR, C header, HLSL, GLSL; Yusov 2013's, the talk's, and Bruneton &
 * Neyret's as EXR, atmosphere_{inscatter,sun,sky}_{yusov2013,bruneton2008}
 * .exr: atmosphere/atmosphere_luts_writers.h), in production also
 * <output>/luts/atmosphere/x4/ (Yusov's set with the in-scatter table at 4x
 * the talk's size on every spatial axis, the sky table's x4 row), and
 * <output>/luts/atmosphere_sizes.dat (per row: table, bytes, interpolation
 * p95 and max, total p95), the data of the report's plot. Every file's bytes
 * are independent of the thread count. */
#ifndef GTLAB_ATMOSPHERE_LUTS_STUDY_H
#define GTLAB_ATMOSPHERE_LUTS_STUDY_H

#include "atmosphere/atmosphere_lut_errors.h"
#include "atmosphere/atmosphere_luts.h"
#include "project/study_context.h"

#define ATMOSPHERE_LUTS_DIR "luts"
#define ATMOSPHERE_TOLERANCE 0.02
enum { ATMOSPHERE_STUDY_MAX_ROWS = 40, ATMOSPHERE_STUDY_MAX_BLENDS = 4, ATMOSPHERE_SKY_MAX_ROWS = 40 };
enum { ATMOSPHERE_FILE_SETS = ATMOSPHERE_PARAMS + 1, ATMOSPHERE_SET_FILES = 6 };
#define ATMOSPHERE_TWILIGHT_THETA_S (96.0 * 3.14159265358979323846 / 180.0) /* civil twilight's end */

typedef struct {
    int points;                  /* random points the tables are scored at */
    int blend_count;             /* their weather blends, off the t grid */
    double blends[ATMOSPHERE_STUDY_MAX_BLENDS];
    int uniform_refinement;      /* also the in-scatter table at twice the talk's size on every spatial axis */
    unsigned seed;
    int sky_pixels;              /* sky-dome pixels per regime (day, twilight) */
    int sky_refinement;          /* also the sky at 4x the talk's size on every spatial axis */
} atmosphere_luts_request;

typedef struct {
    char label[48];              /* what departs from the talk's size */
    int table;                   /* ATMOSPHERE_TABLE_* */
    int sizes[4];
    double bytes;
    int talk;                    /* 1 for the talk's size */
    atmosphere_table_error error;
} atmosphere_luts_row;

/* The sky through one in-scatter table. */
typedef struct {
    char label[48];              /* what departs from the talk's size */
    atmosphere_lut_parametrization parametrization;
    int sizes[4];
    double bytes;
    int talk;                    /* 1 for the talk's size */
    atmosphere_error_stats day, twilight;
} atmosphere_sky_row;

/* One written set of tables: its parametrization, sizes and files (paths
 * below the output folder). */
typedef struct {
    atmosphere_lut_parametrization parametrization;
    atmosphere_lut_sizes sizes;
    int count;
    char files[ATMOSPHERE_SET_FILES][160];
} atmosphere_luts_file_set;

typedef struct {
    atmosphere_luts_request request;
    double build_seconds;        /* the talk-size set for two weathers (4 blends), wall */
    double quadrature_estimate;  /* the references' own error estimate (relative to their scales) */
    int row_count;
    atmosphere_luts_row rows[ATMOSPHERE_STUDY_MAX_ROWS];
    int smallest_within[ATMOSPHERE_TABLES]; /* row of the smallest table within tolerance, or -1 */
    int talk_row[ATMOSPHERE_TABLES];
    int sky_row_count;
    atmosphere_sky_row sky_rows[ATMOSPHERE_SKY_MAX_ROWS];
    int sky_talk_row[ATMOSPHERE_PARAMS]; /* row of the talk's size per parametrization, or -1 */
    int file_set_count;
    atmosphere_luts_file_set file_sets[ATMOSPHERE_FILE_SETS];
} atmosphere_luts_result;

/* The request of `gtlab all` at a quality: its points, weather blends (at
 * t = 1/2 for one, 1/6, 1/2, 5/6 for three), sky pixels and whether the
 * refined in-scatter table and sky are scored are the quality table's
 * (atmosphere rows of techniques/quality_table.txt); seed 1. */
atmosphere_luts_request atmosphere_luts_default_request(study_quality quality);

#define ATMOSPHERE_INTERVAL_Z 1.959963984540054 /* the two-sided 95% normal quantile */
/* +1 when a row's 95% interval lies within the tolerance (the definition
 * above), -1 when it lies beyond, 0 when it straddles it (undecided). */
int atmosphere_luts_row_decision(const atmosphere_luts_row *row);
/* Whether a row is within the tolerance: its decision is +1. */
int atmosphere_luts_row_suffices(const atmosphere_luts_row *row);

/* Builds the tables of `kind` at `sizes` (NULL: the talk's) and writes
 * them into dir (`gtlab lut atmosphere`; the study writes the same from
 * its solutions): the linear set in every format, another as its three
 * EXRs. The bytes do not depend on `threads`. */
int atmosphere_luts_write_tables(const char *dir, const atmosphere_lut_sizes *sizes,
                                 atmosphere_lut_parametrization kind, int threads, double *build_seconds, gt_error *e);

int atmosphere_luts_study(const study_context *ctx, const atmosphere_luts_request *rq, atmosphere_luts_result *out,
                          gt_error *e);

#endif
