/* The plain C scene every renderer reads: triangle meshes already in world
 * space (node transforms applied), glTF metallic-roughness materials, 8-bit
 * textures, and an optional camera. Filled by the glTF reader or by a built-in
 * scene, chosen by scene_load (scene_loaders.h); written back to .glb by the
 * glTF writer (gltf_writer.h). This file knows no file format. */
#ifndef GTLAB_SCENE_SCENE_H
#define GTLAB_SCENE_SCENE_H

#include <stdint.h>

#include "core/error.h"
#include "core/vec3.h"
#include "scene/camera.h"

typedef struct {
    int width, height;
    unsigned char *rgba; /* 8-bit RGBA, rows top to bottom, as stored (sRGB for colour) */
} scene_texture;

typedef struct {
    float base_color[4];         /* linear RGBA factor */
    int base_color_texture;      /* index into textures, or -1 */
    float metallic, roughness;   /* factors; roughness is perceptual (alpha = roughness^2) */
    int metallic_roughness_texture; /* B = metallic, G = roughness (glTF), or -1 */
} scene_material;

typedef struct {
    uint32_t vertex_count, triangle_count;
    float *positions;  /* 3 * vertex_count, world space */
    float *normals;    /* 3 * vertex_count, world space, unit length */
    float *texcoords;  /* 2 * vertex_count, or NULL */
    uint32_t *indices; /* 3 * triangle_count, each < vertex_count */
    int material;      /* index into materials, or -1 for the default material */
    int flat;          /* 1: the glTF primitive had no NORMAL; each triangle has its own three
                        * vertices, their normal the face's (glTF 2.0, "Meshes": flat shading) */
} scene_mesh;

typedef struct {
    char name[256];
    scene_mesh *meshes;
    int mesh_count;
    scene_material *materials;
    int material_count;
    scene_texture *textures;
    int texture_count;
    int has_camera;
    camera camera; /* the glTF (or built-in) camera; width/height from its aspect ratio */
    float *alpha_cutoff; /* NULL (every material opaque), or one per material: the glTF alphaCutoff
                          * of an alphaMode MASK material (a surface point whose alpha, base colour
                          * factor a times texture a, is below it is not there), 0 for an opaque one */
} scene;

/* The glTF default material: white, metallic 1, roughness 1 (glTF 2.0 spec). */
scene_material scene_default_material(void);
const scene_material *scene_mesh_material(const scene *s, const scene_mesh *m);

/* Bounding box of all vertices. */
void scene_bounds(const scene *s, vec3 *lo, vec3 *hi);
uint64_t scene_triangle_count(const scene *s);

/* Adds an empty mesh with room for the given counts (arrays allocated,
 * texcoords only if with_texcoords). Returns it, or NULL if out of memory. */
scene_mesh *scene_add_mesh(scene *s, uint32_t vertex_count, uint32_t triangle_count, int with_texcoords);
int scene_add_material(scene *s, scene_material m);
/* Makes material an alpha-tested one (glTF alphaMode MASK) with the cutoff;
 * 0, or -1 if out of memory. */
int scene_set_alpha_cutoff(scene *s, int material, float cutoff);
/* Computes area-weighted vertex normals from the triangles. */
void scene_mesh_compute_normals(scene_mesh *m);
/* Sets every vertex's normal to its triangle's face normal, normalize((b - a)
 * x (c - a)) (+Y for a degenerate triangle), and marks the mesh flat. For a
 * mesh whose triangles share no vertex (the glTF reader unwelds a primitive
 * without normals first); a shared vertex takes its last triangle's. */
void scene_mesh_compute_flat_normals(scene_mesh *m);
/* Checks finite positions and normals and in-range indices. */
int scene_validate(const scene *s, const char *what, gt_error *e);
void scene_free(scene *s);

/* The camera a render uses (DESIGN.md): the camera JSON file if given, else
 * the scene's own camera, else the automatic framing of its bounds. A width
 * or height > 0 overrides the size; given only one, the other follows the
 * camera's aspect ratio. */
int scene_choose_camera(const scene *s, const char *camera_json_path, int width, int height, camera *cam,
                        gt_error *e);

#endif
