/* Best-fit normals (Kaplanyan 2010) as `gtlab all` studies them: the table
 * the talk ships (512^2, best_fit_normals/best_fit_normals.h) written in every format;
 * the audit of the talk's cell counts ("Storage techniques breakdown");
 * the angular error of each G-buffer normal encoding over uniformly random
 * directions; and what that error does to a GGX highlight.
 *
 * The highlight: a gently curved surface (normals within ~12 degrees of its
 * axis, the case where banding shows), turned by a fixed generic rotation
 * so the encodings see world-space normals in no special position, viewed
 * along the axis and lit from the mirror direction, radiance
 * f_GGX(v, l) n.l tone-mapped by x / (1 + x) after scaling the exact image's
 * peak to 4; DSSIM of each encoding's image against the exact normals'.
 * Writes <output>/normals/best_fit_normals_512.{exr,png,h,hlsl},
 * highlight previews, normals/cells.dat (face, sampled counts) and
 * normals/error_cdf.dat (each encoding's error by percentile). */
#ifndef GTLAB_BEST_FIT_NORMALS_STUDY_H
#define GTLAB_BEST_FIT_NORMALS_STUDY_H

#include "project/study_context.h"

#define NORMALS_DIR "best_fit_normals"

enum {
    NORMALS_MAX_FACES = 6,
    NORMALS_ROUGHNESSES = 4,
    NORMALS_HIGHLIGHT_SIZE = 256,
    /* naive, max, best fit point / bilinear / exhaustive, octahedral 8, 10, 12 bits plain / precise */
    NORMALS_ENCODINGS = 11
};

typedef struct {
    int table_size;
    int directions;            /* random directions the error statistics use */
    int exhaustive_directions; /* the first of them the exhaustive best cell is searched for */
    int faces[NORMALS_MAX_FACES]; /* cubemap faces of the sampled cell counts, increasing */
    int face_count;
    unsigned seed;
} normals_request;

typedef struct {
    const char *name;
    int bits;                      /* bits per normal */
    int directions;                /* directions it was scored on */
    double mean_deg, p99_deg, max_deg;
    double highlight_dssim[NORMALS_ROUGHNESSES];
} normals_encoding_result;

typedef struct {
    int face;
    long naive, max, best_fit;
} normals_cells_row;

typedef struct {
    normals_request request;
    double table_seconds;
    long cells_sphere, cells_surface, cells_distinct; /* the exact counts */
    normals_cells_row sampled[NORMALS_MAX_FACES];
    double roughness[NORMALS_ROUGHNESSES];
    normals_encoding_result encodings[NORMALS_ENCODINGS];
} normals_result;

/* The request of `gtlab all` at a quality: its directions (and the
 * exhaustive search's) and how many of the faces 512 to 8192 it samples are
 * the quality table's (best_fit_normals rows of techniques/quality_table.txt).
 * Both the 512^2 table. */
normals_request normals_default_request(study_quality quality);

/* Builds and writes the table of `size` with the talk's metric to <dir>
 * (`gtlab lut best-fit-normals` and the study); *seconds its build time.
 * Returns the table (caller frees) or NULL with e. */
float *normals_write_table(const char *dir, int size, int threads, double *seconds, gt_error *e);

int normals_study(const study_context *ctx, const normals_request *rq, normals_result *out, gt_error *e);

#endif
