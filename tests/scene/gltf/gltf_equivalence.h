/* Equivalence of a glTF file and a re-encoded copy of it (quantized,
 * meshopt- or Draco-compressed), shared by the glTF equivalence tests:
 * running gltfpack, and comparing two loaded scenes' geometry and AO.
 *
 * The bounds (docs/design.md, "glTF input"): a quantizer rounding positions
 * to a grid of step s moves each coordinate by at most s / 2, so each vertex
 * by at most d = (sqrt(3) / 2) s; unit normals stored as b-bit normalized
 * integers have each component off by at most 1 / (2 (2^(b-1) - 1)), so the
 * renormalised normal by at most sqrt(3) / (2^(b-1) - 1). AO is compared on
 * the image mean, same camera and seed (so the two renders share their
 * random numbers): it may differ by the Monte Carlo difference of the two
 * (4 standard errors of the per-pixel differences) plus a geometric term:
 * a pixel changes its AO (by at most 1) only where a surface edge passes
 * within d of its ray, at most a fraction d / f of the pixels, f the pixel's
 * footprint at the nearest point of the scene's bounding box. */
#ifndef GTLAB_TESTS_GLTF_EQUIVALENCE_H
#define GTLAB_TESTS_GLTF_EQUIVALENCE_H

#include "scene/scene.h"

/* Runs `gltfpack -i in -o out <flags>`: 0 when out was written, 1 when
 * gltfpack is not installed (the caller skips, saying so), -1 on failure. */
int run_gltfpack(const char *in, const char *out, const char *flags);

/* Each check prints what it measured and every failure, and returns the
 * number of failures (0: equivalent). */

/* The vertices of b against a's, mesh by mesh in order, with the same
 * triangles (each up to a rotation of its corners): at most
 * position_bound apart and normals at most normal_bound apart (a normal_bound
 * < 0 skips normals). */
int check_same_geometry(const scene *a, const scene *b, double position_bound, double normal_bound, const char *what);

/* For files on the same position grid whose codec reorders vertices: every
 * vertex of b lies at the position bits of a vertex of a (mesh by mesh), with
 * a normal at most normal_bound from one of those, and the meshes have as
 * many triangles. */
int check_same_vertex_sets(const scene *a, const scene *b, double normal_bound, const char *what);

/* Renders AO of both with a's camera (64 x 48, same seed) and checks
 * |mean(a) - mean(b)| <= 4 SE + d / f (above) for vertices displaced by at
 * most `displacement`. Prints the numbers. */
int check_same_ao(const scene *a, const scene *b, double displacement, const char *what);

#endif
