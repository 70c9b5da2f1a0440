/* Best-fit normals (Kaplanyan 2010, "CryENGINE 3: Reaching the Speed of
 * Light", slides "Normals precision for shading" and Appendix A).
 *
 * A G-buffer stores a unit normal n in an RGB8 target as the code
 * c = round((s n * 0.5 + 0.5) * 255), read back as normalize(2 c / 255 - 1).
 * Storing the normalised normal (s = 1) uses only the cells of the 256^3
 * cube that the unit sphere crosses; but any s > 0 decodes to the same
 * direction, so each direction may pick, along its ray from the centre, the
 * cell whose centre deviates least from the ray.
 *
 * The talk's search (Appendix A, FindMinimumQuantizationError) divides n by
 * its largest |component| (the ray then ends on the cube's surface) and
 * probes t = k / 127.5, k = 1.5, 2.5, ..., 127.5: the major component of
 * the probe p = t n / max|n_i| then sits exactly on a cell centre. Each
 * probe is quantised per component (quantize255 below) and scored by the
 * talk's error max_i |q_i - p_i| / t; the first minimum wins. This file also
 * scores by the true quantity, the angle between q and n
 * (BFN_ERROR_ANGLE), and searches exhaustively: every major-axis slab, the
 * 3 x 3 cells about the ray's crossing (bfn_best_cell_exhaustive).
 *
 * The table (the talk's "unique part" of the cubemap of best scales): for a
 * unit n, let a >= b be the two smaller |components|; texel coordinates are
 * (u, v) = (a, b / a). Each texel stores the best t for the direction its
 * centre encodes; since t = (2 k) / 255 with 2 k odd in 3..255, 8 bits hold
 * it exactly ("the 8-bits precision is sufficient"). Texels whose (u, v)
 * encode no direction (a above the major component: u > 1 / sqrt(2 + v^2))
 * repeat the nearest valid texel of their row, so filtering near the edge
 * reads valid neighbours. */
#ifndef GTLAB_BEST_FIT_NORMALS_H
#define GTLAB_BEST_FIT_NORMALS_H

#include <stdint.h>

enum { BFN_TALK_SIZE = 512, BFN_MAX_SIZE = 4096 };

typedef enum { BFN_ERROR_PUBLISHED, BFN_ERROR_ANGLE, BFN_ERROR_COUNT } bfn_error_metric;

const char *bfn_error_metric_name(int metric);

/* Appendix A: w = saturate(c * 0.5 + 0.5); r = round(w * 255);
 * return r / 255 * 2 - 1 (round: to nearest, ties up). */
double bfn_quantize255(double c);

/* The RGB8 code of quantize255's value and back: code = round(w * 255). */
int bfn_code(double c);
double bfn_code_value(int code);

/* The angle in radians between two vectors (atan2 form: accurate near 0). */
double bfn_angle(const double a[3], const double b[3]);

/* The talk's search for the unit (or any non-zero) n with the given error
 * metric: returns the best probe's t in (0, 1] and its quantised vector in
 * q (values in [-1, 1]). */
double bfn_best_scale(const double n[3], bfn_error_metric metric, double q[3]);

/* The cell whose centre is closest in angle to n among every major-axis
 * slab's 3 x 3 cells about the ray: the best any RGB8 code achieves (up to
 * that neighbourhood). Returns the angle; q receives the cell's value. */
double bfn_best_cell_exhaustive(const double n[3], double q[3]);

/* The unit direction a texel centre (u, v) encodes, major axis +z:
 * (a, a v, sqrt(1 - a^2 - a^2 v^2)) with a = u; 0 if (u, v) encodes none. */
int bfn_texel_direction(double u, double v, double n[3]);

/* The size x size table of best scales t (row j = v, column i = u, texel
 * centres), searched with the metric; OpenMP over rows, bits independent of
 * threads. Returns NULL when out of memory. The caller frees. */
float *bfn_table_build(int size, bfn_error_metric metric, int threads);

/* The shader's lookup of the best scale for unit n: point (nearest texel)
 * or bilinear (clamp to edge), as tex2D with those filters. */
double bfn_table_lookup(const float *table, int size, int bilinear, const double n[3]);

#endif
