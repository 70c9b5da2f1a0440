/* The procedural family (builtin_scene_family.h): one builder per kind, the
 * layout drawn from a hash of (kind, seed), geometry from scene/quad_mesh.h. */
#include "scene/builtin_scene_family.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene/quad_mesh.h"

static const double pi = 3.14159265358979323846;

/* ---- The layout's numbers ------------------------------------------------------ */

/* The n-th number of a member's layout: a PCG hash of its key and n. */
typedef struct {
    uint32_t key, n;
} layout;

static layout layout_of(int kind, uint32_t seed)
{
    return (layout){scene_pcg_hash(seed * (uint32_t)FAMILY_KINDS + (uint32_t)kind), 0};
}

/* Uniform in [lo, hi). */
static float draw(layout *r, float lo, float hi)
{
    float u = scene_unit_hash(r->key ^ scene_pcg_hash(r->n++));
    return lo + (hi - lo) * u;
}

/* Uniform integer in [lo, hi]. */
static int draw_int(layout *r, int lo, int hi) { return lo + (int)floorf(draw(r, 0.0f, (float)(hi - lo + 1))); }

/* ---- Pieces --------------------------------------------------------------------- */

/* An axis-aligned box from lo to hi; a box resting on something has no bottom. */
static int box(quad_list *l, vec3 lo, vec3 hi, int resting)
{
    vec3 corners[8];
    aligned_box_corners(lo, hi, corners);
    return push_box_faces(l, corners, resting ? ALL_FACES & ~FACE_BIT(FACE_NEG_Y) : ALL_FACES, 0);
}

/* A block turned about +Y standing at height y0 (no bottom). */
static int turned_box(quad_list *l, float x, float y0, float z, vec3 size, double angle)
{
    vec3 corners[8];
    turned_block_corners(v3(x, 0.0f, z), size, angle, corners);
    for (int k = 0; k < 8; ++k)
        corners[k].y += y0;
    return push_box_faces(l, corners, ALL_FACES & ~FACE_BIT(FACE_NEG_Y), 0);
}

/* The ground: the square of half side h at y = 0, facing +Y. */
static int ground(quad_list *l, float h)
{
    quad q = {{v3(-h, 0.0f, -h), v3(-h, 0.0f, h), v3(h, 0.0f, h), v3(h, 0.0f, -h)}};
    return quad_list_push(l, q);
}

/* A vertical card of width w and height h, its bottom centre at (x, y, z),
 * facing yaw (radians about +Y). */
static int card(quad_list *l, float x, float y, float z, float w, float h, double yaw)
{
    float dx = (float)(0.5 * w * cos(yaw)), dz = (float)(-0.5 * w * sin(yaw));
    quad q = {{v3(x - dx, y, z - dz), v3(x + dx, y, z + dz), v3(x + dx, y + h, z + dz), v3(x - dx, y + h, z - dz)}};
    return quad_list_push(l, q);
}

/* Four legs of side t under a top at height h covering [x0, x1] x [z0, z1]. */
static int legs(quad_list *l, float x0, float x1, float z0, float z1, float h, float t)
{
    const float xs[2] = {x0, x1 - t}, zs[2] = {z0, z1 - t};
    for (int i = 0; i < 4; ++i)
        if (box(l, v3(xs[i & 1], 0.0f, zs[i >> 1]), v3(xs[i & 1] + t, h, zs[i >> 1] + t), 1) != 0)
            return -1;
    return 0;
}

/* ---- Room -------------------------------------------------------------------------- */

static int table(quad_list *l, layout *r, float x, float z)
{
    float w = draw(r, 0.8f, 1.6f), d = draw(r, 0.6f, 0.9f), h = draw(r, 0.72f, 0.78f);
    float x0 = x - 0.5f * w, z0 = z - 0.5f * d;
    return legs(l, x0, x0 + w, z0, z0 + d, h - 0.04f, 0.05f) ||
           box(l, v3(x0, h - 0.04f, z0), v3(x0 + w, h, z0 + d), 0);
}

static int chair(quad_list *l, layout *r, float x, float z)
{
    float s = draw(r, 0.40f, 0.50f), h = 0.45f, x0 = x - 0.5f * s, z0 = z - 0.5f * s;
    return legs(l, x0, x0 + s, z0, z0 + s, h - 0.04f, 0.04f) ||
           box(l, v3(x0, h - 0.04f, z0), v3(x0 + s, h, z0 + s), 0) ||
           box(l, v3(x0, h, z0), v3(x0 + s, h + draw(r, 0.4f, 0.55f), z0 + 0.04f), 1);
}

/* A shelf with its back to the room's back wall at z = back. */
static int shelf(quad_list *l, layout *r, float x, float back)
{
    float w = draw(r, 0.8f, 1.8f), h = draw(r, 1.2f, 2.2f), d = 0.35f, t = 0.03f, x0 = x - 0.5f * w;
    int boards = draw_int(r, 3, 5);
    int rc = box(l, v3(x0, 0.0f, back), v3(x0 + t, h, back + d), 1) ||
             box(l, v3(x0 + w - t, 0.0f, back), v3(x0 + w, h, back + d), 1);
    for (int b = 0; b < boards && rc == 0; ++b) {
        float y = (h - t) * (float)b / (float)(boards - 1);
        rc = box(l, v3(x0 + t, y, back), v3(x0 + w - t, y + t, back + d), b == 0);
    }
    return rc;
}

static int crate(quad_list *l, layout *r, float x, float z)
{
    float s = draw(r, 0.4f, 0.8f);
    return turned_box(l, x, 0.0f, z, v3(s, draw(r, 0.3f, 0.8f), s), draw(r, 0.0f, (float)(0.5 * pi)));
}

/* Furniture in the cells of a 3 x 3 grid over the floor, at most one a cell. */
static int room_clutter(quad_list *l, layout *r, float w, float d)
{
    int rc = 0;
    for (int cell = 0; cell < 9 && rc == 0; ++cell) {
        float x = w * ((float)(cell % 3) - 1.0f) / 3.2f, z = d * ((float)(cell / 3) - 1.0f) / 3.2f;
        int what = draw_int(r, 0, 4); /* 0 empty, 1 table, 2 chair, 3 crate, 4 shelf (back row only) */
        if (what == 1)
            rc = table(l, r, x, z);
        else if (what == 2)
            rc = chair(l, r, x, z);
        else if (what == 3)
            rc = crate(l, r, x, z);
        else if (what == 4 && cell < 3)
            rc = shelf(l, r, x, -0.5f * d);
    }
    return rc;
}

static int build_room(quad_list *l, layout *r, scene *s)
{
    float w = draw(r, 6.0f, 10.0f), d = draw(r, 6.0f, 10.0f), h = 3.0f;
    vec3 corners[8];
    aligned_box_corners(v3(-0.5f * w, 0.0f, -0.5f * d), v3(0.5f * w, h, 0.5f * d), corners);
    unsigned walls = FACE_BIT(FACE_NEG_Y) | FACE_BIT(FACE_NEG_X) | FACE_BIT(FACE_POS_X) | FACE_BIT(FACE_NEG_Z);
    if (push_box_faces(l, corners, walls, 1) != 0 || room_clutter(l, r, w, d) != 0)
        return -1;
    scene_set_camera(s, v3(0.15f * w, 7.5f, 0.5f * d + 5.0f), v3(0.0f, 0.5f, -0.1f * d), 50.0f);
    return 0;
}

/* ---- Railing ------------------------------------------------------------------------ */

static int railing_bars(quad_list *l, float from, float to, float z, float spacing, float bar)
{
    int n = (int)floorf((to - from) / spacing);
    for (int i = 0; i <= n; ++i) {
        float x = from + spacing * (float)i;
        if (box(l, v3(x - 0.5f * bar, 0.0f, z - 0.5f * bar), v3(x + 0.5f * bar, 0.9f, z + 0.5f * bar), 1) != 0)
            return -1;
    }
    return box(l, v3(from - 0.03f, 0.9f, z - 0.03f), v3(to + 0.03f, 0.95f, z + 0.03f), 1);
}

static int build_railing(quad_list *l, layout *r, scene *s)
{
    float half = draw(r, 3.5f, 5.5f), spacing = draw(r, 0.10f, 0.16f), bar = draw(r, 0.02f, 0.05f);
    float bench = draw(r, -0.5f * half, 0.5f * half);
    int rc = box(l, v3(-half, -0.25f, -2.0f), v3(half, 0.0f, 2.0f), 0) ||
             box(l, v3(-half, 0.0f, -2.3f), v3(half, 3.0f, -2.0f), 1) ||
             railing_bars(l, -half + 0.05f, half - 0.05f, 1.95f, spacing, bar) ||
             box(l, v3(bench - 0.8f, 0.0f, -1.95f), v3(bench - 0.7f, 0.42f, -1.55f), 1) ||
             box(l, v3(bench + 0.7f, 0.0f, -1.95f), v3(bench + 0.8f, 0.42f, -1.55f), 1) ||
             box(l, v3(bench - 0.9f, 0.42f, -1.95f), v3(bench + 0.9f, 0.47f, -1.5f), 1);
    if (rc != 0)
        return -1;
    quad below = {{v3(-30.0f, -4.0f, -30.0f), v3(-30.0f, -4.0f, 30.0f), v3(30.0f, -4.0f, 30.0f),
                   v3(30.0f, -4.0f, -30.0f)}};
    scene_set_camera(s, v3(2.5f, 3.2f, 7.0f), v3(0.0f, 0.4f, 0.0f), 45.0f);
    return quad_list_push(l, below);
}

/* ---- Street -------------------------------------------------------------------------- */

/* A row of buildings along x from the pavement's edge z = edge outwards (side +1 or -1). */
static int building_row(quad_list *l, layout *r, float edge, float side)
{
    int rc = 0;
    for (float x = -30.0f; x < 30.0f && rc == 0;) {
        float w = draw(r, 4.0f, 9.0f), depth = draw(r, 6.0f, 10.0f), h = draw(r, 4.0f, 14.0f);
        float near = edge + side * draw(r, 0.0f, 1.5f), far = near + side * depth;
        rc = box(l, v3(x, 0.0f, fminf(near, far)), v3(fminf(x + w, 30.0f), h, fmaxf(near, far)), 1);
        x += w + draw(r, 0.0f, 2.0f);
    }
    return rc;
}

static int street_furniture(quad_list *l, layout *r)
{
    int rc = 0, count = draw_int(r, 6, 12);
    for (int i = 0; i < count && rc == 0; ++i) {
        float x = draw(r, -25.0f, 25.0f), z = (i & 1 ? 1.0f : -1.0f) * draw(r, 4.4f, 6.6f);
        vec3 size = i % 3 == 0 ? v3(0.6f, 1.1f, 0.6f) : v3(0.15f, 0.9f, 0.15f); /* bins, bollards */
        rc = turned_box(l, x, 0.15f, z, size, draw(r, 0.0f, (float)pi));
    }
    return rc;
}

static int build_street(quad_list *l, layout *r, scene *s)
{
    int rc = ground(l, 40.0f) || box(l, v3(-40.0f, 0.0f, 4.0f), v3(40.0f, 0.15f, 7.0f), 1) ||
             box(l, v3(-40.0f, 0.0f, -7.0f), v3(40.0f, 0.15f, -4.0f), 1) || building_row(l, r, 7.0f, 1.0f) ||
             building_row(l, r, -7.0f, -1.0f) || street_furniture(l, r);
    scene_set_camera(s, v3(16.0f, 20.0f, 30.0f), v3(0.0f, 2.0f, 0.0f), 50.0f);
    return rc ? -1 : 0;
}

/* ---- Props ----------------------------------------------------------------------------- */

static int steps(quad_list *l, float x0, float z0, int count, float rise, float tread)
{
    for (int k = 0; k < count; ++k) {
        float z = z0 + tread * (float)k;
        if (box(l, v3(x0, 0.0f, z), v3(x0 + 1.2f, rise * (float)(count - k), z + tread), 1) != 0)
            return -1;
    }
    return 0;
}

static int build_props(quad_list *l, layout *r, scene *s)
{
    int rc = ground(l, 20.0f) || box(l, v3(-6.0f, 0.0f, -4.0f), v3(6.0f, 2.5f, -3.7f), 1) ||
             box(l, v3(-3.5f, 0.0f, -3.7f), v3(-1.5f, 0.3f, -2.2f), 1) ||
             steps(l, 2.0f, -3.7f, draw_int(r, 2, 4), 0.18f, 0.3f);
    int count = draw_int(r, 6, 12);
    for (int i = 0; i < count && rc == 0; ++i) {
        float x = draw(r, -4.0f, 4.0f), z = draw(r, -2.0f, 2.0f), a = draw(r, 0.0f, (float)(0.5 * pi));
        vec3 size = v3(draw(r, 0.2f, 0.7f), draw(r, 0.15f, 0.6f), draw(r, 0.2f, 0.7f));
        rc = turned_box(l, x, 0.0f, z, size, a);
        if (rc == 0 && i % 3 == 0) /* a smaller one stacked on it */
            rc = turned_box(l, x, size.y, z, v3(0.6f * size.x, 0.6f * size.y, 0.6f * size.z), a + 0.3);
    }
    scene_set_camera(s, v3(4.0f, 3.5f, 6.0f), v3(0.0f, 0.3f, -0.5f), 50.0f);
    return rc ? -1 : 0;
}

/* ---- Foliage ------------------------------------------------------------------------------ */

/* A cluster of crossed cards around (x, z), bottoms at height y. */
static int card_cluster(quad_list *l, layout *r, float x, float y, float z, int count, float size)
{
    int rc = 0;
    for (int i = 0; i < count && rc == 0; ++i) {
        float cx = x + draw(r, -0.4f, 0.4f) * size, cz = z + draw(r, -0.4f, 0.4f) * size;
        float w = draw(r, 0.2f, 0.5f) * size, h = draw(r, 0.3f, 1.0f) * size;
        double yaw = draw(r, 0.0f, (float)pi);
        rc = card(l, cx, y, cz, w, h, yaw) || card(l, cx, y, cz, w, h, yaw + 0.5 * pi);
    }
    return rc;
}

static int build_foliage(quad_list *l, layout *r, scene *s)
{
    int rc = ground(l, 15.0f), clusters = draw_int(r, 6, 10), trunks = draw_int(r, 2, 3);
    for (int c = 0; c < clusters && rc == 0; ++c)
        rc = card_cluster(l, r, draw(r, -5.0f, 5.0f), 0.0f, draw(r, -5.0f, 5.0f), draw_int(r, 8, 16), 1.0f);
    for (int t = 0; t < trunks && rc == 0; ++t) {
        float x = draw(r, -4.0f, 4.0f), z = draw(r, -4.0f, 2.0f);
        rc = box(l, v3(x - 0.1f, 0.0f, z - 0.1f), v3(x + 0.1f, 2.5f, z + 0.1f), 1) ||
             card_cluster(l, r, x, 2.0f, z, 12, 1.5f);
    }
    scene_set_camera(s, v3(6.0f, 5.0f, 9.0f), v3(0.0f, 0.5f, 0.0f), 50.0f);
    return rc ? -1 : 0;
}

/* ---- Edges ----------------------------------------------------------------------------------- */

static int build_edges(quad_list *l, layout *r, scene *s)
{
    float wall = draw(r, 1.2f, 2.2f), gap = draw(r, 0.2f, 0.6f), plinth = draw(r, 0.4f, 1.0f);
    int rc = ground(l, 15.0f) || steps(l, -4.0f, -3.0f, draw_int(r, 4, 7), 0.18f, 0.28f) ||
             box(l, v3(1.0f, 0.0f, -3.0f), v3(4.0f, wall, -2.7f), 1) ||                 /* L-shaped wall */
             box(l, v3(3.7f, 0.0f, -2.7f), v3(4.0f, wall, 0.0f), 1) ||
             box(l, v3(-3.0f, 0.0f, 1.0f), v3(0.0f, 0.5f, 1.6f), 1) ||                  /* a slot between two ridges */
             box(l, v3(-3.0f, 0.0f, 1.6f + gap), v3(0.0f, 0.5f, 2.2f + gap), 1) ||
             box(l, v3(1.5f, 0.0f, 1.0f), v3(2.7f, plinth, 2.2f), 1) ||                 /* a plinth and its cap */
             box(l, v3(1.8f, plinth, 1.3f), v3(2.4f, plinth + 0.5f, 1.9f), 1);
    scene_set_camera(s, v3(7.0f, 6.0f, 9.0f), v3(0.0f, 0.5f, 0.0f), 50.0f);
    return rc ? -1 : 0;
}

/* ---- Terrain ------------------------------------------------------------------------------------ */

enum { TERRAIN_CELLS = 24 };

typedef struct {
    float amplitude[3], frequency[3], phase[3];
} terrain_waves;

static float terrain_height(const terrain_waves *w, float x, float z)
{
    float h = 0.0f;
    for (int k = 0; k < 3; ++k)
        h += w->amplitude[k] * sinf(w->frequency[k] * x + w->phase[k]) * cosf(w->frequency[k] * z - w->phase[k]);
    return h + 1.0f;
}

/* The height grid over [-12, 12]^2, each triangle flat-shaded with its own
 * three vertices and its face normal, counter-clockwise seen from above. */
static int terrain_mesh(scene *s, const terrain_waves *w, int material)
{
    const uint32_t triangles = 2u * TERRAIN_CELLS * TERRAIN_CELLS;
    scene_mesh *m = scene_add_mesh(s, 3 * triangles, triangles, 0);
    if (!m)
        return -1;
    m->material = material;
    const float step = 24.0f / TERRAIN_CELLS;
    uint32_t t = 0;
    for (int j = 0; j < TERRAIN_CELLS; ++j)
        for (int i = 0; i < TERRAIN_CELLS; ++i) {
            vec3 p[4];
            for (int k = 0; k < 4; ++k) {
                float x = -12.0f + step * (float)(i + (k & 1)), z = -12.0f + step * (float)(j + (k >> 1));
                p[k] = v3(x, terrain_height(w, x, z), z);
            }
            const int tri[2][3] = {{0, 2, 3}, {0, 3, 1}}; /* (x, z), (x, z+), (x+, z+): +Y facing */
            for (int h = 0; h < 2; ++h, ++t) {
                vec3 a = p[tri[h][0]], b = p[tri[h][1]], c = p[tri[h][2]];
                vec3 n = v3_normalize(v3_cross(v3_sub(b, a), v3_sub(c, a)));
                const vec3 corner[3] = {a, b, c};
                for (int k = 0; k < 3; ++k) {
                    v3_store(&m->positions[3 * (3 * t + k)], corner[k]);
                    v3_store(&m->normals[3 * (3 * t + k)], n);
                    m->indices[3 * t + k] = 3 * t + (uint32_t)k;
                }
            }
        }
    return 0;
}

static int build_terrain(quad_list *l, layout *r, scene *s, int material)
{
    terrain_waves w;
    for (int k = 0; k < 3; ++k) {
        w.amplitude[k] = draw(r, 0.2f, 0.7f) / (float)(k + 1);
        w.frequency[k] = draw(r, 0.15f, 0.4f) * (float)(k + 1);
        w.phase[k] = draw(r, 0.0f, (float)(2.0 * pi));
    }
    int rc = terrain_mesh(s, &w, material), rocks = draw_int(r, 5, 10);
    for (int i = 0; i < rocks && rc == 0; ++i) {
        float x = draw(r, -6.0f, 6.0f), z = draw(r, -6.0f, 6.0f), size = draw(r, 0.4f, 1.5f);
        rc = turned_box(l, x, terrain_height(&w, x, z) - 0.4f * size, z, v3(size, size, 0.8f * size),
                        draw(r, 0.0f, (float)pi));
    }
    scene_set_camera(s, v3(9.0f, 8.0f, 12.0f), v3(0.0f, 0.5f, 0.0f), 50.0f);
    return rc ? -1 : 0;
}

/* ---- The family ------------------------------------------------------------------------------------ */

static const char *const kinds[FAMILY_KINDS] = {"room", "railing", "street", "props", "foliage", "edges", "terrain"};

const char *family_kind_name(int kind) { return kind >= 0 && kind < FAMILY_KINDS ? kinds[kind] : NULL; }

int family_member_parse(const char *name, int *kind, uint32_t *seed)
{
    for (int k = 0; k < FAMILY_KINDS; ++k) {
        size_t n = strlen(kinds[k]);
        const char *digits = name + n + 1;
        if (strncmp(name, kinds[k], n) != 0 || name[n] != '-' || !*digits || strlen(digits) > 4 ||
            strspn(digits, "0123456789") != strlen(digits) || (digits[0] == '0' && digits[1]))
            continue;
        *kind = k, *seed = (uint32_t)atoi(digits);
        return 1;
    }
    return 0;
}

void family_member_name(int index, char *name, size_t size)
{
    snprintf(name, size, "%s-%d", kinds[index % FAMILY_KINDS], index / FAMILY_KINDS);
}

int family_member_build(int kind, uint32_t seed, scene *s)
{
    layout r = layout_of(kind, seed);
    int white = scene_add_material(s, scene_matte_material(0.8f, 0.8f, 0.8f));
    quad_list l = {0};
    if (white < 0)
        return -1;
    int rc = kind == 0   ? build_room(&l, &r, s)
             : kind == 1 ? build_railing(&l, &r, s)
             : kind == 2 ? build_street(&l, &r, s)
             : kind == 3 ? build_props(&l, &r, s)
             : kind == 4 ? build_foliage(&l, &r, s)
             : kind == 5 ? build_edges(&l, &r, s)
                         : build_terrain(&l, &r, s, white);
    if (rc == 0 && l.count > 0)
        rc = quad_mesh_add(s, &l, white);
    quad_list_free(&l);
    return rc ? -1 : 0;
}

void family_describe(FILE *f)
{
    fprintf(f, "The procedural family (builtin_scene_family.h): builtin:KIND-SEED, SEED 0 to %d, KIND one of\n"
               "  room (open-topped, furniture-like clutter), railing (thin bars, a balcony), street (blocks,\n"
               "  kerbs, bins), props (small props on a floor by a wall), foliage (crossed cards, trunks),\n"
               "  edges (stairs, an L wall, a slot, a plinth), terrain (metre-scale ground, rocks).\n"
               "The layout comes from a hash of kind and seed: the same name gives the same .glb bytes.\n"
               "All white (albedo 0.8, roughness 0.5); the camera looks down from outside, 512 x 512.\n",
            FAMILY_MAX_SEED);
}
