/* The built-in scene "aa-thin" (builtin_scene_aa_thin.h): every surface a
 * quad or a triangle with its own vertices, flat normals and TEXCOORD_0. */
#include "scene/builtin_scene_aa_thin.h"

#include <math.h>
#include <stdlib.h>

enum { FENCE_VERTICAL = 51, FENCE_HORIZONTAL = 19, GRASS_BLADES = 600, CARDS = 3, LEAF_TEXELS = 64 };

static int add_material(scene *s, float r, float g, float b, int texture)
{
    scene_material m = {{r, g, b, 1.0f}, texture, 0.0f, 0.5f, -1};
    return scene_add_material(s, m);
}

/* Appends a w x h RGBA texture filled by texel(i, j, rgba); its index or -1. */
static int add_texture(scene *s, int w, int h, void (*texel)(int i, int j, unsigned char rgba[4]))
{
    scene_texture *grown = realloc(s->textures, sizeof *grown * (size_t)(s->texture_count + 1));
    if (!grown)
        return -1;
    s->textures = grown;
    scene_texture *t = &s->textures[s->texture_count];
    if (!(t->rgba = malloc(4 * (size_t)w * h)))
        return -1;
    t->width = w, t->height = h;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            texel(i, j, &t->rgba[4 * ((size_t)j * w + i)]);
    return s->texture_count++;
}

/* Sets vertex v of mesh m: position, normal, uv. */
static void set_vertex(scene_mesh *m, uint32_t v, vec3 p, vec3 n, float u, float t)
{
    v3_store(&m->positions[3 * v], p);
    v3_store(&m->normals[3 * v], n);
    m->texcoords[2 * v] = u, m->texcoords[2 * v + 1] = t;
}

/* Quad q of m from corner a along edges eu and ev (normal eu x ev); uv
 * (0, 1) .. (1, 0) over the quad, or, when planar > 0, the corners' world
 * (x, z) times planar. */
static void set_quad(scene_mesh *m, uint32_t q, vec3 a, vec3 eu, vec3 ev, float planar)
{
    vec3 n = v3_normalize(v3_cross(eu, ev));
    for (uint32_t k = 0; k < 4; ++k) {
        float u = (float)(k == 1 || k == 2), t = (float)(k >= 2);
        vec3 p = v3_add(a, v3_add(v3_scale(eu, u), v3_scale(ev, t)));
        set_vertex(m, 4 * q + k, p, n, planar > 0.0f ? planar * p.x : u, planar > 0.0f ? planar * p.z : 1.0f - t);
    }
    const uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    for (int k = 0; k < 6; ++k)
        m->indices[6 * q + k] = 4 * q + tri[k];
}

static void checker_texel(int i, int j, unsigned char rgba[4])
{
    unsigned char v = ((i / 2) + (j / 2)) % 2 ? 230 : 26;
    rgba[0] = rgba[1] = rgba[2] = v, rgba[3] = 255;
}

static int add_floor(scene *s)
{
    int texture = add_texture(s, 32, 32, checker_texel), material = add_material(s, 1.0f, 1.0f, 1.0f, texture);
    scene_mesh *m = texture < 0 || material < 0 ? NULL : scene_add_mesh(s, 4, 2, 1);
    if (!m)
        return -1;
    m->material = material;
    set_quad(m, 0, v3(-6.0f, 0.0f, 6.0f), v3(12.0f, 0.0f, 0.0f), v3(0.0f, 0.0f, -12.0f), 1.25f);
    return 0;
}

static int add_fence(scene *s)
{
    int material = add_material(s, 0.15f, 0.15f, 0.15f, -1);
    scene_mesh *m = material < 0 ? NULL : scene_add_mesh(s, 4 * (FENCE_VERTICAL + FENCE_HORIZONTAL),
                                                         2 * (FENCE_VERTICAL + FENCE_HORIZONTAL), 1);
    if (!m)
        return -1;
    m->material = material;
    const float z = -1.5f, wire = 0.01f, step = 0.12f;
    for (uint32_t k = 0; k < FENCE_VERTICAL; ++k)
        set_quad(m, k, v3(-3.0f + step * k - 0.5f * wire, 0.0f, z), v3(wire, 0.0f, 0.0f), v3(0.0f, 2.2f, 0.0f), 0.0f);
    for (uint32_t k = 0; k < FENCE_HORIZONTAL; ++k)
        set_quad(m, FENCE_VERTICAL + k, v3(-3.0f, step * (k + 1) - 0.5f * wire, z), v3(6.0f, 0.0f, 0.0f),
                 v3(0.0f, wire, 0.0f), 0.0f);
    return 0;
}

/* A uniform number in [0, 1) from an index (SplitMix64). */
static double splitmix_uniform(uint64_t i)
{
    uint64_t x = (i + 1) * 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return (double)((x ^ (x >> 31)) >> 11) * 0x1.0p-53;
}

static void set_blade(scene_mesh *m, uint32_t b)
{
    double u[5];
    for (int k = 0; k < 5; ++k)
        u[k] = splitmix_uniform(5u * b + (uint64_t)k);
    vec3 base = v3((float)(-3.0 + 6.0 * u[0]), 0.0f, (float)(0.5 + 2.0 * u[1]));
    vec3 tip = v3(base.x + (float)(0.16 * u[3] - 0.08), (float)(0.15 + 0.25 * u[2]), base.z + (float)(0.16 * u[4] - 0.08));
    vec3 half = v3(0.01f, 0.0f, 0.0f), a = v3_sub(base, half), c = v3_add(base, half);
    vec3 n = v3_normalize(v3_cross(v3_sub(c, a), v3_sub(tip, a)));
    set_vertex(m, 3 * b, a, n, 0.0f, 1.0f);
    set_vertex(m, 3 * b + 1, c, n, 1.0f, 1.0f);
    set_vertex(m, 3 * b + 2, tip, n, 0.5f, 0.0f);
    for (uint32_t k = 0; k < 3; ++k)
        m->indices[3 * b + k] = 3 * b + k;
}

static int add_grass(scene *s)
{
    int material = add_material(s, 0.2f, 0.5f, 0.1f, -1);
    scene_mesh *m = material < 0 ? NULL : scene_add_mesh(s, 3 * GRASS_BLADES, GRASS_BLADES, 1);
    if (!m)
        return -1;
    m->material = material;
    for (uint32_t b = 0; b < GRASS_BLADES; ++b)
        set_blade(m, b);
    return 0;
}

/* Leaves: alpha 1 inside one of 16 ellipses on a 4 x 4 grid of 16-texel
 * cells, semi-axes 6 and 2.5 texels, turned +-40 degrees. */
static void leaf_texel(int i, int j, unsigned char rgba[4])
{
    const double angle = (((i / 16) + (j / 16)) % 2 ? 40.0 : -40.0) * 3.14159265358979323846 / 180.0;
    double x = (i % 16) + 0.5 - 8.0, y = (j % 16) + 0.5 - 8.0;
    double a = cos(angle) * x + sin(angle) * y, b = -sin(angle) * x + cos(angle) * y;
    int inside = (a / 6.0) * (a / 6.0) + (b / 2.5) * (b / 2.5) <= 1.0;
    rgba[0] = 60, rgba[1] = (unsigned char)(140 + 4 * (i % 16)), rgba[2] = 40, rgba[3] = inside ? 255 : 0;
}

static int add_cards(scene *s)
{
    static const float x[CARDS] = {-2.0f, 0.2f, 2.2f}, turn_deg[CARDS] = {20.0f, -30.0f, 45.0f};
    int texture = add_texture(s, LEAF_TEXELS, LEAF_TEXELS, leaf_texel);
    int material = texture < 0 ? -1 : add_material(s, 1.0f, 1.0f, 1.0f, texture);
    scene_mesh *m = material < 0 ? NULL : scene_add_mesh(s, 4 * CARDS, 2 * CARDS, 1);
    if (!m || scene_set_alpha_cutoff(s, material, 0.5f) != 0)
        return -1;
    m->material = material;
    for (uint32_t k = 0; k < CARDS; ++k) {
        double a = turn_deg[k] * 3.14159265358979323846 / 180.0;
        vec3 eu = v3((float)(1.2 * cos(a)), 0.0f, (float)(-1.2 * sin(a)));
        set_quad(m, k, v3_sub(v3(x[k], 0.0f, -0.5f), v3_scale(eu, 0.5f)), eu, v3(0.0f, 1.2f, 0.0f), 0.0f);
    }
    return 0;
}

int builtin_build_aa_thin(scene *s)
{
    if (add_floor(s) != 0 || add_fence(s) != 0 || add_grass(s) != 0 || add_cards(s) != 0)
        return -1;
    s->has_camera = 1;
    s->camera = (camera){v3(1.5f, 1.6f, 5.5f), v3(0.0f, 0.8f, -0.5f), v3(0.0f, 1.0f, 0.0f),
                         (float)(45.0 * 3.14159265358979323846 / 180.0), 512, 512};
    return 0;
}
