/* The AO decal scenes: see builtin_scene_ao_decals.h. Flat faces are quads
 * with their own four vertices and exact flat normals (as in
 * builtin_scenes.c); ellipsoids are computed in double and rounded once. */
#include "scene/builtin_scene_ao_decals.h"

#include <math.h>
#include <string.h>

static const double pi = 3.14159265358979323846;

#define ELLIPSOID(cx, cy, cz, rx, ry, rz) {AO_OCCLUDER_ELLIPSOID, {cx, cy, cz}, {rx, ry, rz}}
#define BOX(cx, cy, cz, hx, hy, hz) {AO_OCCLUDER_BOX, {cx, cy, cz}, {hx, hy, hz}}

static const ao_decal_scene decal_scenes[] = {
    {"pill-on-plane", 0, 1, {ELLIPSOID(0.0f, 0.8f, 0.0f, 1.6f, 0.5f, 0.5f)}},
    {"box-on-plane", 0, 1, {BOX(0.0f, 0.6f, 0.0f, 0.75f, 0.6f, 0.5f)}},
    {"box-in-corner", 1, 1, {BOX(1.4f, 0.5f, 1.1f, 0.6f, 0.5f, 0.5f)}},
    {"overlap-on-plane", 0, 5,
     {ELLIPSOID(-0.5f, 1.0f, 0.3f, 0.7f, 0.7f, 0.7f), ELLIPSOID(0.4f, 1.0f, 0.3f, 0.7f, 0.7f, 0.7f),
      BOX(0.9f, 0.5f, -1.0f, 0.6f, 0.5f, 0.5f), ELLIPSOID(1.3f, 0.6f, -0.6f, 0.5f, 0.5f, 0.5f),
      ELLIPSOID(-3.2f, 0.3f, -2.4f, 0.8f, 0.8f, 0.8f)}},
};

int ao_decal_scene_count(void) { return (int)(sizeof decal_scenes / sizeof decal_scenes[0]); }

const ao_decal_scene *ao_decal_scene_at(int index)
{
    return index >= 0 && index < ao_decal_scene_count() ? &decal_scenes[index] : NULL;
}

const ao_decal_scene *ao_decal_scene_find(const char *name)
{
    for (int i = 0; i < ao_decal_scene_count(); ++i)
        if (strcmp(decal_scenes[i].name, name) == 0)
            return &decal_scenes[i];
    return NULL;
}

/* ---- Meshes ------------------------------------------------------------------ */

static int add_white(scene *s)
{
    scene_material m = {{0.8f, 0.8f, 0.8f, 1.0f}, -1, 0.0f, 0.5f, -1};
    return scene_add_material(s, m);
}

/* One mesh of count quads (corners counter-clockwise seen from the front), each with its own
 * vertices and its plane's normal computed in double. */
static int add_quads(scene *s, const vec3 (*quads)[4], int count, int material)
{
    scene_mesh *m = scene_add_mesh(s, 4u * count, 2u * count, 0);
    if (!m)
        return -1;
    m->material = material;
    for (int q = 0; q < count; ++q) {
        const vec3 *p = quads[q];
        double u[3] = {p[1].x - p[0].x, p[1].y - p[0].y, p[1].z - p[0].z};
        double v[3] = {p[2].x - p[0].x, p[2].y - p[0].y, p[2].z - p[0].z};
        double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 4; ++k) {
            v3_store(&m->positions[3 * (4 * q + k)], p[k]);
            v3_store(&m->normals[3 * (4 * q + k)], v3((float)(n[0] / len), (float)(n[1] / len), (float)(n[2] / len)));
        }
        static const uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; ++k)
            m->indices[6 * q + k] = 4u * q + tri[k];
    }
    return 0;
}

/* Corner c of the box lo..hi has bit 0 on +x, bit 1 on +y, bit 2 on +z; faces +x, -x, +y, -y, +z, -z
 * counter-clockwise seen from outside (builtin_scenes.c's table). */
static const unsigned char face_corners[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                                 {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
enum { FACE_NEG_X = 1, FACE_NEG_Y = 3, FACE_NEG_Z = 5 };

/* The faces in mask, outward or (inward) reversed; returns the number written. */
static int box_quads(vec3 lo, vec3 hi, unsigned mask, int inward, vec3 (*out)[4])
{
    int count = 0;
    for (int f = 0; f < 6; ++f) {
        if (!(mask & (1u << f)))
            continue;
        for (int k = 0; k < 4; ++k) {
            int c = face_corners[f][inward ? (4 - k) % 4 : k];
            out[count][k] = v3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
        }
        ++count;
    }
    return count;
}

static int add_floor(scene *s, int material)
{
    const vec3 floor[1][4] = {{v3(-50.0f, 0.0f, -50.0f), v3(-50.0f, 0.0f, 50.0f), v3(50.0f, 0.0f, 50.0f),
                               v3(50.0f, 0.0f, -50.0f)}};
    return add_quads(s, floor, 1, material);
}

/* builtin:corner's walls: the floor y = 0 and the walls x = 0, z = 0 of [0, 10]^3, facing inside. */
static int add_corner_walls(scene *s, int material)
{
    vec3 quads[3][4];
    unsigned mask = 1u << FACE_NEG_X | 1u << FACE_NEG_Y | 1u << FACE_NEG_Z;
    int count = box_quads(v3(0.0f, 0.0f, 0.0f), v3(10.0f, 10.0f, 10.0f), mask, 1, quads);
    return add_quads(s, (const vec3(*)[4])quads, count, material);
}

/* Every box occluder, without a bottom face where it stands on y = 0. */
static int add_boxes(scene *s, const ao_decal_scene *d, int material)
{
    vec3 quads[6 * AO_DECAL_SCENE_MAX_OCCLUDERS][4];
    int count = 0;
    for (int i = 0; i < d->occluder_count; ++i) {
        const ao_occluder *o = &d->occluders[i];
        if (o->kind != AO_OCCLUDER_BOX)
            continue;
        vec3 lo = v3_sub(o->centre, o->half), hi = v3_add(o->centre, o->half);
        count += box_quads(lo, hi, lo.y == 0.0f ? 0x3fu & ~(1u << FACE_NEG_Y) : 0x3fu, 0, &quads[count]);
    }
    return count ? add_quads(s, (const vec3(*)[4])quads, count, material) : 0;
}

/* Vertex index of ring i (1 .. RINGS - 1), segment j; 0 is the pole +Y, the last the pole -Y. */
static uint32_t ring_vertex(int i, int j)
{
    return 1u + (uint32_t)((i - 1) * AO_DECAL_SCENE_SEGMENTS + j % AO_DECAL_SCENE_SEGMENTS);
}

static void ellipsoid_vertex(scene_mesh *m, uint32_t v, const ao_occluder *o, double theta, double phi)
{
    double u[3] = {sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi)};
    double c[3] = {o->centre.x, o->centre.y, o->centre.z}, r[3] = {o->half.x, o->half.y, o->half.z}, n[3];
    for (int k = 0; k < 3; ++k)
        m->positions[3 * v + k] = (float)(c[k] + r[k] * u[k]), n[k] = u[k] / r[k];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; ++k)
        m->normals[3 * v + k] = (float)(n[k] / len);
}

/* Triangles counter-clockwise from outside: pole fans and two per quad between rings. */
static void ellipsoid_triangles(uint32_t *t, uint32_t base, uint32_t bottom)
{
    const int n = AO_DECAL_SCENE_SEGMENTS, last = AO_DECAL_SCENE_RINGS - 1;
    for (int j = 0; j < n; ++j) {
        uint32_t fan[6] = {0, ring_vertex(1, j + 1), ring_vertex(1, j), bottom, ring_vertex(last, j),
                           ring_vertex(last, j + 1)};
        for (int k = 0; k < 6; ++k)
            *t++ = base + fan[k];
        for (int i = 1; i < last; ++i) {
            uint32_t a = ring_vertex(i, j), b = ring_vertex(i, j + 1), c = ring_vertex(i + 1, j),
                     d = ring_vertex(i + 1, j + 1), quad[6] = {a, b, c, b, d, c};
            for (int k = 0; k < 6; ++k)
                *t++ = base + quad[k];
        }
    }
}

/* Every ellipsoid occluder in one mesh (smooth normals). */
static int add_ellipsoids(scene *s, const ao_decal_scene *d, int material)
{
    const uint32_t per_vertices = (AO_DECAL_SCENE_RINGS - 1) * AO_DECAL_SCENE_SEGMENTS + 2;
    const uint32_t per_triangles = 2 * (AO_DECAL_SCENE_RINGS - 1) * AO_DECAL_SCENE_SEGMENTS;
    uint32_t count = 0;
    for (int i = 0; i < d->occluder_count; ++i)
        count += d->occluders[i].kind == AO_OCCLUDER_ELLIPSOID;
    scene_mesh *m = count ? scene_add_mesh(s, count * per_vertices, count * per_triangles, 0) : NULL;
    if (count && !m)
        return -1;
    for (int i = 0, e = 0; i < d->occluder_count; ++i) {
        const ao_occluder *o = &d->occluders[i];
        if (o->kind != AO_OCCLUDER_ELLIPSOID)
            continue;
        uint32_t base = e * per_vertices, bottom = per_vertices - 1;
        ellipsoid_vertex(m, base, o, 0.0, 0.0);
        ellipsoid_vertex(m, base + bottom, o, pi, 0.0);
        for (int r = 1; r < AO_DECAL_SCENE_RINGS; ++r)
            for (int j = 0; j < AO_DECAL_SCENE_SEGMENTS; ++j)
                ellipsoid_vertex(m, base + ring_vertex(r, j), o, pi * r / AO_DECAL_SCENE_RINGS,
                                 2.0 * pi * j / AO_DECAL_SCENE_SEGMENTS);
        ellipsoid_triangles(&m->indices[3 * (size_t)e++ * per_triangles], base, bottom);
        m->material = material;
    }
    return 0;
}

/* ---- Scenes ------------------------------------------------------------------- */

static void set_camera(scene *s, vec3 position, vec3 target)
{
    s->has_camera = 1;
    s->camera = (camera){position, target, v3(0.0f, 1.0f, 0.0f), (float)(45.0 * pi / 180.0), 512, 512};
}

static int build(scene *s, const char *name, vec3 position, vec3 target)
{
    const ao_decal_scene *d = ao_decal_scene_find(name);
    int white = add_white(s);
    if (white < 0 || (d->corner ? add_corner_walls(s, white) : add_floor(s, white)) != 0)
        return -1;
    if (add_ellipsoids(s, d, white) != 0 || add_boxes(s, d, white) != 0)
        return -1;
    set_camera(s, position, target);
    return 0;
}

int builtin_scene_build_pill_on_plane(scene *s) { return build(s, "pill-on-plane", v3(4.5f, 4.0f, 6.0f), v3(0.0f, 0.5f, 0.0f)); }
int builtin_scene_build_box_on_plane(scene *s) { return build(s, "box-on-plane", v3(4.5f, 4.0f, 6.0f), v3(0.0f, 0.5f, 0.0f)); }
int builtin_scene_build_box_in_corner(scene *s) { return build(s, "box-in-corner", v3(6.0f, 5.0f, 7.0f), v3(1.0f, 0.5f, 1.0f)); }

int builtin_scene_build_overlap_on_plane(scene *s)
{
    return build(s, "overlap-on-plane", v3(5.0f, 5.5f, 6.5f), v3(-0.7f, 0.4f, -1.0f));
}
