/* The silhouette region of a G-buffer: the surface pixels within a few
 * pixels of a depth discontinuity, where screen-space techniques lose the
 * geometry behind an edge (the GTSO talk's "overdarkening near the
 * silhouette", issue 26). A discontinuity lies between two 4-neighbours when
 *   - one is a surface pixel and the other background (mask < 0.5), or
 *   - both are surface pixels and their view distances d1, d2 differ by more
 *     than `relative_jump` times the nearer one: |d1 - d2| > j min(d1, d2).
 * The image border is not a discontinuity. A surface pixel belongs to the
 * region when a discontinuity touches a pixel within Chebyshev distance
 * `radius` of it (a (2 radius + 1)^2 square). */
#ifndef GTLAB_METRICS_SILHOUETTE_REGION_H
#define GTLAB_METRICS_SILHOUETTE_REGION_H

/* Writes 1 into region[i] for the surface pixels of the silhouette region, 0
 * for every other pixel; `interior` (may be NULL) receives the other surface
 * pixels (1) and 0 elsewhere. depth: view distance per pixel (read only where
 * mask >= 0.5). Returns 0, or -1 when out of memory. */
int silhouette_region(const float *depth, const float *mask, int width, int height, int radius,
                      double relative_jump, float *region, float *interior);

#endif
