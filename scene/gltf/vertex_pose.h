/* The default pose of a glTF mesh (glTF 2.0, "Morph Targets" and "Skins"):
 *
 * Morph targets: p = p_0 + sum_i w_i t_i for positions and normals, with the
 * weights of the node (else of the mesh, else zero); normals are
 * renormalised by whoever uses them.
 *
 * Skins: each vertex's skin matrix is S = sum_k w_k J_{j_k} over its joint
 * influences (JOINTS_n / WEIGHTS_n), J_j = G_j * IBM_j the joint node's global
 * transform times its inverse bind matrix; positions become S p, in world
 * space (the skinned node's own transform is ignored, as the spec says), and
 * normals cof(S) n = det(S) S^-T n with the sign of det(S) (the cofactor form
 * needs no division; the length is renormalised later). Matrices are 4x4
 * column-major doubles, m[4 * column + row], as glTF stores them. */
#ifndef GTLAB_SCENE_GLTF_VERTEX_POSE_H
#define GTLAB_SCENE_GLTF_VERTEX_POSE_H

#include <stddef.h>
#include <stdint.h>

/* base[i] += weight * delta[i] for i < n. */
void pose_morph_add(float *base, const float *delta, float weight, size_t n);

/* The skin matrix of one vertex from `influences` (joint, weight) pairs;
 * joints index joint_matrices (16 doubles each), already range-checked. */
void pose_skin_matrix(const double *joint_matrices, const uint32_t *joints, const float *weights, int influences,
                      double out[16]);

/* Applies S (above) to vertex_count positions (3 floats each) and, when not
 * NULL, normals. joints/weights hold `influences` entries per vertex. */
void pose_skin_vertices(const double *joint_matrices, const uint32_t *joints, const float *weights, int influences,
                        size_t vertex_count, float *positions, float *normals);

#endif
