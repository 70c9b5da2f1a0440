/* Broken glTF input: the deliberately broken files of Debian's
 * assimp-testmodels and files crafted here. Each must either fail with one
 * error that starts with the file's path and names the problem (leaving the
 * scene empty), or — where the file is still usable — load with a warning and
 * the right content. Either way the library may print nothing but gt_warn
 * lines. ASan/UBSan builds run the same cases (GTLAB_SANITIZE=ON). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../../check.h"
#include "gltf_test_files.h"
#include "scene/gltf/gltf_reader.h"

#define ASSIMP "/usr/share/assimp/models/glTF2/"

static char printed[16384];

/* Loads path and expects failure with `problem` in the message. */
static void expect_error(const char *path, const char *problem)
{
    scene s;
    gt_error e = {{0}};
    int rc = load_capturing(path, &s, &e, printed, sizeof printed);
    CHECK_MSG(rc != 0, "%s loaded, expected an error about \"%s\"", path, problem);
    if (rc == 0) {
        scene_free(&s);
        return;
    }
    size_t n = strlen(path);
    CHECK_MSG(strncmp(e.message, path, n) == 0 && strncmp(e.message + n, ": ", 2) == 0,
              "message does not start with the path: %s", e.message);
    CHECK_MSG(strstr(e.message, problem) != NULL, "expected \"%s\" in: %s", problem, e.message);
    CHECK_MSG(strchr(e.message, '\n') == NULL, "multi-line message: %s", e.message);
    CHECK_MSG(only_warnings(printed), "%s printed more than warnings", path);
    CHECK(s.mesh_count == 0 && s.meshes == NULL && s.textures == NULL && s.materials == NULL);
}

/* Loads path and expects success with a warning containing `warning`. The
 * caller checks the content and frees the scene. */
static int expect_warning(const char *path, const char *warning, scene *s)
{
    gt_error e = {{0}};
    int rc = load_capturing(path, s, &e, printed, sizeof printed);
    CHECK_MSG(rc == 0, "%s failed: %s", path, e.message);
    CHECK_MSG(strstr(printed, warning) != NULL, "%s: expected a warning with \"%s\"", path, warning);
    CHECK_MSG(only_warnings(printed), "%s printed more than warnings", path);
    return rc;
}

static int expect_clean_load(const char *path, scene *s)
{
    gt_error e = {{0}};
    int rc = load_capturing(path, s, &e, printed, sizeof printed);
    CHECK_MSG(rc == 0, "%s failed: %s", path, e.message);
    CHECK_MSG(printed[0] == '\0', "%s printed something", path);
    return rc;
}

/* ------------------------------------------------------------------ files */

/* One triangle (0,0,0) (1,0,0) (0,1,0) with u16 indices: 36 + 6 bytes, padded. */
typedef struct {
    float positions[9];
    unsigned short indices[4];
} triangle_buffer;

static const triangle_buffer good_buffer = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 1, 2, 0}};

/* A .gltf whose parts default to a valid one-triangle file. */
typedef struct {
    const char *file;
    const char *scenes, *nodes, *meshes, *accessors, *views, *buffers, *extra;
    const triangle_buffer *buffer;
} crafted;

static const char default_accessors[] =
    "[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
    "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]";
static const char default_views[] =
    "[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6}]";

static char *crafted_json(const crafted *c, int glb)
{
    char *uri = data_uri(c->buffer ? c->buffer : &good_buffer, sizeof(triangle_buffer));
    char default_buffers[4096];
    if (glb)
        snprintf(default_buffers, sizeof default_buffers, "[{\"byteLength\":%zu}]", sizeof(triangle_buffer));
    else
        snprintf(default_buffers, sizeof default_buffers, "[{\"byteLength\":%zu,\"uri\":\"%s\"}]",
                 sizeof(triangle_buffer), uri);
    size_t cap = 16384;
    char *json = malloc(cap);
    snprintf(json, cap,
             "{\"asset\":{\"version\":\"2.0\"},%s,\"nodes\":%s,\"meshes\":%s,\"accessors\":%s,"
             "\"bufferViews\":%s,\"buffers\":%s%s%s}",
             c->scenes ? c->scenes : "\"scene\":0,\"scenes\":[{\"nodes\":[0]}]", c->nodes ? c->nodes : "[{\"mesh\":0}]",
             c->meshes ? c->meshes : "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}]",
             c->accessors ? c->accessors : default_accessors, c->views ? c->views : default_views,
             c->buffers ? c->buffers : default_buffers, c->extra ? "," : "", c->extra ? c->extra : "");
    free(uri);
    return json;
}

static const char *write_crafted(const crafted *c)
{
    char *json = crafted_json(c, 0);
    const char *path = tmp_path(c->file);
    CHECK(write_bytes(path, json, strlen(json)) == 0);
    free(json);
    return path;
}

static unsigned char *crafted_glb(const crafted *c, size_t *size)
{
    char *json = crafted_json(c, 1);
    unsigned char *glb = glb_bytes(json, c->buffer ? c->buffer : &good_buffer, sizeof(triangle_buffer), size);
    free(json);
    return glb;
}

static const char *write_crafted_glb(const crafted *c)
{
    size_t size;
    unsigned char *glb = crafted_glb(c, &size);
    const char *path = tmp_path(c->file);
    CHECK(write_bytes(path, glb, size) == 0);
    free(glb);
    return path;
}

/* ------------------------------------------------- assimp-testmodels files */

/* Decisions for the broken files of assimp-testmodels:
 *  BoxWithInfinites   error: POSITION holds +-inf; no render can be right.
 *  IndexOutOfRange,
 *  AllIndicesOutOfRange  error: an index >= the vertex count would read
 *                     outside the vertex arrays.
 *  MissingBin         error: the geometry lives in the missing .bin.
 *  RecursiveNodes     error: node 0 -> 1 -> 0 is a cycle ("node graph has a cycle").
 *  IncorrectVertexArrays  error: a triangle primitive with 35 vertices (and
 *                     one with 35 indices) is not a whole number of
 *                     triangles; guessing which vertex is missing could render
 *                     a wrong mesh. (Its line primitives would be skipped
 *                     with a warning.)
 *  TestNoRootNode     error: no scene / a scene without nodes has no triangles.
 *  BoxBadNormals      usable with a warning: some normals are zero (others
 *                     merely not unit length, which is renormalised); the
 *                     positions are fine, so the normals are recomputed from
 *                     the triangles and the box renders correctly. */
static void check_assimp_broken_files(void)
{
    expect_error(ASSIMP "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "is not finite");
    expect_error(ASSIMP "IndexOutOfRange/IndexOutOfRange.gltf", "index 255 (entry 0) is out of range (24 vertices)");
    expect_error(ASSIMP "IndexOutOfRange/AllIndicesOutOfRange.gltf", "is out of range");
    expect_error(ASSIMP "MissingBin/BoxTextured.gltf", "BoxTextured0.bin");
    expect_error(ASSIMP "RecursiveNodes/RecursiveNodes.gltf", "node graph has a cycle");
    expect_error(ASSIMP "IncorrectVertexArrays/Cube.gltf", "mesh 1 (TruncatedCube) primitive 0: 35 vertices");
    expect_error(ASSIMP "TestNoRootNode/NoScene.gltf", "no triangles");
    expect_error(ASSIMP "TestNoRootNode/SceneWithoutNodes.gltf", "no triangles");

    /* BoxBadNormals: the recomputed normals must be the faces' normals: the
     * box's 24 vertices are 4 per face, so each vertex normal equals the
     * normal of both of its face's triangles, computed here from positions. */
    scene s;
    if (expect_warning(ASSIMP "BoxBadNormals-glTF-Binary/BoxBadNormals.glb", "normals recomputed", &s) != 0)
        return;
    CHECK(s.mesh_count == 1 && s.meshes[0].triangle_count == 12 && s.meshes[0].vertex_count == 24);
    const scene_mesh *m = &s.meshes[0];
    for (uint32_t t = 0; t < m->triangle_count; ++t) {
        const uint32_t *idx = &m->indices[3 * t];
        vec3 a = v3_load(&m->positions[3 * idx[0]]), b = v3_load(&m->positions[3 * idx[1]]),
             c = v3_load(&m->positions[3 * idx[2]]);
        vec3 face = v3_normalize(v3_cross(v3_sub(b, a), v3_sub(c, a)));
        for (int k = 0; k < 3; ++k)
            CHECK_NEAR(v3_dot(v3_load(&m->normals[3 * idx[k]]), face), 1.0, 1e-6);
        /* and it points out of the box (centred at the origin) */
        CHECK(v3_dot(face, v3_scale(v3_add(v3_add(a, b), c), 1.0f / 3.0f)) > 0.0f);
    }
    scene_free(&s);
}

static void check_assimp_good_files(void)
{
    scene s;
    /* The same textured box three ways: external .bin + .png, .glb, embedded. */
    const char *boxes[] = {ASSIMP "BoxTextured-glTF/BoxTextured.gltf", ASSIMP "BoxTextured-glTF-Binary/BoxTextured.glb",
                           ASSIMP "BoxTextured-glTF-Embedded/BoxTextured.gltf"};
    for (int i = 0; i < 3; ++i) {
        if (expect_clean_load(boxes[i], &s) != 0)
            continue;
        CHECK(scene_triangle_count(&s) == 12);
        CHECK(s.material_count == 1 && s.texture_count == 1);
        if (s.material_count == 1 && s.texture_count == 1) {
            CHECK(s.materials[0].base_color_texture == 0);
            CHECK(s.textures[0].width == 211 && s.textures[0].height == 211); /* CesiumLogoFlat.png */
        }
        CHECK(s.meshes[0].texcoords != NULL);
        scene_free(&s);
    }
    if (expect_clean_load(ASSIMP "2CylinderEngine-glTF-Binary/2CylinderEngine.glb", &s) == 0) {
        CHECK_MSG(scene_triangle_count(&s) == 121496, "%llu triangles",
                  (unsigned long long)scene_triangle_count(&s));
        scene_free(&s);
    }
    if (expect_clean_load(ASSIMP "cameras/Cameras.gltf", &s) == 0) {
        CHECK(s.has_camera);
        scene_free(&s);
    }
}

/* wrongTypes holds JSON values of the wrong type in various places: whatever
 * tinygltf accepts must load to a valid scene, the rest must be one error. */
static void check_assimp_wrong_types(void)
{
    const char *files[] = {"badArray", "badExtension", "badNumber", "badObject", "badString", "badUint"};
    for (int i = 0; i < 6; ++i) {
        char path[512];
        snprintf(path, sizeof path, ASSIMP "wrongTypes/%s.gltf", files[i]);
        scene s;
        gt_error e = {{0}};
        int rc = load_capturing(path, &s, &e, printed, sizeof printed);
        CHECK(only_warnings(printed));
        if (rc == 0) {
            CHECK(scene_validate(&s, path, &e) == 0);
            scene_free(&s);
        } else {
            CHECK_MSG(strncmp(e.message, path, strlen(path)) == 0, "%s", e.message);
        }
    }
}

/* ---------------------------------------------------------- crafted files */

static void check_crafted_errors(void)
{
    const crafted cases[] = {
        {.file = "points-only.gltf", .meshes = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"mode\":0}]}]"},
        {.file = "empty-scene.gltf", .scenes = "\"scene\":0,\"scenes\":[{\"nodes\":[]}]"},
        {.file = "self-cycle.gltf", .nodes = "[{\"mesh\":0,\"children\":[0]}]"},
        {.file = "detached-cycle.gltf", .nodes = "[{\"mesh\":0},{\"children\":[2]},{\"children\":[1]}]"},
        {.file = "two-parents.gltf", .scenes = "\"scenes\":[{\"nodes\":[0,1]}]",
         .nodes = "[{\"mesh\":0,\"children\":[2]},{\"children\":[2]},{}]"},
        {.file = "child-missing.gltf", .nodes = "[{\"mesh\":0,\"children\":[7]}]"},
        {.file = "mesh-missing.gltf", .nodes = "[{\"mesh\":3}]"},
        {.file = "scene-node-missing.gltf", .scenes = "\"scenes\":[{\"nodes\":[3]}]"},
        {.file = "default-scene-missing.gltf", .scenes = "\"scene\":5,\"scenes\":[{\"nodes\":[0]}]"},
        {.file = "scene-lists-child.gltf", .scenes = "\"scenes\":[{\"nodes\":[0,1]}]",
         .nodes = "[{\"mesh\":0,\"children\":[1]},{}]"},
        {.file = "bad-matrix.gltf", .nodes = "[{\"mesh\":0,\"matrix\":[1,0,0]}]"},
        {.file = "zero-quaternion.gltf", .nodes = "[{\"mesh\":0,\"rotation\":[0,0,0,0]}]"},
        {.file = "position-accessor-missing.gltf",
         .meshes = "[{\"primitives\":[{\"attributes\":{\"POSITION\":9},\"indices\":1}]}]"},
        {.file = "indices-accessor-missing.gltf",
         .meshes = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":9}]}]"},
        {.file = "material-missing.gltf",
         .meshes = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"material\":5}]}]"},
        {.file = "no-position.gltf", .meshes = "[{\"primitives\":[{\"attributes\":{\"NORMAL\":0},\"indices\":1}]}]"},
        {.file = "position-vec2.gltf",
         .accessors = "[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC2\"},"
                      "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]"},
        {.file = "position-u16.gltf",
         .accessors = "[{\"bufferView\":0,\"componentType\":5123,\"count\":3,\"type\":\"VEC3\"},"
                      "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]"},
        {.file = "indices-float.gltf",
         .accessors = "[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
                      "{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"SCALAR\"}]"},
        {.file = "texcoord-u8-not-normalized.gltf",
         .meshes = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":2},\"indices\":1}]}]",
         .accessors = "[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
                      "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"},"
                      "{\"bufferView\":0,\"componentType\":5121,\"count\":3,\"type\":\"VEC2\"}]"},
        {.file = "normal-count.gltf",
         .meshes = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":2},\"indices\":1}]}]",
         .accessors = "[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
                      "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"},"
                      "{\"bufferView\":0,\"componentType\":5126,\"count\":2,\"type\":\"VEC3\"}]"},
        {.file = "accessor-past-view.gltf",
         .accessors = "[{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\"},"
                      "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]"},
        {.file = "accessor-offset-past-view.gltf",
         .accessors = "[{\"bufferView\":0,\"byteOffset\":4000000000,\"componentType\":5126,\"count\":3,"
                      "\"type\":\"VEC3\"},{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]"},
        {.file = "huge-count.gltf",
         .accessors = "[{\"bufferView\":0,\"componentType\":5126,\"count\":4294967295,\"type\":\"VEC3\"},"
                      "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]"},
        {.file = "view-past-buffer.gltf",
         .views = "[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},"
                  "{\"buffer\":0,\"byteOffset\":40,\"byteLength\":6}]"},
        {.file = "view-buffer-missing.gltf",
         .views = "[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},"
                  "{\"buffer\":3,\"byteOffset\":36,\"byteLength\":6}]"},
        {.file = "accessor-view-missing.gltf",
         .accessors = "[{\"bufferView\":5,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
                      "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]"},
        {.file = "accessor-no-view.gltf",
         .accessors = "[{\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
                      "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]"},
        {.file = "small-stride.gltf",
         .views = "[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36,\"byteStride\":8},"
                  "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6}]"},
        {.file = "sparse.gltf",
         .accessors = "[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\",\"sparse\":{\"count\":1,"
                      "\"indices\":{\"bufferView\":1,\"componentType\":5126},\"values\":{\"bufferView\":0}}},"
                      "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]"},
        {.file = "two-indices.gltf",
         .accessors = "[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
                      "{\"bufferView\":1,\"componentType\":5123,\"count\":2,\"type\":\"SCALAR\"}]"},
        {.file = "missing-bin.gltf", .buffers = "[{\"byteLength\":44,\"uri\":\"nothere.bin\"}]"},
        {.file = "short-bin.gltf",
         .buffers = "[{\"byteLength\":4400,\"uri\":\"data:application/octet-stream;base64,AAAA\"}]"},
        {.file = "extension-required.gltf",
         .extra = "\"extensionsUsed\":[\"KHR_texture_basisu\"],"
                  "\"extensionsRequired\":[\"KHR_texture_basisu\"]"},
        {.file = "bad-yfov.gltf", .scenes = "\"scenes\":[{\"nodes\":[0,1]}]", .nodes = "[{\"mesh\":0},{\"camera\":0}]",
         .extra = "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":4,\"znear\":0.1}}]"},
        {.file = "camera-missing.gltf", .scenes = "\"scenes\":[{\"nodes\":[0,1]}]",
         .nodes = "[{\"mesh\":0},{\"camera\":2}]"},
        {.file = "texture-missing.gltf",
         .meshes = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"material\":0}]}]",
         .extra = "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":4}}}]"},
    };
    const char *problems[] = {
        "no triangles",
        "no triangles",
        "node graph has a cycle (node 0 is its own ancestor)",
        "node graph has a cycle",
        "node 2 has two parents",
        "child 7 does not exist",
        "mesh 3 does not exist",
        "node 3 does not exist",
        "default scene 5 does not exist",
        "lists node 1 as a root, but it is a child of node 0",
        "matrix has 3 numbers, expected 16",
        "rotation quaternion has zero",
        "POSITION accessor 9 does not exist",
        "accessor out of bounds",
        "material 5 does not exist",
        "no POSITION attribute",
        "POSITION accessor 0 is float VEC2; expected float VEC3",
        "POSITION accessor 0 is unsigned short VEC3; expected float VEC3",
        "indices accessor 1 is float SCALAR",
        "TEXCOORD_0 accessor 2 is unsigned byte VEC2; expected float or normalized",
        "NORMAL has 2 elements but POSITION has 3",
        "exceeds bufferView 0",
        "exceeds bufferView 0",
        "exceeds bufferView 0",
        "exceeds buffer 0",
        "buffer 3 does not exist",
        "bufferView 5 does not exist",
        "has no bufferView",
        "byteStride 8 is smaller",
        "POSITION accessor 0: sparse indices are float; expected unsigned byte/short/int",
        "2 indices is not a whole number of triangles",
        "nothere.bin",
        "cannot load glTF",
        "requires the glTF extension KHR_texture_basisu (Basis Universal textures), which gtlab does not support",
        "yfov 4 is not in (0, pi)",
        "camera 2 does not exist",
        "texture 4 does not exist",
    };
    _Static_assert(sizeof cases / sizeof cases[0] == sizeof problems / sizeof problems[0], "one problem per case");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        expect_error(write_crafted(&cases[i]), problems[i]);

    /* The points-only file also says why its primitive was dropped. */
    expect_error(write_crafted(&cases[0]), "no triangles");
    CHECK(strstr(printed, "mode 0 (points) is not triangles; skipped") != NULL);

    triangle_buffer nan_buffer = good_buffer;
    nan_buffer.positions[4] = NAN;
    crafted nan_case = {.file = "nan-position.gltf", .buffer = &nan_buffer};
    expect_error(write_crafted(&nan_case), "POSITION 1 is not finite");

    triangle_buffer far_index = good_buffer;
    far_index.indices[2] = 7;
    crafted index_case = {.file = "index-out-of-range.gltf", .buffer = &far_index};
    expect_error(write_crafted(&index_case), "index 7 (entry 2) is out of range (3 vertices)");

    const char *invalid = tmp_path("invalid-json.gltf");
    const char text[] = "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [";
    CHECK(write_bytes(invalid, text, sizeof text - 1) == 0);
    expect_error(invalid, "JSON text ends early: an array or object is not closed at line 1, column 41");

    const char *not_array = tmp_path("scenes-not-objects.gltf");
    const char text2[] = "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[1,2]}";
    CHECK(write_bytes(not_array, text2, sizeof text2 - 1) == 0);
    expect_error(not_array, "cannot load glTF");

    const char *empty = tmp_path("empty.gltf");
    CHECK(write_bytes(empty, "", 0) == 0);
    expect_error(empty, "JSON text ends where a value was expected");

    expect_error(tmp_path("does-not-exist.gltf"), "cannot open");
    expect_error(check_tmp_dir(), "is a directory, not a regular file");
}

static void check_crafted_warnings(void)
{
    scene s;
    crafted mixed = {.file = "points-and-triangles.gltf",
                     .meshes = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"mode\":0},"
                               "{\"attributes\":{\"POSITION\":0},\"indices\":1}]}]"};
    if (expect_warning(write_crafted(&mixed), "mode 0 (points) is not triangles; skipped", &s) == 0) {
        CHECK(s.mesh_count == 1 && scene_triangle_count(&s) == 1);
        scene_free(&s);
    }

    /* A texture whose image file is missing, or whose bytes are not an image:
     * the material keeps its factor and renders without the texture. */
    const char *images[] = {"[{\"uri\":\"missing.png\"}]",
                            "[{\"uri\":\"data:image/png;base64,AAAAAAAAAAAAAAAAAAAAAAAA\"}]"};
    const char *warnings[] = {"image 0 (missing.png) could not be read", "cannot be decoded"};
    for (int i = 0; i < 2; ++i) {
        char extra[512];
        snprintf(extra, sizeof extra,
                 "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.5,0.25,0.125,1],"
                 "\"baseColorTexture\":{\"index\":0}}}],\"textures\":[{\"source\":0}],\"images\":%s",
                 images[i]);
        crafted textured = {
            .file = i == 0 ? "texture-file-missing.gltf" : "texture-undecodable.gltf",
            .meshes = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"material\":0}]}]",
            .extra = extra};
        if (expect_warning(write_crafted(&textured), warnings[i], &s) != 0)
            continue;
        CHECK(s.material_count == 1 && s.texture_count == 0);
        if (s.material_count == 1) {
            CHECK(s.materials[0].base_color_texture == -1);
            CHECK(s.materials[0].base_color[0] == 0.5f && s.materials[0].base_color[1] == 0.25f &&
                  s.materials[0].base_color[2] == 0.125f);
        }
        scene_free(&s);
    }

    /* A zero scale flattens the mesh: the inverse transpose does not exist. */
    crafted flat = {.file = "zero-scale.gltf",
                    .nodes = "[{\"mesh\":0,\"scale\":[1,1,0]}]",
                    .meshes = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":0},\"indices\":1}]}]"};
    if (expect_warning(write_crafted(&flat), "singular", &s) == 0) {
        CHECK_NEAR(s.meshes[0].normals[2], 1.0, 1e-6); /* the triangle lies in z = 0 */
        scene_free(&s);
    }
}

/* Binary glTF: every truncation of a valid .glb is an error, content decides
 * the format over the extension, and extents inside the GLB are checked. */
static void check_glb(void)
{
    crafted base = {.file = "good.glb"};
    size_t size;
    unsigned char *glb = crafted_glb(&base, &size);
    scene s;
    if (expect_clean_load(write_crafted_glb(&base), &s) == 0) {
        CHECK(scene_triangle_count(&s) == 1);
        scene_free(&s);
    }
    const char *as_gltf = tmp_path("glb-content.gltf");
    CHECK(write_bytes(as_gltf, glb, size) == 0);
    if (expect_clean_load(as_gltf, &s) == 0)
        scene_free(&s);

    char path[4096];
    snprintf(path, sizeof path, "%s", tmp_path("truncated.glb"));
    int all_failed = 1;
    for (size_t length = 0; length < size; ++length) {
        CHECK(write_bytes(path, glb, length) == 0);
        gt_error e = {{0}};
        int rc = load_capturing(path, &s, &e, printed, sizeof printed);
        if (rc == 0) {
            scene_free(&s);
            all_failed = 0;
            fprintf(stderr, "truncated to %zu of %zu bytes: loaded\n", length, size);
        }
        CHECK(strncmp(e.message, path, strlen(path)) == 0);
        CHECK(printed[0] == '\0');
    }
    CHECK(all_failed);
    expect_error(path, "bytes but the file has"); /* the last one, one byte short: "(truncated?)" */
    free(glb);

    const char *json_as_glb = tmp_path("json.glb");
    const char text[] = "{\"asset\":{\"version\":\"2.0\"}}";
    CHECK(write_bytes(json_as_glb, text, sizeof text - 1) == 0);
    expect_error(json_as_glb, "not a binary glTF");

    crafted image_outside = {.file = "image-outside.glb",
                             .views = "[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},"
                                      "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6},"
                                      "{\"buffer\":0,\"byteOffset\":40,\"byteLength\":1000}]",
                             .extra = "\"images\":[{\"bufferView\":2,\"mimeType\":\"image/png\"}]"};
    expect_error(write_crafted_glb(&image_outside), "bufferView 2 lies outside its buffer");

    crafted empty_buffer = {.file = "empty-buffer.glb", .buffers = "[{\"byteLength\":0}]"};
    expect_error(write_crafted_glb(&empty_buffer), "malformed data");

    crafted too_long = {.file = "buffer-longer-than-bin.glb", .buffers = "[{\"byteLength\":4000}]"};
    expect_error(write_crafted_glb(&too_long), "cannot load binary glTF");
}

/* The decoders of issue 30 on broken data: meshopt views and Draco
 * primitives, morph weights, skins, and a required extension named before a
 * broken accessor. */
#define MESHOPT_VIEW(ext) "[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36,\"extensions\":{\"EXT_meshopt_compression\":" ext "}}," \
                          "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6}]"
#define DRACO_MESH(ext) "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"extensions\":{\"KHR_draco_mesh_compression\":" ext "}}]}]"

static void check_decoder_errors(void)
{
    const crafted cases[] = {
        {.file = "meshopt-mode.gltf",
         .views = MESHOPT_VIEW("{\"buffer\":0,\"byteLength\":36,\"byteStride\":12,\"count\":3,\"mode\":\"FOO\"}")},
        {.file = "meshopt-stride.gltf",
         .views = MESHOPT_VIEW("{\"buffer\":0,\"byteLength\":36,\"byteStride\":6,\"count\":3,\"mode\":\"ATTRIBUTES\"}")},
        {.file = "meshopt-garbage.gltf",
         .views = MESHOPT_VIEW("{\"buffer\":0,\"byteLength\":36,\"byteStride\":12,\"count\":3,\"mode\":\"ATTRIBUTES\"}")},
        {.file = "meshopt-range.gltf",
         .views = MESHOPT_VIEW("{\"buffer\":0,\"byteOffset\":40,\"byteLength\":36,\"byteStride\":12,\"count\":3,"
                               "\"mode\":\"ATTRIBUTES\"}")},
        {.file = "meshopt-filter.gltf",
         .views = MESHOPT_VIEW("{\"buffer\":0,\"byteLength\":36,\"byteStride\":12,\"count\":3,\"mode\":\"ATTRIBUTES\","
                               "\"filter\":\"QUATERNION\"}")},
        {.file = "draco-garbage.gltf", .meshes = DRACO_MESH("{\"bufferView\":0,\"attributes\":{\"POSITION\":0}}")},
        {.file = "draco-view.gltf", .meshes = DRACO_MESH("{\"bufferView\":9,\"attributes\":{\"POSITION\":0}}")},
        {.file = "draco-skin.gltf", .meshes = DRACO_MESH("{\"bufferView\":0,\"attributes\":{\"POSITION\":0}}"),
         .nodes = "[{\"mesh\":0,\"skin\":0}]", .extra = "\"skins\":[{\"joints\":[0]}]"},
        {.file = "morph-weights.gltf",
         .meshes = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"targets\":[{\"POSITION\":0}]}],"
                   "\"weights\":[1,1]}]"},
        {.file = "skin-missing.gltf", .nodes = "[{\"mesh\":0,\"skin\":3}]"},
        {.file = "required-first.gltf", .extra = "\"extensionsRequired\":[\"EXT_texture_webp\"]",
         .accessors = "[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
                      "{\"bufferView\":77,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}]"},
    };
    const char *problems[] = {
        "bufferView 0: EXT_meshopt_compression: unknown mode \"FOO\"",
        "bufferView 0: EXT_meshopt_compression: ATTRIBUTES byteStride 6 is not a multiple of 4",
        "bufferView 0: EXT_meshopt_compression: ATTRIBUTES data does not decode",
        "bufferView 0: EXT_meshopt_compression: bytes 40 + 36 exceed buffer 0",
        "bufferView 0: EXT_meshopt_compression: filter QUATERNION with byteStride 12",
        "mesh 0 primitive 0: KHR_draco_mesh_compression: the Draco data does not decode",
        "mesh 0 primitive 0: KHR_draco_mesh_compression: bufferView 9 does not exist",
        "mesh 0 primitive 0: KHR_draco_mesh_compression with a skin is not supported",
        "mesh 0 primitive 0: 2 morph weights for 1 morph targets",
        "mesh 0 primitive 0: skin 3 does not exist",
        "requires the glTF extension EXT_texture_webp (WebP textures), which gtlab does not support",
    };
    _Static_assert(sizeof cases / sizeof cases[0] == sizeof problems / sizeof problems[0], "one problem per case");
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        expect_error(write_crafted(&cases[i]), problems[i]);
}

int main(void)
{
    struct stat st;
    if (stat(ASSIMP, &st) == 0) {
        check_assimp_broken_files();
        check_assimp_good_files();
        check_assimp_wrong_types();
    } else {
        printf("test_gltf_bad_input: %s not installed (Debian package assimp-testmodels); those cases skipped\n",
               ASSIMP);
    }
    check_crafted_errors();
    check_decoder_errors();
    check_crafted_warnings();
    check_glb();
    return check_report("test_gltf_bad_input");
}
