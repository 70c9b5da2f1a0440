/* The pieces the built-in scenes are made of (builtin_scenes.c and the
 * procedural family, builtin_scene_family.c): flat quads, each with its own
 * four vertices and its exact flat normal, so no normal is ever averaged
 * across a hard edge; boxes as sets of quads whose corners come from the same
 * numbers, so shared edges are bit-identical and rays cannot leak through
 * cracks; a matte material, a camera, and a deterministic hash for the
 * scenes' pseudo-random layouts. */
#ifndef GTLAB_SCENE_QUAD_MESH_H
#define GTLAB_SCENE_QUAD_MESH_H

#include <stdint.h>

#include "scene/scene.h"

/* Four corners, counter-clockwise seen from the side the normal points to. */
typedef struct {
    vec3 p[4];
} quad;

typedef struct {
    quad *items;
    uint32_t count, capacity;
} quad_list;

int quad_list_push(quad_list *l, quad q); /* 0, or -1 out of memory */
void quad_list_free(quad_list *l);

/* One mesh of the quads: 4 vertices and 2 triangles (0 1 2, 0 2 3) per quad,
 * the normal of each quad's vertices its own plane's (computed in double). */
int quad_mesh_add(scene *s, const quad_list *l, int material);

/* A box's corner c has bit 0 set on its +x side, bit 1 on +y, bit 2 on +z (in
 * the box's own axes). */
enum { FACE_POS_X, FACE_NEG_X, FACE_POS_Y, FACE_NEG_Y, FACE_POS_Z, FACE_NEG_Z };
#define FACE_BIT(f) (1u << (f))
#define ALL_FACES 0x3fu

void aligned_box_corners(vec3 lo, vec3 hi, vec3 corners[8]);
/* A block of size (x, height, z) standing on y = 0 with its base centred at
 * base_centre, turned by angle (radians, counter-clockwise seen from above,
 * i.e. a right-handed rotation about +Y). */
void turned_block_corners(vec3 base_centre, vec3 size, double angle, vec3 corners[8]);
/* Pushes the faces in face_mask (each counter-clockwise seen from outside);
 * inward reverses them so that their normals face into the box (room walls). */
int push_box_faces(quad_list *l, const vec3 corners[8], unsigned face_mask, int inward);

/* Base colour (r, g, b), metallic 0, roughness 0.5, no textures. */
scene_material scene_matte_material(float r, float g, float b);
/* The scene's camera: up +Y, 512 x 512. */
void scene_set_camera(scene *s, vec3 position, vec3 target, float yfov_deg);

/* PCG hash: Jarzynski and Olano 2020, "Hash Functions for GPU Rendering"
 * (JCGT 9(3)), a good one-round 32-bit hash; deterministic everywhere. */
uint32_t scene_pcg_hash(uint32_t v);
/* scene_pcg_hash(n) as a float in [0, 1) (24 bits). */
float scene_unit_hash(uint32_t n);

#endif
