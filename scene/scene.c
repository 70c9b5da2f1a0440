#include "scene/scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

scene_material scene_default_material(void)
{
    scene_material m = {{1.0f, 1.0f, 1.0f, 1.0f}, -1, 1.0f, 1.0f, -1};
    return m;
}

const scene_material *scene_mesh_material(const scene *s, const scene_mesh *m)
{
    static const scene_material fallback = {{1.0f, 1.0f, 1.0f, 1.0f}, -1, 1.0f, 1.0f, -1};
    if (m->material >= 0 && m->material < s->material_count)
        return &s->materials[m->material];
    return &fallback;
}

void scene_bounds(const scene *s, vec3 *lo, vec3 *hi)
{
    *lo = v3(INFINITY, INFINITY, INFINITY);
    *hi = v3(-INFINITY, -INFINITY, -INFINITY);
    for (int i = 0; i < s->mesh_count; ++i) {
        const scene_mesh *m = &s->meshes[i];
        for (uint32_t v = 0; v < m->vertex_count; ++v) {
            vec3 p = v3_load(&m->positions[3 * v]);
            *lo = v3_min(*lo, p);
            *hi = v3_max(*hi, p);
        }
    }
}

uint64_t scene_triangle_count(const scene *s)
{
    uint64_t n = 0;
    for (int i = 0; i < s->mesh_count; ++i)
        n += s->meshes[i].triangle_count;
    return n;
}

scene_mesh *scene_add_mesh(scene *s, uint32_t vertex_count, uint32_t triangle_count, int with_texcoords)
{
    scene_mesh *grown = realloc(s->meshes, sizeof *grown * (size_t)(s->mesh_count + 1));
    if (!grown)
        return NULL;
    s->meshes = grown;
    scene_mesh *m = &s->meshes[s->mesh_count];
    memset(m, 0, sizeof *m);
    m->vertex_count = vertex_count;
    m->triangle_count = triangle_count;
    m->material = -1;
    m->positions = malloc(sizeof(float) * 3 * (size_t)vertex_count + 1);
    m->normals = malloc(sizeof(float) * 3 * (size_t)vertex_count + 1);
    m->indices = malloc(sizeof(uint32_t) * 3 * (size_t)triangle_count + 1);
    m->texcoords = with_texcoords ? malloc(sizeof(float) * 2 * (size_t)vertex_count + 1) : NULL;
    if (!m->positions || !m->normals || !m->indices || (with_texcoords && !m->texcoords)) {
        free(m->positions);
        free(m->normals);
        free(m->indices);
        free(m->texcoords);
        return NULL;
    }
    s->mesh_count++;
    return m;
}

int scene_add_material(scene *s, scene_material m)
{
    scene_material *grown = realloc(s->materials, sizeof *grown * (size_t)(s->material_count + 1));
    if (!grown)
        return -1;
    s->materials = grown;
    s->materials[s->material_count] = m;
    if (s->alpha_cutoff) {
        float *cutoffs = realloc(s->alpha_cutoff, sizeof *cutoffs * (size_t)(s->material_count + 1));
        if (!cutoffs)
            return -1;
        s->alpha_cutoff = cutoffs;
        s->alpha_cutoff[s->material_count] = 0.0f;
    }
    return s->material_count++;
}

int scene_set_alpha_cutoff(scene *s, int material, float cutoff)
{
    if (!s->alpha_cutoff && !(s->alpha_cutoff = calloc((size_t)s->material_count + 1, sizeof(float))))
        return -1;
    s->alpha_cutoff[material] = cutoff;
    return 0;
}

void scene_mesh_compute_normals(scene_mesh *m)
{
    memset(m->normals, 0, sizeof(float) * 3 * m->vertex_count);
    for (uint32_t t = 0; t < m->triangle_count; ++t) {
        const uint32_t *idx = &m->indices[3 * t];
        vec3 a = v3_load(&m->positions[3 * idx[0]]);
        vec3 b = v3_load(&m->positions[3 * idx[1]]);
        vec3 c = v3_load(&m->positions[3 * idx[2]]);
        vec3 area_normal = v3_cross(v3_sub(b, a), v3_sub(c, a)); /* length = 2 x area */
        for (int k = 0; k < 3; ++k) {
            float *n = &m->normals[3 * idx[k]];
            v3_store(n, v3_add(v3_load(n), area_normal));
        }
    }
    for (uint32_t v = 0; v < m->vertex_count; ++v) {
        vec3 n = v3_load(&m->normals[3 * v]);
        float len = v3_length(n);
        v3_store(&m->normals[3 * v], len > 0.0f ? v3_scale(n, 1.0f / len) : v3(0.0f, 1.0f, 0.0f));
    }
}

void scene_mesh_compute_flat_normals(scene_mesh *m)
{
    for (uint32_t t = 0; t < m->triangle_count; ++t) {
        const uint32_t *idx = &m->indices[3 * t];
        vec3 a = v3_load(&m->positions[3 * idx[0]]);
        vec3 b = v3_load(&m->positions[3 * idx[1]]);
        vec3 c = v3_load(&m->positions[3 * idx[2]]);
        vec3 n = v3_cross(v3_sub(b, a), v3_sub(c, a));
        float len = v3_length(n);
        n = len > 0.0f ? v3_scale(n, 1.0f / len) : v3(0.0f, 1.0f, 0.0f);
        for (int k = 0; k < 3; ++k)
            v3_store(&m->normals[3 * idx[k]], n);
    }
    m->flat = 1;
}

int scene_validate(const scene *s, const char *what, gt_error *e)
{
    if (scene_triangle_count(s) == 0)
        return gt_error_set(e, what, "the scene has no triangles");
    for (int i = 0; i < s->mesh_count; ++i) {
        const scene_mesh *m = &s->meshes[i];
        for (uint32_t v = 0; v < m->vertex_count; ++v) {
            if (!v3_is_finite(v3_load(&m->positions[3 * v])))
                return gt_error_set(e, what, "mesh %d: vertex %u has a non-finite position", i, v);
            if (!v3_is_finite(v3_load(&m->normals[3 * v])))
                return gt_error_set(e, what, "mesh %d: vertex %u has a non-finite normal", i, v);
        }
        for (uint64_t k = 0; k < 3ull * m->triangle_count; ++k)
            if (m->indices[k] >= m->vertex_count)
                return gt_error_set(e, what, "mesh %d: index %u out of range (%u vertices)", i, m->indices[k],
                                    m->vertex_count);
    }
    return 0;
}

void scene_free(scene *s)
{
    for (int i = 0; i < s->mesh_count; ++i) {
        free(s->meshes[i].positions);
        free(s->meshes[i].normals);
        free(s->meshes[i].texcoords);
        free(s->meshes[i].indices);
    }
    free(s->meshes);
    for (int i = 0; i < s->texture_count; ++i)
        free(s->textures[i].rgba);
    free(s->textures);
    free(s->materials);
    free(s->alpha_cutoff);
    memset(s, 0, sizeof *s);
}

int scene_choose_camera(const scene *s, const char *camera_json_path, int width, int height, camera *cam,
                        gt_error *e)
{
    if (camera_json_path) {
        if (camera_read_json(camera_json_path, cam, e) != 0)
            return -1;
    } else if (s->has_camera) {
        *cam = s->camera;
    } else {
        vec3 lo, hi;
        scene_bounds(s, &lo, &hi);
        *cam = camera_auto_framing(lo, hi, 512, 512);
    }
    double aspect = (double)cam->width / (double)cam->height;
    if (width > 0 && height <= 0)
        height = (int)fmax(1.0, round(width / aspect));
    if (height > 0 && width <= 0)
        width = (int)fmax(1.0, round(height * aspect));
    if (width > 0) {
        cam->width = width;
        cam->height = height;
    }
    return camera_validate(cam, camera_json_path ? camera_json_path : s->name, e);
}
