/* Morph targets and skins in the default pose: see vertex_pose.h. */
#include "scene/gltf/vertex_pose.h"

#include <string.h>

void pose_morph_add(float *base, const float *delta, float weight, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        base[i] += weight * delta[i];
}

void pose_skin_matrix(const double *joint_matrices, const uint32_t *joints, const float *weights, int influences,
                      double out[16])
{
    memset(out, 0, 16 * sizeof out[0]);
    for (int k = 0; k < influences; ++k) {
        const double *j = &joint_matrices[16 * (size_t)joints[k]];
        for (int c = 0; c < 16; ++c)
            out[c] += (double)weights[k] * j[c];
    }
}

static void transform_point(const double m[16], float p[3])
{
    double r[3];
    for (int row = 0; row < 3; ++row)
        r[row] = m[row] * p[0] + m[4 + row] * p[1] + m[8 + row] * p[2] + m[12 + row];
    for (int row = 0; row < 3; ++row)
        p[row] = (float)r[row];
}

static double det3(const double m[16])
{
    return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
           m[8] * (m[1] * m[6] - m[5] * m[2]);
}

/* n <- sign(det) cof(M) n, cof(M)_{row,col} the (row, col) cofactor of M's 3x3 part. */
static void transform_normal(const double m[16], float n[3])
{
    const double sign = det3(m) < 0.0 ? -1.0 : 1.0;
    double r[3] = {0, 0, 0};
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) {
            const int r0 = (row + 1) % 3, r1 = (row + 2) % 3, c0 = (col + 1) % 3, c1 = (col + 2) % 3;
            const double cof = m[4 * c0 + r0] * m[4 * c1 + r1] - m[4 * c1 + r0] * m[4 * c0 + r1];
            r[row] += sign * cof * n[col];
        }
    for (int row = 0; row < 3; ++row)
        n[row] = (float)r[row];
}

void pose_skin_vertices(const double *joint_matrices, const uint32_t *joints, const float *weights, int influences,
                        size_t vertex_count, float *positions, float *normals)
{
    for (size_t i = 0; i < vertex_count; ++i) {
        double s[16];
        const size_t at = i * (size_t)influences;
        pose_skin_matrix(joint_matrices, &joints[at], &weights[at], influences, s);
        transform_point(s, &positions[3 * i]);
        if (normals)
            transform_normal(s, &normals[3 * i]);
    }
}
