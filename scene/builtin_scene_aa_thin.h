/* The built-in scene "aa-thin" (issue 19): content that defeats
 * post-process anti-aliasing, for the anti-aliasing studies. */
#ifndef GTLAB_SCENE_BUILTIN_SCENE_AA_THIN_H
#define GTLAB_SCENE_BUILTIN_SCENE_AA_THIN_H

#include "scene/scene.h"

#define BUILTIN_AA_THIN_DESCRIPTION                                                                              \
    "Content that defeats post-process anti-aliasing (issue 19), four meshes with TEXCOORD_0:\n"               \
    "  mesh 0, floor x, z in [-6, 6] at y = 0 (+Y), uv = 1.25 (x, z): a 32 x 32 texture of 2 x 2-texel\n"     \
    "    checks 0.9 / 0.1 (sRGB), a high-frequency texture of 5 cm checks;\n"                                  \
    "  mesh 1, a wire fence in the plane z = -1.5, x in [-3, 3], y in [0, 2.2]: 51 vertical and 19\n"          \
    "    horizontal wires every 0.12 m, 1 cm wide (quads, normal +Z), grey 0.15;\n"                           \
    "  mesh 2, 600 grass blades, triangles of base 2 cm at (x, 0, z), x in [-3, 3], z in [0.5, 2.5],\n"        \
    "    tips 0.15 .. 0.4 m up, leaning up to 0.08 m (positions from SplitMix64 of the blade index), green\n"  \
    "    (0.2, 0.5, 0.1);\n"                                                                                   \
    "  mesh 3, three 1.2 x 1.2 m vertical foliage cards standing on the floor at x = -2, 0.2, 2.2,\n"   \
    "    z = -0.5, turned 20, -30, 45 deg about +Y, alpha-tested (glTF alphaMode MASK, cutoff 0.5): a\n"        \
    "    64 x 64 RGBA texture, alpha 1 inside 16 elliptic leaves (semi-axes 6 x 2.5 texels, centres on a\n"   \
    "    4 x 4 grid, turned by 40 deg, alternating sign) and 0 elsewhere, green.\n"                          \
    "Materials roughness 0.5, metallic 0. Bounds: [-6, 6] x [0, 2.2] x [-6, 6].\n"                              \
    "Camera: position (1.5, 1.6, 5.5), target (0, 0.8, -0.5), up +Y, yfov 45 deg, 512 x 512.\n"                       \
    "Not in the studies' scene list (builtin_study_scene_at): their results stay the same."

int builtin_build_aa_thin(scene *s);

#endif
