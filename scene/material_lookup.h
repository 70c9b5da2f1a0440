/* Evaluates a glTF metallic-roughness material at a surface point: factors
 * times textures (bilinear, wrapping; the base colour texture decoded from
 * sRGB, the metallic-roughness texture linear), as the glTF 2.0 spec defines. */
#ifndef GTLAB_SCENE_MATERIAL_LOOKUP_H
#define GTLAB_SCENE_MATERIAL_LOOKUP_H

#include "scene/scene.h"

typedef struct {
    float base_color[3]; /* linear albedo */
    float roughness;     /* perceptual; GGX alpha = roughness^2 */
    float metallic;
} material_sample;

material_sample material_lookup(const scene *s, int mesh, const float uv[2]);

/* glTF alpha coverage (alphaMode MASK): 1 if the surface of mesh is there at
 * uv, i.e. its material is opaque or its alpha (base colour factor a times
 * the texture's a, bilinear) is >= the material's alpha cutoff. */
int material_alpha_covers(const scene *s, int mesh, const float uv[2]);

#endif
