/* The description of a GTSO cone/lobe table (specular_occlusion_lut.h) as
 * JSON, beside the table's EXR/PNG/C files (lut_writers.h): lobe, size,
 * axes and their layout, the quadrature error estimate, the trilinear
 * interpolation error at `points` random points
 * (so_lut_interpolation_error) and the seconds the build took. Written by
 * `gtlab lut specular-occlusion`. */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_LUT_WRITERS_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_LUT_WRITERS_H

#include "core/error.h"
#include "specular_occlusion/specular_occlusion_lut.h"

int so_lut_write_json(const char *path, const so_lut *lut, double seconds, int points, double max_interp,
                      double rms_interp, gt_error *e);

/* What so_lut_make built and wrote. */
typedef struct {
    char base[128];                  /* specular_occlusion_<lobe>_<size> */
    double seconds;                  /* the build's */
    double max_error_estimate;       /* the quadrature's */
    double max_interp, rms_interp;   /* trilinear lookup against direct integration */
} so_lut_made;

/* Builds the table and writes dir/<base>.{exr,png,h} (lut_writers.h) and
 * .json, its interpolation error measured at `points` random points. 0, or
 * -1 with e. */
int so_lut_make(const char *dir, int size, so_lobe lobe, so_lut_axes axes, int threads, int points, so_lut_made *out,
                gt_error *e);

#endif
