/* The built-in scenes' pieces (scene/quad_mesh.h). */
#include "scene/quad_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

scene_material scene_matte_material(float r, float g, float b)
{
    scene_material m = {{r, g, b, 1.0f}, -1, 0.0f, 0.5f, -1}; /* metallic 0, roughness 0.5 */
    return m;
}

void scene_set_camera(scene *s, vec3 position, vec3 target, float yfov_deg)
{
    s->has_camera = 1;
    s->camera.position = position;
    s->camera.target = target;
    s->camera.up = v3(0.0f, 1.0f, 0.0f);
    s->camera.yfov = (float)(yfov_deg * 3.14159265358979323846 / 180.0);
    s->camera.width = 512;
    s->camera.height = 512;
}

int quad_list_push(quad_list *l, quad q)
{
    if (l->count == l->capacity) {
        uint32_t capacity = l->capacity ? 2 * l->capacity : 64;
        quad *grown = realloc(l->items, sizeof *grown * capacity);
        if (!grown)
            return -1;
        l->items = grown;
        l->capacity = capacity;
    }
    l->items[l->count++] = q;
    return 0;
}

void quad_list_free(quad_list *l)
{
    free(l->items);
    memset(l, 0, sizeof *l);
}

int quad_mesh_add(scene *s, const quad_list *l, int material)
{
    scene_mesh *m = scene_add_mesh(s, 4 * l->count, 2 * l->count, 0);
    if (!m)
        return -1;
    m->material = material;
    for (uint32_t q = 0; q < l->count; ++q) {
        const vec3 *p = l->items[q].p;
        double u[3] = {p[1].x - p[0].x, p[1].y - p[0].y, p[1].z - p[0].z};
        double v[3] = {p[2].x - p[0].x, p[2].y - p[0].y, p[2].z - p[0].z};
        double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        vec3 normal = v3((float)(n[0] / len), (float)(n[1] / len), (float)(n[2] / len));
        for (int k = 0; k < 4; ++k) {
            v3_store(&m->positions[3 * (4 * q + k)], p[k]);
            v3_store(&m->normals[3 * (4 * q + k)], normal);
        }
        const uint32_t base = 4 * q, tri[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; ++k)
            m->indices[6 * q + k] = base + tri[k];
    }
    return 0;
}

/* Each face's corners, counter-clockwise seen from outside. */
static const unsigned char box_face_corners[6][4] = {
    {1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1},
};

void aligned_box_corners(vec3 lo, vec3 hi, vec3 corners[8])
{
    for (int c = 0; c < 8; ++c)
        corners[c] = v3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
}

void turned_block_corners(vec3 base_centre, vec3 size, double angle, vec3 corners[8])
{
    const double c = cos(angle), s = sin(angle);
    for (int k = 0; k < 8; ++k) {
        double x = (k & 1 ? 0.5 : -0.5) * size.x, z = (k & 4 ? 0.5 : -0.5) * size.z;
        corners[k] = v3((float)(base_centre.x + c * x + s * z), k & 2 ? size.y : 0.0f,
                        (float)(base_centre.z - s * x + c * z));
    }
}

int push_box_faces(quad_list *l, const vec3 corners[8], unsigned face_mask, int inward)
{
    for (int f = 0; f < 6; ++f) {
        if (!(face_mask & FACE_BIT(f)))
            continue;
        quad q;
        for (int k = 0; k < 4; ++k)
            q.p[k] = corners[box_face_corners[f][inward ? (4 - k) % 4 : k]];
        if (quad_list_push(l, q) != 0)
            return -1;
    }
    return 0;
}

uint32_t scene_pcg_hash(uint32_t v)
{
    uint32_t state = v * 747796405u + 2891336453u;
    uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

float scene_unit_hash(uint32_t n) { return (float)(scene_pcg_hash(n) >> 8) * (1.0f / 16777216.0f); }
