/* glTF 2.0 ("Meshes"): a primitive without NORMAL is flat-shaded. Each
 * built-in scene written without normals loads into the same arrays, bit for
 * bit, as the same scene written with explicit flat normals (every triangle
 * its own three vertices carrying its face normal), and its AO reference is
 * the same image bit for bit; its normals are not the smooth ones the scene
 * was built with (where those are not flat already), and the meshes say they
 * were flat-shaded. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "raytracer/reference_render.h"
#include "scene/builtin_scenes.h"
#include "scene/gltf/gltf_writer.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"
#include "tests/scene/gltf/gltf_test_files.h"

/* The scene with every mesh unwelded (three vertices per triangle) and its
 * normals flat, as an exporter writing explicit flat normals would. */
static int flat_copy(const scene *s, scene *out)
{
    memset(out, 0, sizeof *out);
    for (int i = 0; i < s->mesh_count; ++i) {
        const scene_mesh *m = &s->meshes[i];
        scene_mesh *f = scene_add_mesh(out, 3 * m->triangle_count, m->triangle_count, m->texcoords != NULL);
        if (!f)
            return -1;
        f->material = m->material;
        for (uint32_t k = 0; k < 3 * m->triangle_count; ++k) {
            memcpy(&f->positions[3 * k], &m->positions[3 * m->indices[k]], 3 * sizeof(float));
            if (m->texcoords)
                memcpy(&f->texcoords[2 * k], &m->texcoords[2 * m->indices[k]], 2 * sizeof(float));
            f->indices[k] = k;
        }
        scene_mesh_compute_flat_normals(f);
    }
    for (int i = 0; i < s->material_count; ++i)
        if (scene_add_material(out, s->materials[i]) < 0 ||
            (s->alpha_cutoff && scene_set_alpha_cutoff(out, i, s->alpha_cutoff[i]) != 0))
            return -1;
    if (s->texture_count > 0 && !(out->textures = calloc((size_t)s->texture_count, sizeof *out->textures)))
        return -1;
    for (int i = 0; i < s->texture_count; ++i, ++out->texture_count) { /* textured scenes (aa-thin) */
        size_t bytes = 4 * (size_t)s->textures[i].width * s->textures[i].height;
        out->textures[i] = s->textures[i];
        if (!(out->textures[i].rgba = malloc(bytes)))
            return -1;
        memcpy(out->textures[i].rgba, s->textures[i].rgba, bytes);
    }
    return 0;
}

static int same_mesh(const scene_mesh *a, const scene_mesh *b)
{
    return a->vertex_count == b->vertex_count && a->triangle_count == b->triangle_count &&
           memcmp(a->positions, b->positions, 12 * (size_t)a->vertex_count) == 0 &&
           memcmp(a->normals, b->normals, 12 * (size_t)a->vertex_count) == 0 &&
           memcmp(a->indices, b->indices, 12 * (size_t)a->triangle_count) == 0;
}

static int render_ao(const scene *s, const camera *cam, image *out)
{
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = 8, .seed = 3, .threads = 2},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    gt_error e;
    return reference_render(s, "test", cam, &req, out, &stats, &e);
}

static void check_scene(const char *name)
{
    scene built, flat, loaded_bare, loaded_flat;
    gt_error e;
    CHECK(builtin_scene_build(name, &built, &e) == 0);
    CHECK(flat_copy(&built, &flat) == 0);
    char bare_path[4096], flat_path[4096];
    snprintf(bare_path, sizeof bare_path, "%s", tmp_path("flat_bare.glb"));
    snprintf(flat_path, sizeof flat_path, "%s", tmp_path("flat_explicit.glb"));
    CHECK(gltf_write_glb(flat_path, &flat, &e) == 0);
    float *smooth[64];
    int smooth_differs = 0;
    for (int i = 0; i < built.mesh_count && i < 64; ++i) {
        smooth[i] = built.meshes[i].normals;
        built.meshes[i].normals = NULL; /* written without NORMAL */
    }
    CHECK(gltf_write_glb(bare_path, &built, &e) == 0);
    for (int i = 0; i < built.mesh_count && i < 64; ++i)
        built.meshes[i].normals = smooth[i];
    CHECK(scene_load(bare_path, &loaded_bare, &e) == 0 && scene_load(flat_path, &loaded_flat, &e) == 0);
    CHECK(loaded_bare.mesh_count == loaded_flat.mesh_count);
    for (int i = 0; i < loaded_bare.mesh_count && i < loaded_flat.mesh_count; ++i) {
        CHECK_MSG(same_mesh(&loaded_bare.meshes[i], &loaded_flat.meshes[i]), "%s mesh %d", name, i);
        CHECK(loaded_bare.meshes[i].flat && !loaded_flat.meshes[i].flat);
        const scene_mesh *b = &built.meshes[i];
        for (uint32_t k = 0; k < 3 * b->triangle_count; ++k)
            smooth_differs |= memcmp(&b->normals[3 * b->indices[k]], &loaded_bare.meshes[i].normals[3 * k], 12) != 0;
    }
    vec3 lo, hi;
    scene_bounds(&built, &lo, &hi);
    camera cam = camera_auto_framing(lo, hi, 32, 32);
    image a, b;
    CHECK(render_ao(&loaded_bare, &cam, &a) == 0 && render_ao(&loaded_flat, &cam, &b) == 0);
    const float *va = image_channel_data(&a, "ao.V"), *vb = image_channel_data(&b, "ao.V");
    CHECK_MSG(va && vb && memcmp(va, vb, sizeof(float) * 32 * 32) == 0, "%s: AO differs", name);
    printf("%s: %d meshes; flat normals differ from the smooth ones: %s\n", name, loaded_bare.mesh_count,
           smooth_differs ? "yes" : "no");
    if (strcmp(name, "sphere-on-plane") == 0)
        CHECK(smooth_differs);
    image_free(&a);
    image_free(&b);
    scene_free(&built);
    scene_free(&flat);
    scene_free(&loaded_bare);
    scene_free(&loaded_flat);
}

int main(void)
{
    for (int i = 0; i < builtin_scene_count(); ++i)
        check_scene(builtin_scene_at(i)->name);
    return check_report("test_gltf_flat_normals");
}
