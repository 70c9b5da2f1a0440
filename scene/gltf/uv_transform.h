/* KHR_texture_transform: texture coordinates moved by an affine map,
 * uv' = T R S uv with T the offset, S the scale and R the rotation by r
 * radians, which the extension's text calls counter-clockwise and whose
 * worked example ("offset [0, 1], rotation pi/2, scale [0.5, 0.5]" selects
 * the lower-left quadrant of the image, rotated) fixes as
 *   u' = s_u cos(r) u + s_v sin(r) v + o_u
 *   v' = -s_u sin(r) u + s_v cos(r) v + o_v.
 * gltfpack writes one to dequantize integer texture coordinates
 * (KHR_mesh_quantization), so a reader that skips it samples textures at the
 * wrong place. The glTF reader bakes a material's transform into the
 * texture coordinates of the meshes that use it. */
#ifndef GTLAB_SCENE_GLTF_UV_TRANSFORM_H
#define GTLAB_SCENE_GLTF_UV_TRANSFORM_H

#include <stddef.h>

typedef struct {
    double m[6]; /* u' = m[0] u + m[1] v + m[2], v' = m[3] u + m[4] v + m[5] */
} uv_transform;

uv_transform uv_transform_identity(void);
uv_transform uv_transform_from_khr(const double offset[2], double rotation, const double scale[2]);
int uv_transform_equal(const uv_transform *a, const uv_transform *b);
/* Applies t to count (u, v) pairs in place. */
void uv_transform_apply(const uv_transform *t, float *uv, size_t count);

#endif
