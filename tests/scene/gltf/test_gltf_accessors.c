/* Accessor decoding against the glTF 2.0 formulas, on a file crafted here:
 *  - KHR_mesh_quantization: POSITION as short integers (not normalized: the
 *    value itself), NORMAL as normalized bytes (f = max(c / 127, -1), so -128
 *    and -127 both give -1), with the node's scale and translation carrying
 *    the dequantization: world = 0.5 p + (1, 0, 0);
 *  - sparse accessors: POSITION's element 1 replaced by sparse values, and
 *    TEXCOORD_0 without a bufferView (zeros) but for a sparse element 2;
 *  - the same file without KHR_mesh_quantization in extensionsUsed is
 *    refused, naming the extension;
 *  - KHR_texture_transform, on the extension's own example (offset [0, 1],
 *    rotation pi/2, scale [0.5, 0.5]: the lower-left quadrant of the image,
 *    rotated): uv (u, v) -> (v / 2, 1 - u / 2), baked into TEXCOORD_0. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltf_test_files.h"
#include "scene/gltf/accessor_decode.h"
#include "scene/gltf/gltf_reader.h"
#include "tests/check.h"

typedef struct {
    int16_t positions[3][4];  /* VEC3 short, byteStride 8 */
    int8_t normals[3][4];     /* VEC3 normalized byte, byteStride 4 */
    uint8_t sparse_index[4];  /* [1] */
    int16_t sparse_position[4];
    uint8_t sparse_uv_index[4]; /* [2] */
    float sparse_uv[2];
} buffer_layout;

static const buffer_layout data = {
    {{-300, 7, 32767, 0}, {1, 2, 3, 0}, {-32768, 0, 5, 0}},
    {{-128, 0, 0, 0}, {0, 127, 0, 0}, {0, 64, -64, 0}},
    {1, 0, 0, 0}, {10, -20, 30, 0}, {2, 0, 0, 0}, {0.25f, 0.75f}};

/* A 1x1 PNG texture with the spec's example transform. */
static const char textured[] =
    "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0,\"extensions\":"
    "{\"KHR_texture_transform\":{\"offset\":[0,1],\"rotation\":1.57079632679,\"scale\":[0.5,0.5]}}}}}],"
    "\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAf"
    "FcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg==\"}],";

static const char *write_file(const char *name, const char *extensions)
{
    char *uri = data_uri(&data, sizeof data);
    char json[8192];
    snprintf(json, sizeof json,
             "{\"asset\":{\"version\":\"2.0\"},%s\"scenes\":[{\"nodes\":[0]}],"
             "\"nodes\":[{\"mesh\":0,\"scale\":[0.5,0.5,0.5],\"translation\":[1,0,0]}],"
             "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2}%s}]}],"
             "\"buffers\":[{\"byteLength\":%zu,\"uri\":\"%s\"}],"
             "\"bufferViews\":[{\"buffer\":0,\"byteLength\":24,\"byteStride\":8},"
             "{\"buffer\":0,\"byteOffset\":24,\"byteLength\":12,\"byteStride\":4},"
             "{\"buffer\":0,\"byteOffset\":36,\"byteLength\":1},{\"buffer\":0,\"byteOffset\":40,\"byteLength\":6},"
             "{\"buffer\":0,\"byteOffset\":48,\"byteLength\":1},{\"buffer\":0,\"byteOffset\":52,\"byteLength\":8}],"
             "\"accessors\":[{\"bufferView\":0,\"componentType\":5122,\"count\":3,\"type\":\"VEC3\","
             "\"sparse\":{\"count\":1,\"indices\":{\"bufferView\":2,\"componentType\":5121},\"values\":{\"bufferView\":3}}},"
             "{\"bufferView\":1,\"componentType\":5120,\"normalized\":true,\"count\":3,\"type\":\"VEC3\"},"
             "{\"componentType\":5126,\"count\":3,\"type\":\"VEC2\","
             "\"sparse\":{\"count\":1,\"indices\":{\"bufferView\":4,\"componentType\":5121},\"values\":{\"bufferView\":5}}}]}",
             extensions, strstr(extensions, "KHR_texture_transform") ? ",\"material\":0" : "", sizeof data, uri);
    free(uri);
    const char *path = tmp_path(name);
    CHECK(write_bytes(path, json, strlen(json)) == 0);
    return path;
}

static void check_formulas(void)
{
    const unsigned char b[2] = {0x80, 0x81}; /* -128, -127 */
    CHECK(gltf_component_float(b, 0, GLTF_BYTE, 1) == -1.0f && gltf_component_float(b, 1, GLTF_BYTE, 1) == -1.0f);
    const int16_t s = -32767;
    CHECK(gltf_component_float((const unsigned char *)&s, 0, GLTF_SHORT, 1) == -1.0f);
    CHECK(gltf_component_float((const unsigned char *)&s, 0, GLTF_SHORT, 0) == -32767.0f);
    const uint16_t u = 65535;
    CHECK(gltf_component_float((const unsigned char *)&u, 0, GLTF_UNSIGNED_SHORT, 1) == 1.0f);
    CHECK(gltf_component_float((const unsigned char *)&u, 0, GLTF_UNSIGNED_SHORT, 0) == 65535.0f);
}

static void check_loaded(const scene *s)
{
    const int16_t p[3][3] = {{-300, 7, 32767}, {10, -20, 30}, {-32768, 0, 5}};
    const float n[3][3] = {{-1, 0, 0}, {0, 1, 0}, {0, 0.70710678f, -0.70710678f}};
    CHECK(s->mesh_count == 1 && s->meshes[0].vertex_count == 3 && s->meshes[0].texcoords);
    if (s->mesh_count != 1 || s->meshes[0].vertex_count != 3 || !s->meshes[0].texcoords)
        return;
    const scene_mesh *m = &s->meshes[0];
    for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k) {
            CHECK(m->positions[3 * v + k] == 0.5f * p[v][k] + (k == 0 ? 1.0f : 0.0f));
            CHECK_NEAR(m->normals[3 * v + k], n[v][k], 1e-6);
        }
    const float uv[6] = {0, 0, 0, 0, 0.25f, 0.75f};
    CHECK(memcmp(m->texcoords, uv, sizeof uv) == 0);
}

static void check_texture_transform(void)
{
    char extensions[2048];
    snprintf(extensions, sizeof extensions, "\"extensionsUsed\":[\"KHR_mesh_quantization\",\"KHR_texture_transform\"],%s",
             textured);
    scene s;
    gt_error e;
    CHECK_MSG(gltf_load(write_file("texture_transform.gltf", extensions), &s, &e) == 0, "%s", e.message);
    const float uv[6] = {0, 1, 0, 1, 0.375f, 0.875f};
    for (int i = 0; i < 6 && s.mesh_count == 1; ++i)
        CHECK_NEAR(s.meshes[0].texcoords[i], uv[i], 1e-7);
    scene_free(&s);
}

int main(void)
{
    check_texture_transform();
    check_formulas();
    scene s;
    gltf_report r;
    gt_error e;
    const char *good = write_file("quantized_sparse.gltf", "\"extensionsUsed\":[\"KHR_mesh_quantization\"],"
                                                           "\"extensionsRequired\":[\"KHR_mesh_quantization\"],");
    CHECK_MSG(gltf_load_report(good, &s, &r, &e) == 0, "%s", e.message);
    check_loaded(&s);
    CHECK(r.quantized_primitives == 1 && r.sparse_accessors == 2 && r.primitives_by_mode[4] == 1);
    scene_free(&s);
    const char *undeclared = write_file("quantized_undeclared.gltf", "");
    CHECK(gltf_load(undeclared, &s, &e) != 0);
    CHECK_MSG(strstr(e.message, "POSITION accessor 0 is short VEC3; expected float VEC3 (KHR_mesh_quantization"),
              "%s", e.message);
    return check_report("test_gltf_accessors");
}
