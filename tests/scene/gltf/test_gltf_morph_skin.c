/* Morph targets and skins in the default pose (glTF 2.0, "Morph Targets",
 * "Skins"; scene/gltf/vertex_pose.h), on tiny files written here:
 *  - a triangle with one morph target of weight 1 (from the mesh, or from
 *    the node overriding the mesh's 0) loads to the same bits as the file
 *    whose positions are the target's (base + delta) and whose normal is the
 *    target's; weight 0.5 gives base + delta / 2;
 *  - a triangle skinned to one joint rotated 90 degrees about +z (identity
 *    inverse bind matrix) loads as the same triangle placed on a node with
 *    that rotation: R (x, y, z) = (-y, x, z); the skinned node's own
 *    translation (100, 0, 0) is ignored, as the spec requires;
 *  - two joints weighted 1/2 each, the second unrotated but with inverse bind
 *    matrix translate(0, 0, -1) under a node at (0, 0, 1), give the mean
 *    (R p + p) / 2. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_test_files.h"
#include "scene/gltf/gltf_reader.h"
#include "tests/check.h"

typedef struct {
    float positions[3][3], normals[3][3], delta_positions[3][3], delta_normals[3][3];
    uint8_t joints[3][4];
    float weights[3][4];
    float inverse_bind[2][16];
} buffer_layout;

static buffer_layout data = {
    {{0.2f, -0.3f, 0.5f}, {1.1f, 0.4f, -0.2f}, {-0.5f, 0.9f, 0.3f}},
    {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}},
    {{0.1f, 0.2f, 0.3f}, {-0.4f, 0.0f, 0.25f}, {0.0f, -0.6f, 0.125f}},
    {{1, 0, -1}, {1, 0, -1}, {1, 0, -1}},
    {{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}},
    {{1, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}},
    {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 1}}};

static const char views[] =
    "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36,\"byteLength\":36},"
    "{\"buffer\":0,\"byteOffset\":72,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":108,\"byteLength\":36},"
    "{\"buffer\":0,\"byteOffset\":144,\"byteLength\":12},{\"buffer\":0,\"byteOffset\":156,\"byteLength\":48},"
    "{\"buffer\":0,\"byteOffset\":204,\"byteLength\":128}],"
    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
    "{\"bufferView\":1,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
    "{\"bufferView\":2,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
    "{\"bufferView\":3,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
    "{\"bufferView\":4,\"componentType\":5121,\"count\":3,\"type\":\"VEC4\"},"
    "{\"bufferView\":5,\"componentType\":5126,\"count\":3,\"type\":\"VEC4\"},"
    "{\"bufferView\":6,\"componentType\":5126,\"count\":2,\"type\":\"MAT4\"}]";

/* A file from its nodes and meshes (and extra top-level members). */
static int load_json(const char *name, const char *nodes, const char *meshes, const char *extra, scene *s)
{
    char *uri = data_uri(&data, sizeof data);
    char json[16384];
    snprintf(json, sizeof json,
             "{\"asset\":{\"version\":\"2.0\"},\"nodes\":%s,\"meshes\":%s,%s"
             "\"buffers\":[{\"byteLength\":%zu,\"uri\":\"%s\"}],%s}",
             nodes, meshes, extra, sizeof data, uri, views);
    free(uri);
    const char *path = tmp_path(name);
    gt_error e;
    CHECK(write_bytes(path, json, strlen(json)) == 0);
    const int rc = gltf_load(path, s, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    return rc;
}

static int same_bits(const scene *a, const scene *b)
{
    return a->mesh_count == 1 && b->mesh_count == 1 && memcmp(a->meshes[0].positions, b->meshes[0].positions, 36) == 0 &&
           memcmp(a->meshes[0].normals, b->meshes[0].normals, 36) == 0;
}

static const char morph_mesh[] = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},"
                                 "\"targets\":[{\"POSITION\":2,\"NORMAL\":3}]}],\"weights\":[%s]}]";

static void check_morphs(void)
{
    buffer_layout saved = data;
    scene mesh_weight, node_weight, half, target;
    char meshes[512];
    snprintf(meshes, sizeof meshes, morph_mesh, "1");
    load_json("morph_mesh.gltf", "[{\"mesh\":0}]", meshes, "", &mesh_weight);
    snprintf(meshes, sizeof meshes, morph_mesh, "0");
    load_json("morph_node.gltf", "[{\"mesh\":0,\"weights\":[1]}]", meshes, "", &node_weight);
    snprintf(meshes, sizeof meshes, morph_mesh, "0.5");
    load_json("morph_half.gltf", "[{\"mesh\":0}]", meshes, "", &half);
    for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k) {
            data.positions[v][k] = saved.positions[v][k] + saved.delta_positions[v][k];
            data.normals[v][k] = saved.normals[v][k] + saved.delta_normals[v][k];
        }
    load_json("morph_target.gltf", "[{\"mesh\":0}]", "[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1}}]}]",
              "", &target);
    data = saved;
    CHECK_MSG(same_bits(&mesh_weight, &target), "mesh weight 1 is not the target");
    CHECK_MSG(same_bits(&node_weight, &target), "node weight 1 is not the target");
    for (int v = 0; v < 3 && half.mesh_count == 1; ++v)
        for (int k = 0; k < 3; ++k)
            CHECK(half.meshes[0].positions[3 * v + k] == saved.positions[v][k] + 0.5f * saved.delta_positions[v][k]);
    scene_free(&mesh_weight), scene_free(&node_weight), scene_free(&half), scene_free(&target);
}

static const char skinned_mesh[] =
    "[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"JOINTS_0\":4,\"WEIGHTS_0\":5}}]}]";
static const char rotation[] = "\"rotation\":[0,0,0.70710678,0.70710678]";

static void check_skins(void)
{
    scene skinned, rotated, two;
    char nodes[512];
    snprintf(nodes, sizeof nodes, "[{\"mesh\":0,\"skin\":0,\"translation\":[100,0,0]},{%s}]", rotation);
    load_json("skin_one.gltf", nodes, skinned_mesh, "\"skins\":[{\"joints\":[1]}],", &skinned);
    snprintf(nodes, sizeof nodes, "[{\"mesh\":0,%s}]", rotation);
    load_json("skin_rotated.gltf", nodes, "[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1}}]}]", "",
              &rotated);
    for (int i = 0; i < 9 && skinned.mesh_count == 1 && rotated.mesh_count == 1; ++i) {
        CHECK_NEAR(skinned.meshes[0].positions[i], rotated.meshes[0].positions[i], 1e-6);
        CHECK_NEAR(skinned.meshes[0].normals[i], rotated.meshes[0].normals[i], 1e-6);
    }
    for (int v = 0; v < 3 && skinned.mesh_count == 1; ++v) { /* R p = (-y, x, z) */
        CHECK_NEAR(skinned.meshes[0].positions[3 * v], -data.positions[v][1], 1e-6);
        CHECK_NEAR(skinned.meshes[0].positions[3 * v + 1], data.positions[v][0], 1e-6);
    }
    const buffer_layout saved = data;
    for (int v = 0; v < 3; ++v)
        data.joints[v][1] = 1, data.weights[v][0] = 0.5f, data.weights[v][1] = 0.5f;
    snprintf(nodes, sizeof nodes, "[{\"mesh\":0,\"skin\":0},{%s},{\"translation\":[0,0,1]}]", rotation);
    load_json("skin_two.gltf", nodes, skinned_mesh, "\"skins\":[{\"joints\":[1,2],\"inverseBindMatrices\":6}],", &two);
    data = saved;
    for (int v = 0; v < 3 && two.mesh_count == 1; ++v) {
        const float *p = data.positions[v], *q = &two.meshes[0].positions[3 * v];
        CHECK_NEAR(q[0], 0.5 * (-p[1] + p[0]), 1e-6);
        CHECK_NEAR(q[1], 0.5 * (p[0] + p[1]), 1e-6);
        CHECK_NEAR(q[2], p[2], 1e-6);
    }
    scene_free(&skinned), scene_free(&rotated), scene_free(&two);
}

int main(void)
{
    check_morphs();
    check_skins();
    return check_report("test_gltf_morph_skin");
}
