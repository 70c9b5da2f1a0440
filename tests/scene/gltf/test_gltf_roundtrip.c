/* gltf_write_glb then gltf_load: a small hand-built scene (two meshes, a
 * textured material and a plain one, a camera) comes back equal: geometry
 * exactly (floats are stored as floats), PNG texels exactly (lossless), the
 * camera to float rounding. Also: the output is written atomically and an
 * unwritable path is one clear error. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../check.h"
#include "gltf_test_files.h"
#include "scene/gltf/gltf_reader.h"
#include "scene/gltf/gltf_writer.h"

static const float quad_positions[] = {0, 0, 0, 2, 0, 0, 2, 0, -3, 0, 0, -3};
static const float quad_texcoords[] = {0, 0, 1, 0, 1, 1, 0, 1};
static const uint32_t quad_indices[] = {0, 1, 2, 0, 2, 3};
static const float tri_positions[] = {-1, 0.5f, 0.25f, 1, 0.5f, 0.25f, 0, 1.75f, 0.25f};
static const uint32_t tri_indices[] = {0, 1, 2};
static const unsigned char texels[16] = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0, 17, 34, 51, 68};

static void build_scene(scene *s)
{
    memset(s, 0, sizeof *s);
    scene_mesh *quad = scene_add_mesh(s, 4, 2, 1);
    memcpy(quad->positions, quad_positions, sizeof quad_positions);
    memcpy(quad->texcoords, quad_texcoords, sizeof quad_texcoords);
    memcpy(quad->indices, quad_indices, sizeof quad_indices);
    scene_mesh_compute_normals(quad);
    quad->material = 0;
    scene_mesh *tri = scene_add_mesh(s, 3, 1, 0);
    memcpy(tri->positions, tri_positions, sizeof tri_positions);
    memcpy(tri->indices, tri_indices, sizeof tri_indices);
    scene_mesh_compute_normals(tri);
    tri->material = 1;

    s->textures = calloc(1, sizeof *s->textures);
    s->textures[0].width = 2;
    s->textures[0].height = 2;
    s->textures[0].rgba = malloc(sizeof texels);
    memcpy(s->textures[0].rgba, texels, sizeof texels);
    s->texture_count = 1;
    scene_material textured = {{0.5f, 0.25f, 0.125f, 1.0f}, 0, 0.3f, 0.7f, 0};
    scene_material plain = {{0.1f, 0.2f, 0.3f, 0.9f}, -1, 0.0f, 0.45f, -1};
    scene_add_material(s, textured);
    scene_add_material(s, plain);

    s->has_camera = 1;
    s->camera.position = v3(1, 2, 3);
    s->camera.target = v3(1, 1.5f, 1); /* direction (0, -0.5, -2): a tilted view */
    s->camera.up = v3(0, 1, 0);
    s->camera.yfov = 0.8f;
    s->camera.width = 512;
    s->camera.height = 256;
}

static void check_mesh_equal(const scene_mesh *a, const scene_mesh *b)
{
    CHECK(a->vertex_count == b->vertex_count);
    CHECK(a->triangle_count == b->triangle_count);
    if (a->vertex_count != b->vertex_count || a->triangle_count != b->triangle_count)
        return;
    CHECK(memcmp(a->positions, b->positions, sizeof(float) * 3 * a->vertex_count) == 0);
    CHECK(memcmp(a->indices, b->indices, sizeof(uint32_t) * 3 * a->triangle_count) == 0);
    for (uint32_t i = 0; i < 3 * a->vertex_count; ++i)
        CHECK_NEAR(a->normals[i], b->normals[i], 1e-6); /* renormalised on load */
    CHECK((a->texcoords == NULL) == (b->texcoords == NULL));
    if (a->texcoords && b->texcoords)
        CHECK(memcmp(a->texcoords, b->texcoords, sizeof(float) * 2 * a->vertex_count) == 0);
}

static void check_material_equal(const scene *sa, const scene_material *a, const scene *sb, const scene_material *b)
{
    for (int k = 0; k < 4; ++k)
        CHECK(a->base_color[k] == b->base_color[k]);
    CHECK(a->metallic == b->metallic);
    CHECK(a->roughness == b->roughness);
    CHECK((a->base_color_texture < 0) == (b->base_color_texture < 0));
    CHECK((a->metallic_roughness_texture < 0) == (b->metallic_roughness_texture < 0));
    if (a->base_color_texture >= 0 && b->base_color_texture >= 0 && b->base_color_texture < sb->texture_count) {
        const scene_texture *ta = &sa->textures[a->base_color_texture];
        const scene_texture *tb = &sb->textures[b->base_color_texture];
        CHECK(ta->width == tb->width && ta->height == tb->height);
        if (ta->width == tb->width && ta->height == tb->height)
            CHECK(memcmp(ta->rgba, tb->rgba, 4 * (size_t)ta->width * (size_t)ta->height) == 0);
    }
}

static void check_roundtrip(void)
{
    scene original, loaded;
    gt_error e = {{0}};
    build_scene(&original);
    const char *path = tmp_path("roundtrip.glb");
    char path_copy[4096];
    snprintf(path_copy, sizeof path_copy, "%s", path);
    unlink(path_copy);
    CHECK_MSG(gltf_write_glb(path_copy, &original, &e) == 0, "%s", e.message);

    char temp[4200]; /* atomic_file's temporary name must be gone */
    snprintf(temp, sizeof temp, "%s/.roundtrip.glb.tmp-%ld", check_tmp_dir(), (long)getpid());
    CHECK(access(temp, F_OK) != 0);

    char printed[4096];
    int rc = load_capturing(path_copy, &loaded, &e, printed, sizeof printed);
    CHECK_MSG(rc == 0, "%s", e.message);
    CHECK(printed[0] == '\0');
    if (rc != 0)
        return;
    CHECK(loaded.mesh_count == 2);
    for (int i = 0; i < 2 && i < loaded.mesh_count; ++i) {
        check_mesh_equal(&original.meshes[i], &loaded.meshes[i]);
        check_material_equal(&original, scene_mesh_material(&original, &original.meshes[i]), &loaded,
                             scene_mesh_material(&loaded, &loaded.meshes[i]));
    }
    CHECK(loaded.texture_count == 1);

    /* The loader's camera target is position + unit forward (a glTF camera has
     * no target distance), so compare directions. */
    CHECK(loaded.has_camera);
    vec3 d0 = v3_normalize(v3_sub(original.camera.target, original.camera.position));
    vec3 d1 = v3_sub(loaded.camera.target, loaded.camera.position);
    CHECK_NEAR(v3_length(d1), 1.0, 1e-6);
    CHECK_NEAR(d1.x, d0.x, 1e-6);
    CHECK_NEAR(d1.y, d0.y, 1e-6);
    CHECK_NEAR(d1.z, d0.z, 1e-6);
    CHECK_NEAR(loaded.camera.position.x, 1.0, 1e-6);
    CHECK_NEAR(loaded.camera.position.y, 2.0, 1e-6);
    CHECK_NEAR(loaded.camera.position.z, 3.0, 1e-6);
    /* up comes back orthogonalised: perpendicular to the view, in the plane of
     * the original up and the view direction, on the same side as +Y. */
    CHECK_NEAR(v3_dot(loaded.camera.up, d1), 0.0, 1e-6);
    CHECK_NEAR(v3_dot(loaded.camera.up, v3_cross(d0, v3(0, 1, 0))), 0.0, 1e-6);
    CHECK(loaded.camera.up.y > 0.0f);
    CHECK_NEAR(loaded.camera.yfov, 0.8, 1e-6);
    CHECK(loaded.camera.width == 512 && loaded.camera.height == 256);

    /* asset.generator identifies the writer. */
    FILE *f = fopen(path_copy, "rb");
    char head[2048] = {0};
    size_t n = f ? fread(head, 1, sizeof head - 1, f) : 0;
    if (f)
        fclose(f);
    CHECK(n > 20);
    int found = 0;
    for (size_t i = 20; i + 19 < n; ++i)
        found |= memcmp(head + i, "\"generator\":\"gtlab\"", 19) == 0;
    CHECK(found);

    scene_free(&loaded);
    scene_free(&original);
}

static void check_unwritable_path(void)
{
    scene s;
    gt_error e = {{0}};
    build_scene(&s);
    const char *path = "/nonexistent-gtlab-dir/out.glb";
    CHECK(gltf_write_glb(path, &s, &e) != 0);
    CHECK(strstr(e.message, path) == e.message);
    CHECK(access(path, F_OK) != 0);
    scene_free(&s);
}

int main(void)
{
    check_roundtrip();
    check_unwritable_path();
    return check_report("test_gltf_roundtrip");
}
