/* Built-in procedural scenes (builtin_scenes.h): a table of names, exact
 * descriptions and builders. Flat surfaces are lists of quads, each quad with
 * its own four vertices and its exact flat normal, so no normal is ever
 * averaged across a hard edge; corners shared by neighbouring quads are
 * computed once (or from the same integers), so shared edges are bit-identical
 * and rays cannot leak through cracks. The sphere is an icosphere whose
 * vertices lie on the sphere and carry the exact sphere normals. */
#include "scene/builtin_scenes.h"

#include "scene/builtin_scene_ao_decals.h"
#include "scene/builtin_scene_aa_thin.h"
#include "scene/builtin_scene_family.h"
#include "scene/quad_mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double pi = 3.14159265358979323846;

/* ---- Materials and cameras ------------------------------------------------ */

/* The generic white of every scene but the Cornell box: albedo 0.8, the usual
 * "white" of production scenes (a physical albedo, unlike 1.0). */
static int add_white_material(scene *s) { return scene_add_material(s, scene_matte_material(0.8f, 0.8f, 0.8f)); }

/* ---- The floor shared by most scenes ---------------------------------------- */

static int add_floor(scene *s, int material)
{
    quad_list l = {0};
    quad q = {{v3(-50.0f, 0.0f, -50.0f), v3(-50.0f, 0.0f, 50.0f), v3(50.0f, 0.0f, 50.0f), v3(50.0f, 0.0f, -50.0f)}};
    int rc = quad_list_push(&l, q) == 0 ? quad_mesh_add(s, &l, material) : -1;
    quad_list_free(&l);
    return rc;
}

/* ---- Icosphere ---------------------------------------------------------------- */

/* Unit vectors in double until the mesh is written, so every vertex is on the
 * sphere to double precision before the single rounding to float. */
typedef struct {
    double (*vertices)[3];
    uint32_t (*faces)[3];
    uint32_t vertex_count, face_count;
} icosphere;

/* Open-addressing map from an undirected edge to the vertex at its midpoint. */
typedef struct {
    uint64_t *keys; /* (lo << 32 | hi) + 1; 0 = empty slot */
    uint32_t *values;
    size_t mask;
} edge_map;

static uint32_t edge_midpoint(edge_map *map, icosphere *ico, uint32_t a, uint32_t b)
{
    uint64_t key = (a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a) + 1;
    size_t slot = (size_t)((key * 0x9E3779B97F4A7C15ull) >> 32) & map->mask; /* Fibonacci hashing */
    for (; map->keys[slot]; slot = (slot + 1) & map->mask)
        if (map->keys[slot] == key)
            return map->values[slot];
    const double *p = ico->vertices[a], *q = ico->vertices[b];
    double m[3] = {p[0] + q[0], p[1] + q[1], p[2] + q[2]};
    double len = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    uint32_t v = ico->vertex_count++;
    for (int k = 0; k < 3; ++k)
        ico->vertices[v][k] = m[k] / len;
    map->keys[slot] = key;
    map->values[slot] = v;
    return v;
}

/* The icosahedron with vertices at the poles (0, +-1, 0) and two rings of
 * five at latitude +-atan(1/2), the lower ring turned by 36 degrees; faces
 * counter-clockwise seen from outside. */
static void icosahedron(icosphere *ico)
{
    const double ring_y = 1.0 / sqrt(5.0), ring_r = 2.0 / sqrt(5.0);
    double(*v)[3] = ico->vertices;
    v[0][0] = 0.0, v[0][1] = 1.0, v[0][2] = 0.0;
    v[11][0] = 0.0, v[11][1] = -1.0, v[11][2] = 0.0;
    for (int k = 0; k < 5; ++k) {
        double upper = 2.0 * pi * k / 5.0, lower = upper + pi / 5.0;
        v[1 + k][0] = ring_r * cos(upper), v[1 + k][1] = ring_y, v[1 + k][2] = ring_r * sin(upper);
        v[6 + k][0] = ring_r * cos(lower), v[6 + k][1] = -ring_y, v[6 + k][2] = ring_r * sin(lower);
    }
    ico->vertex_count = 12;
    uint32_t(*f)[3] = ico->faces;
    for (uint32_t k = 0; k < 5; ++k) {
        uint32_t u0 = 1 + k, u1 = 1 + (k + 1) % 5, l0 = 6 + k, l1 = 6 + (k + 1) % 5;
        const uint32_t tris[4][3] = {{0, u1, u0}, {u0, u1, l0}, {u1, l1, l0}, {11, l0, l1}};
        memcpy(f[4 * k], tris, sizeof tris);
    }
    ico->face_count = 20;
}

/* Splits every face into four at its edge midpoints, projected onto the sphere. */
static void subdivide(icosphere *ico, uint32_t (*out)[3], edge_map *map)
{
    memset(map->keys, 0, sizeof *map->keys * (map->mask + 1));
    for (uint32_t t = 0; t < ico->face_count; ++t) {
        uint32_t a = ico->faces[t][0], b = ico->faces[t][1], c = ico->faces[t][2];
        uint32_t ab = edge_midpoint(map, ico, a, b), bc = edge_midpoint(map, ico, b, c),
                 ca = edge_midpoint(map, ico, c, a);
        const uint32_t children[4][3] = {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}};
        memcpy(out[4 * t], children, sizeof children);
    }
    memcpy(ico->faces, out, sizeof *out * 4 * ico->face_count);
    ico->face_count *= 4;
}

/* Level L has 20 4^L faces and 10 4^L + 2 vertices. */
static int icosphere_build(icosphere *ico, int levels)
{
    uint32_t faces = 20u << (2 * levels), vertices = 10u * (1u << (2 * levels)) + 2u;
    size_t edges_split_last = (30u << (2 * levels)) / 4, slots = 1; /* the map stays at most half full */
    while (slots < 2 * edges_split_last)
        slots *= 2;
    edge_map map = {malloc(slots * sizeof(uint64_t)), malloc(slots * sizeof(uint32_t)), slots - 1};
    uint32_t(*scratch)[3] = malloc(sizeof *scratch * faces);
    ico->vertices = malloc(sizeof *ico->vertices * vertices);
    ico->faces = malloc(sizeof *ico->faces * faces);
    int ok = map.keys && map.values && scratch && ico->vertices && ico->faces;
    if (ok) {
        icosahedron(ico);
        for (int level = 0; level < levels; ++level)
            subdivide(ico, scratch, &map);
    }
    free(map.keys);
    free(map.values);
    free(scratch);
    if (!ok) {
        free(ico->vertices);
        free(ico->faces);
        return -1;
    }
    return 0;
}

/* Why 7 levels: the icosphere is convex and lies between the unit sphere and
 * the ball of radius r_in, its smallest centre-to-face-plane distance. The
 * solid angle of a ball of radius r seen from distance d,
 *   Omega(r) = 2 pi (1 - sqrt(1 - (r/d)^2)),
 * grows with r with slope dOmega/dr = 2 pi r / (d sqrt(d^2 - r^2)), steepest
 * at the nearest floor point (d = 1.5, straight below): 3.75 sr per unit of
 * radius. So the solid-angle error anywhere on the floor is at most
 * Omega(1) - Omega(r_in) at d = 1.5. Level 6 has 1 - r_in = 7.1e-5 (bound
 * 2.7e-4 sr: not enough); level 7 has 1 - r_in = 1.8e-5, bound 6.7e-5 sr
 * < 1e-4. (The test recomputes r_in and the bound from the mesh.) */
enum { SPHERE_LEVELS = 7 };

static int add_sphere(scene *s, vec3 centre, float radius, int material)
{
    icosphere ico;
    if (icosphere_build(&ico, SPHERE_LEVELS) != 0)
        return -1;
    scene_mesh *m = scene_add_mesh(s, ico.vertex_count, ico.face_count, 0);
    if (m) {
        m->material = material;
        for (uint32_t v = 0; v < ico.vertex_count; ++v) {
            const double *n = ico.vertices[v];
            v3_store(&m->normals[3 * v], v3((float)n[0], (float)n[1], (float)n[2]));
            v3_store(&m->positions[3 * v], v3((float)(centre.x + radius * n[0]), (float)(centre.y + radius * n[1]),
                                              (float)(centre.z + radius * n[2])));
        }
        memcpy(m->indices, ico.faces, sizeof *ico.faces * ico.face_count);
    }
    free(ico.vertices);
    free(ico.faces);
    return m ? 0 : -1;
}

/* ---- Menger sponge ------------------------------------------------------------- */

enum { MENGER_LEVELS = 3, MENGER_CELLS = 27 /* 3^MENGER_LEVELS */ };

/* Cell (i, j, k) of the 27^3 grid is removed if, at any level, at least two
 * of its base-3 digits are 1 (Menger 1926). Cells outside the grid are empty. */
static int menger_solid(int i, int j, int k)
{
    if (i < 0 || j < 0 || k < 0 || i >= MENGER_CELLS || j >= MENGER_CELLS || k >= MENGER_CELLS)
        return 0;
    for (int level = 0; level < MENGER_LEVELS; ++level, i /= 3, j /= 3, k /= 3)
        if ((i % 3 == 1) + (j % 3 == 1) + (k % 3 == 1) >= 2)
            return 0;
    return 1;
}

/* Grid line n in world units: side 2, x and z centred, bottom on y = 0. The
 * same n always gives the same float, so neighbouring faces share edges exactly. */
static float menger_x(int n) { return (float)(n * 2.0 / MENGER_CELLS - 1.0); }
static float menger_y(int n) { return (float)(n * 2.0 / MENGER_CELLS); }

static int push_menger_faces(quad_list *l)
{
    static const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int i = 0; i < MENGER_CELLS; ++i)
        for (int j = 0; j < MENGER_CELLS; ++j)
            for (int k = 0; k < MENGER_CELLS; ++k) {
                if (!menger_solid(i, j, k))
                    continue;
                unsigned faces = 0;
                for (int f = 0; f < 6; ++f)
                    if (!menger_solid(i + step[f][0], j + step[f][1], k + step[f][2]))
                        faces |= FACE_BIT(f);
                if (j == 0)
                    faces &= ~FACE_BIT(FACE_NEG_Y); /* lies on the floor, never visible */
                vec3 corners[8];
                aligned_box_corners(v3(menger_x(i), menger_y(j), menger_x(k)),
                                    v3(menger_x(i + 1), menger_y(j + 1), menger_x(k + 1)), corners);
                if (push_box_faces(l, corners, faces, 0) != 0)
                    return -1;
            }
    return 0;
}

/* ---- Box field ------------------------------------------------------------------ */

enum { BOX_GRID = 8 };

static int push_box_field(quad_list *l)
{
    for (int r = 0; r < BOX_GRID; ++r)
        for (int c = 0; c < BOX_GRID; ++c) {
            float u[5];
            for (uint32_t k = 0; k < 5; ++k)
                u[k] = scene_unit_hash(5u * (uint32_t)(BOX_GRID * r + c) + k);
            float width = 0.5f + 2.0f * u[0], depth = 0.5f + 2.0f * u[1], height = 0.5f + 3.5f * u[2];
            float x = 3.0f * c - 10.5f + 1.5f * (u[3] - 0.5f), z = 3.0f * r - 10.5f + 1.5f * (u[4] - 0.5f);
            vec3 corners[8];
            aligned_box_corners(v3(x - 0.5f * width, 0.0f, z - 0.5f * depth),
                                v3(x + 0.5f * width, height, z + 0.5f * depth), corners);
            if (push_box_faces(l, corners, ALL_FACES & ~FACE_BIT(FACE_NEG_Y), 0) != 0)
                return -1;
        }
    return 0;
}

/* ---- Scenes ----------------------------------------------------------------------- */

static int build_plane(scene *s)
{
    int white = add_white_material(s);
    if (white < 0 || add_floor(s, white) != 0)
        return -1;
    scene_set_camera(s, v3(12.0f, 9.0f, 15.0f), v3(0.0f, 0.0f, 0.0f), 45.0f);
    return 0;
}

static int build_sphere_on_plane(scene *s)
{
    int white = add_white_material(s);
    if (white < 0 || add_floor(s, white) != 0 || add_sphere(s, v3(0.0f, 1.5f, 0.0f), 1.0f, white) != 0)
        return -1;
    scene_set_camera(s, v3(4.5f, 4.0f, 6.0f), v3(0.0f, 1.0f, 0.0f), 45.0f);
    return 0;
}

static int build_corner(scene *s)
{
    int white = add_white_material(s);
    if (white < 0)
        return -1;
    vec3 corners[8];
    aligned_box_corners(v3(0.0f, 0.0f, 0.0f), v3(10.0f, 10.0f, 10.0f), corners);
    quad_list l = {0};
    int rc = push_box_faces(&l, corners, FACE_BIT(FACE_NEG_Y) | FACE_BIT(FACE_NEG_X) | FACE_BIT(FACE_NEG_Z), 1);
    if (rc == 0)
        rc = quad_mesh_add(s, &l, white);
    quad_list_free(&l);
    scene_set_camera(s, v3(11.0f, 9.0f, 13.0f), v3(2.0f, 2.0f, 2.0f), 45.0f);
    return rc;
}

static int build_menger(scene *s)
{
    int white = add_white_material(s);
    if (white < 0 || add_floor(s, white) != 0)
        return -1;
    quad_list l = {0};
    int rc = push_menger_faces(&l);
    if (rc == 0)
        rc = quad_mesh_add(s, &l, white);
    quad_list_free(&l);
    scene_set_camera(s, v3(2.7f, 2.6f, 3.6f), v3(0.0f, 0.9f, 0.0f), 45.0f);
    return rc;
}

static int build_boxes(scene *s)
{
    int white = add_white_material(s);
    if (white < 0 || add_floor(s, white) != 0)
        return -1;
    quad_list l = {0};
    int rc = push_box_field(&l);
    if (rc == 0)
        rc = quad_mesh_add(s, &l, white);
    quad_list_free(&l);
    scene_set_camera(s, v3(27.0f, 22.0f, 35.0f), v3(0.0f, 0.0f, 0.0f), 45.0f);
    return rc;
}

/* The classic Cornell box colours (base colours of the white, red and green
 * walls as commonly tabulated from the Cornell measurements). */
static int build_cornell(scene *s)
{
    int white = scene_add_material(s, scene_matte_material(0.73f, 0.73f, 0.73f));
    int red = scene_add_material(s, scene_matte_material(0.63f, 0.065f, 0.05f));
    int green = scene_add_material(s, scene_matte_material(0.14f, 0.45f, 0.091f));
    if (white < 0 || red < 0 || green < 0)
        return -1;
    vec3 room[8], short_block[8], tall_block[8];
    aligned_box_corners(v3(-2.75f, 0.0f, -2.75f), v3(2.75f, 5.5f, 2.75f), room);
    turned_block_corners(v3(0.9f, 0.0f, 1.1f), v3(1.65f, 1.65f, 1.65f), -17.0 * pi / 180.0, short_block);
    turned_block_corners(v3(-0.9f, 0.0f, -0.7f), v3(1.65f, 3.3f, 1.65f), 17.0 * pi / 180.0, tall_block);
    const unsigned block_faces = ALL_FACES & ~FACE_BIT(FACE_NEG_Y);
    quad_list whites = {0}, reds = {0}, greens = {0};
    int rc = push_box_faces(&whites, room, FACE_BIT(FACE_NEG_Y) | FACE_BIT(FACE_POS_Y) | FACE_BIT(FACE_NEG_Z), 1);
    if (rc == 0)
        rc = push_box_faces(&whites, short_block, block_faces, 0);
    if (rc == 0)
        rc = push_box_faces(&whites, tall_block, block_faces, 0);
    if (rc == 0)
        rc = push_box_faces(&reds, room, FACE_BIT(FACE_NEG_X), 1);
    if (rc == 0)
        rc = push_box_faces(&greens, room, FACE_BIT(FACE_POS_X), 1);
    if (rc == 0)
        rc = quad_mesh_add(s, &whites, white);
    if (rc == 0)
        rc = quad_mesh_add(s, &reds, red);
    if (rc == 0)
        rc = quad_mesh_add(s, &greens, green);
    quad_list_free(&whites);
    quad_list_free(&reds);
    quad_list_free(&greens);
    scene_set_camera(s, v3(0.0f, 2.75f, 10.7f), v3(0.0f, 2.75f, 0.0f), 39.3f);
    return rc;
}

/* ---- Terrain ----------------------------------------------------------------- */

/* The height field of 'terrain' [m]: two ridges of sines, a hill and a
 * basin (Gaussians), cut at 0 (flat valley floors). */
static double terrain_height(double x, double z)
{
    double ridges = 140.0 * sin(2.0 * pi * x / 3200.0 + 0.4) * cos(2.0 * pi * z / 2700.0 - 0.3) +
                    70.0 * sin(2.0 * pi * (x - 0.6 * z) / 1500.0);
    double hill = 260.0 * exp(-((x - 1400.0) * (x - 1400.0) + (z + 900.0) * (z + 900.0)) / (900.0 * 900.0));
    double basin = 220.0 * exp(-((x + 600.0) * (x + 600.0) + (z - 700.0) * (z - 700.0)) / (1000.0 * 1000.0));
    return fmax(0.0, 180.0 + ridges + hill - basin);
}

enum { TERRAIN_CELLS = 160 };
#define TERRAIN_HALF 4000.0

static int build_terrain(scene *s)
{
    const uint32_t n = TERRAIN_CELLS, row = n + 1;
    int material = scene_add_material(s, scene_matte_material(0.25f, 0.3f, 0.18f));
    scene_mesh *m = material < 0 ? NULL : scene_add_mesh(s, row * row, 2 * n * n, 0);
    if (!m)
        return -1;
    m->material = material;
    for (uint32_t j = 0; j < row; ++j)
        for (uint32_t i = 0; i < row; ++i) {
            double x = -TERRAIN_HALF + 2.0 * TERRAIN_HALF * i / n, z = -TERRAIN_HALF + 2.0 * TERRAIN_HALF * j / n;
            v3_store(&m->positions[3 * (j * row + i)], v3((float)x, (float)terrain_height(x, z), (float)z));
        }
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1, *t = &m->indices[6 * (j * n + i)];
            t[0] = a, t[1] = c, t[2] = b; /* counter-clockwise from above (+Y) */
            t[3] = b, t[4] = c, t[5] = d;
        }
    scene_mesh_compute_normals(m);
    scene_set_camera(s, v3(-3600.0f, 1500.0f, 3600.0f), v3(600.0f, 100.0f, -800.0f), 50.0f);
    return 0;
}

/* ---- The table ---------------------------------------------------------------------- */

#define WHITE_MATERIAL "Material: base colour 0.8 grey (linear), roughness 0.5, metallic 0.\n"
#define FLOOR "The floor of 'plane' (mesh 0): x, z in [-50, 50] at y = 0, normal +Y.\n"

static const builtin_scene scenes[] = {
    {"plane",
     "A square of side 100 at y = 0 centred at the origin: x, z in [-50, 50].\n"
     "One mesh: 2 triangles over 4 vertices, normal +Y everywhere.\n" WHITE_MATERIAL
     "Bounds: [-50, 50] x [0, 0] x [-50, 50].\n"
     "Camera: position (12, 9, 15), target (0, 0, 0), up +Y, yfov 45 deg, 512 x 512.",
     build_plane, 0},
    {"sphere-on-plane",
     FLOOR "A sphere (mesh 1) of radius 1 centred at (0, 1.5, 0), 0.5 above the floor: an icosphere\n"
     "(icosahedron with vertices at the poles, faces split in 4 seven times, new vertices projected\n"
     "onto the sphere): 327680 triangles, 163842 vertices all on the sphere, normals the exact\n"
     "sphere normals. Its solid angle from any floor point is within 6.7e-5 sr of a true sphere's.\n" WHITE_MATERIAL
     "Bounds: [-50, 50] x [0, 2.5] x [-50, 50].\n"
     "Camera: position (4.5, 4, 6), target (0, 1, 0), up +Y, yfov 45 deg, 512 x 512.",
     build_sphere_on_plane, 0},
    {"corner",
     "Three perpendicular 10 x 10 squares meeting at the origin, one mesh, each square 2 triangles\n"
     "with its own 4 vertices; all normals face into the octant x, y, z >= 0:\n"
     "  floor y = 0 (x, z in [0, 10]) normal +Y; wall x = 0 (y, z in [0, 10]) normal +X;\n"
     "  wall z = 0 (x, y in [0, 10]) normal +Z.\n" WHITE_MATERIAL "Bounds: [0, 10] x [0, 10] x [0, 10].\n"
     "Camera: position (11, 9, 13), target (2, 2, 2), up +Y, yfov 45 deg, 512 x 512.",
     build_corner, 0},
    {"menger",
     FLOOR "A level-3 Menger sponge of side 2 (mesh 1) standing on it: x, z in [-1, 1], y in [0, 2].\n"
     "The cube is cut into 27^3 cells of side 2/27; cell (i, j, k) is solid unless at some level two\n"
     "or more of the base-3 digits of i, j, k are 1 (8000 solid cells). The mesh holds only cell faces\n"
     "between a solid cell and an empty one or the outside, except the bottom faces lying on the floor:\n"
     "17536 squares, each 2 triangles with its own 4 vertices and its axis-aligned outward normal.\n" WHITE_MATERIAL
     "Bounds: [-50, 50] x [0, 2] x [-50, 50].\n"
     "Camera: position (2.7, 2.6, 3.6), target (0, 0.9, 0), up +Y, yfov 45 deg, 512 x 512.",
     build_menger, 0},
    {"boxes",
     FLOOR "64 axis-aligned boxes on it (mesh 1) in an 8 x 8 grid, row r and column c in 0..7. With\n"
     "u_k = (pcg_hash(5 (8 r + c) + k) >> 8) / 2^24 (pcg_hash of Jarzynski and Olano 2020), box (r, c) is\n"
     "  width (x) 0.5 + 2 u_0, depth (z) 0.5 + 2 u_1, height 0.5 + 3.5 u_2, bottom at y = 0,\n"
     "  centred at x = 3 c - 10.5 + 1.5 (u_3 - 0.5), z = 3 r - 10.5 + 1.5 (u_4 - 0.5).\n"
     "Boxes may overlap. Each has 5 faces (no bottom), each 2 triangles with its own 4 vertices and\n"
     "its outward normal.\n" WHITE_MATERIAL "Bounds: [-50, 50] x [0, 3.8948] x [-50, 50] (the tallest box: 3.894838).\n"
     "Camera: position (27, 22, 35), target (0, 0, 0), up +Y, yfov 45 deg, 512 x 512.",
     build_boxes, 0},
    {"cornell",
     "A Cornell-box-like room, x in [-2.75, 2.75], y in [0, 5.5], z in [-2.75, 2.75], open at the\n"
     "front (z = 2.75), all wall normals facing into the room, one mesh per material:\n"
     "  mesh 0, white (base colour 0.73): floor y = 0 (+Y), ceiling y = 5.5 (-Y), back z = -2.75 (+Z),\n"
     "    and two blocks standing on the floor, 5 faces each (no bottom), outward normals, turned\n"
     "    about +Y (positive = counter-clockwise seen from above):\n"
     "    short 1.65 x 1.65 x 1.65 (x, y, z), base centred at (0.9, 0, 1.1), turned -17 deg;\n"
     "    tall 1.65 x 3.3 x 1.65, base centred at (-0.9, 0, -0.7), turned +17 deg;\n"
     "  mesh 1, red (0.63, 0.065, 0.05): left wall x = -2.75 (+X);\n"
     "  mesh 2, green (0.14, 0.45, 0.091): right wall x = 2.75 (-X).\n"
     "All roughness 0.5, metallic 0. No light source (the references light by a uniform dome).\n"
     "Bounds: [-2.75, 2.75] x [0, 5.5] x [-2.75, 2.75].\n"
     "Camera (the classic view in through the open front): position (0, 2.75, 10.7),\n"
     "target (0, 2.75, 0), up +Y, yfov 39.3 deg, 512 x 512.",
     build_cornell, 0},
    {"terrain",
     "A km-scale height field for the height fog (issue 16): x, z in [-4000, 4000] m on a 160 x 160\n"
     "grid of 50 m cells (161^2 vertices, each cell 2 triangles), one mesh, y = h(x, z) with\n"
     "  h = max(0, 180 + 140 sin(2 pi x / 3200 + 0.4) cos(2 pi z / 2700 - 0.3)\n"
     "             + 70 sin(2 pi (x - 0.6 z) / 1500) + 260 exp(-((x - 1400)^2 + (z + 900)^2) / 900^2)\n"
     "             - 220 exp(-((x + 600)^2 + (z - 700)^2) / 1000^2)):\n"
     "ridges, a hill, a basin and flat valley floors at y = 0. Smooth (area-weighted) vertex normals.\n"
     "Material: base colour (0.25, 0.3, 0.18), roughness 0.5, metallic 0.\n"
     "Bounds: [-4000, 4000] x [0, 513.2886] x [-4000, 4000].\n"
     "Camera: position (-3600, 1500, 3600), target (600, 100, -800), up +Y, yfov 50 deg, 512 x 512.\n"
     "Not in the studies' scene list (builtin_study_scene_at): their results stay the same.",
     build_terrain, 1},
    /* INSIDE's AO decal occluders as geometry (scene/builtin_scene_ao_decals.h); outside the studies' list */
    {"pill-on-plane",
     FLOOR "A \"pill\" (mesh 1): the ellipsoid centred at (0, 0.8, 0) with radii (1.6, 0.5, 0.5), 0.3 above\n"
     "the floor; 128 rings x 256 segments (pole fans), every vertex on it, exact ellipsoid normals.\n" WHITE_MATERIAL
     "Bounds: [-50, 50] x [0, 1.3] x [-50, 50].\n"
     "Camera: position (4.5, 4, 6), target (0, 0.5, 0), up +Y, yfov 45 deg, 512 x 512.\n"
     "Not in the studies' scene list: for the AO decals (techniques/ao_decals/).",
     builtin_scene_build_pill_on_plane, 1},
    {"box-on-plane",
     FLOOR "A crate (mesh 1) standing on it: x in [-0.75, 0.75], y in [0, 1.2], z in [-0.5, 0.5], 5 faces\n"
     "(no bottom), each 2 triangles with its own 4 vertices and its outward normal.\n" WHITE_MATERIAL
     "Bounds: [-50, 50] x [0, 1.2] x [-50, 50].\n"
     "Camera: position (4.5, 4, 6), target (0, 0.5, 0), up +Y, yfov 45 deg, 512 x 512.\n"
     "Not in the studies' scene list: for the AO decals (techniques/ao_decals/).",
     builtin_scene_build_box_on_plane, 1},
    {"box-in-corner",
     "The three walls of 'corner' (mesh 0: y = 0, x = 0, z = 0, 10 x 10, facing into x, y, z >= 0) and a\n"
     "crate (mesh 1) on the floor: x in [0.8, 2], y in [0, 1], z in [0.6, 1.6], 5 faces (no bottom),\n"
     "outward normals.\n" WHITE_MATERIAL "Bounds: [0, 10] x [0, 10] x [0, 10].\n"
     "Camera: position (6, 5, 7), target (1, 0.5, 1), up +Y, yfov 45 deg, 512 x 512.\n"
     "Not in the studies' scene list: for the AO decals (techniques/ao_decals/).",
     builtin_scene_build_box_in_corner, 1},
    {"overlap-on-plane",
     FLOOR "Overlapping occluders: spheres (mesh 1, meshed as pill-on-plane's) of radius 0.7 at\n"
     "(-0.5, 1, 0.3) and (0.4, 1, 0.3) (they intersect), of radius 0.5 at (1.3, 0.6, -0.6) piercing a\n"
     "crate (mesh 2: x in [0.3, 1.5], y in [0, 1], z in [-1.5, -0.5], no bottom), and of radius 0.8 at\n"
     "(-3.2, 0.3, -2.4), sunk into the floor, apart.\n" WHITE_MATERIAL "Bounds: [-50, 50] x [-0.5, 1.7] x [-50, 50].\n"
     "Camera: position (5, 5.5, 6.5), target (-0.7, 0.4, -1), up +Y, yfov 45 deg, 512 x 512.\n"
     "Not in the studies' scene list: for the AO decals (techniques/ao_decals/).",
     builtin_scene_build_overlap_on_plane, 1},
    {"aa-thin", BUILTIN_AA_THIN_DESCRIPTION, builtin_build_aa_thin, 1},
};

int builtin_scene_count(void) { return (int)(sizeof scenes / sizeof scenes[0]); }

int builtin_study_scene_count(void)
{
    int count = 0;
    for (int i = 0; i < builtin_scene_count(); ++i)
        count += !scenes[i].outside_studies;
    return count;
}

const builtin_scene *builtin_study_scene_at(int index)
{
    for (int i = 0; i < builtin_scene_count(); ++i)
        if (!scenes[i].outside_studies && index-- == 0)
            return &scenes[i];
    return NULL;
}

const builtin_scene *builtin_scene_at(int index)
{
    return index >= 0 && index < builtin_scene_count() ? &scenes[index] : NULL;
}

const builtin_scene *builtin_scene_find(const char *name)
{
    for (int i = 0; i < builtin_scene_count(); ++i)
        if (strcmp(scenes[i].name, name) == 0)
            return &scenes[i];
    return NULL;
}

int builtin_scene_build(const char *name, scene *s, gt_error *e)
{
    memset(s, 0, sizeof *s);
    char subject[sizeof s->name];
    snprintf(subject, sizeof subject, "builtin:%s", name);
    const builtin_scene *b = builtin_scene_find(name);
    int kind;
    uint32_t seed;
    int family = !b && family_member_parse(name, &kind, &seed);
    if (!b && !family)
        return gt_error_set(e, subject, "unknown built-in scene (try 'gtlab scene list')");
    if (family ? family_member_build(kind, seed, s) != 0 : b->build(s) != 0) {
        scene_free(s);
        return gt_error_set(e, subject, "out of memory");
    }
    memcpy(s->name, subject, sizeof subject);
    return 0;
}
