/* The loader against hand-written .gltf files (JSON text, buffer as a data:
 * URI), with every expected value derived here by hand:
 *
 *   node 0: translation (1,2,3), rotation 90 deg about +Z, scale (sx,3,4)
 *     node 1 (child): matrix = translate(0.5,-1,2) * rotX(90 deg) * diag(1,0.5,1), mesh 0
 *   node 2: translation (0,1,5)
 *     node 3 (child): rotation 90 deg about +Y, camera 0
 *   node 4: translation (100,0,0), mesh 0 (only in scene 0, not the default)
 *
 * Rz90 (x,y,z) = (-y,x,z) and RotX90 (x,y,z) = (x,-z,y), so a local point p
 * lands at q = (0.5 + p.x, -1 - p.z, 2 + 0.5 p.y) under node 1 and at
 * (1 - 3 q.y, 2 + sx q.x, 3 + 4 q.z) in the world. Normals go by the inverse
 * transpose, which for rotations R and diagonals D is R and D^-1:
 * n' ~ Rz(S^-1 RotX(D^-1 n)). With sx = -2 the transform mirrors and the
 * triangle's winding must flip so that its geometric normal stays on the side
 * of the shading normal. The same triangle is stored with u8, u16, u32 and no
 * indices, with interleaved (byteStride 24) or separate attributes, and with
 * float, normalized u8 (byteStride 4) and normalized u16 texture coordinates. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../check.h"
#include "gltf_test_files.h"
#include "scene/gltf/gltf_reader.h"

enum { NONE = 0, U8 = 5121, U16 = 5123, U32 = 5125, F32 = 5126 };

typedef struct {
    const char *file;
    int index_type;    /* NONE, U8, U16, U32 */
    int interleaved;   /* POSITION and NORMAL in one bufferView, byteStride 24 */
    int texcoord_type; /* NONE, U8 or U16 (normalized), F32 */
    float sx;          /* node 0's x scale: 2, or -2 to mirror */
    int no_scenes;     /* omit "scenes": all root nodes are loaded */
} variant;

static const float local_p[3][3] = {{0.2f, -0.3f, 0.5f}, {1.1f, 0.4f, -0.2f}, {-0.5f, 0.9f, 0.3f}};
static const unsigned texcoord_u8[3][2] = {{0, 255}, {128, 64}, {255, 0}};
static const unsigned texcoord_u16[3][2] = {{0, 65535}, {32768, 16384}, {65535, 0}};
/* Corner k of the triangle is vertex corner_vertex[k]; indexed files store the
 * vertices in order with indices (2, 0, 1), the non-indexed file stores them
 * already in corner order. */
static const int corner_vertex[3] = {2, 0, 1};

static vec3 face_normal(void)
{
    vec3 a = v3_load(local_p[0]), b = v3_load(local_p[1]), c = v3_load(local_p[2]);
    return v3_normalize(v3_cross(v3_sub(b, a), v3_sub(c, a)));
}

static vec3 expected_world(vec3 p, float sx)
{
    vec3 q = v3(0.5f + p.x, -1.0f - p.z, 2.0f + 0.5f * p.y);
    return v3(1.0f - 3.0f * q.y, 2.0f + sx * q.x, 3.0f + 4.0f * q.z);
}

static vec3 expected_normal(vec3 n, float sx)
{
    vec3 a = v3(n.x, n.y / 0.5f, n.z);       /* D^-1 */
    vec3 b = v3(a.x, -a.z, a.y);             /* RotX90 */
    vec3 c = v3(b.x / sx, b.y / 3.0f, b.z / 4.0f); /* S^-1 */
    return v3_normalize(v3(-c.y, c.x, c.z)); /* Rz90 */
}

static float expected_texcoord(int type, int vertex, int k)
{
    if (type == U8)
        return texcoord_u8[vertex][k] / 255.0f;
    if (type == U16)
        return texcoord_u16[vertex][k] / 65535.0f;
    return (float)texcoord_u8[vertex][k] / 255.0f; /* F32 stores the same values */
}

static void appendf(char *buf, size_t cap, const char *fmt, ...)
{
    size_t used = strlen(buf);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf + used, cap - used, fmt, ap);
    va_end(ap);
}

/* Writes the variant's .gltf; returns its path (static buffer). */
static const char *write_variant(const variant *v)
{
    unsigned char bin[256] = {0};
    size_t size = 0;
    char views[1024] = "", accessors[1024] = "";
    int view_count = 0;
    int order[3] = {0, 1, 2};
    if (v->index_type == NONE)
        memcpy(order, corner_vertex, sizeof order);
    const vec3 n = face_normal();
    const float normal[3] = {n.x, n.y, n.z};

    /* POSITION and NORMAL */
    if (v->interleaved) {
        for (int i = 0; i < 3; ++i) {
            memcpy(bin + 24 * i, local_p[order[i]], 12);
            memcpy(bin + 24 * i + 12, normal, 12);
        }
        appendf(views, sizeof views, "{\"buffer\":0,\"byteOffset\":0,\"byteLength\":72,\"byteStride\":24}");
        appendf(accessors, sizeof accessors,
                "{\"bufferView\":0,\"byteOffset\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
                "{\"bufferView\":0,\"byteOffset\":12,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}");
        view_count = 1;
    } else {
        for (int i = 0; i < 3; ++i) {
            memcpy(bin + 12 * i, local_p[order[i]], 12);
            memcpy(bin + 36 + 12 * i, normal, 12);
        }
        appendf(views, sizeof views,
                "{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36,\"byteLength\":36}");
        appendf(accessors, sizeof accessors,
                "{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
                "{\"bufferView\":1,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}");
        view_count = 2;
    }
    size = 72;
    int next_accessor = 2;

    char texcoord_attribute[64] = "";
    if (v->texcoord_type != NONE) {
        size_t stride = v->texcoord_type == U8 ? 4 : v->texcoord_type == U16 ? 4 : 8;
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 2; ++k) {
                unsigned char *at = bin + size + stride * (size_t)i;
                int vertex = order[i];
                if (v->texcoord_type == U8) {
                    at[k] = (unsigned char)texcoord_u8[vertex][k];
                } else if (v->texcoord_type == U16) {
                    unsigned short u = (unsigned short)texcoord_u16[vertex][k];
                    memcpy(at + 2 * k, &u, 2);
                } else {
                    float f = texcoord_u8[vertex][k] / 255.0f;
                    memcpy(at + 4 * k, &f, 4);
                }
            }
        appendf(views, sizeof views, ",{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu%s}", size, 3 * stride,
                v->texcoord_type == U8 ? ",\"byteStride\":4" : "");
        appendf(accessors, sizeof accessors,
                ",{\"bufferView\":%d,\"componentType\":%d,\"count\":3,\"type\":\"VEC2\"%s}", view_count,
                v->texcoord_type, v->texcoord_type == F32 ? "" : ",\"normalized\":true");
        snprintf(texcoord_attribute, sizeof texcoord_attribute, ",\"TEXCOORD_0\":%d", next_accessor++);
        view_count++;
        size += 3 * stride;
    }

    char indices[32] = "";
    if (v->index_type != NONE) {
        size_t width = v->index_type == U8 ? 1 : v->index_type == U16 ? 2 : 4;
        for (int k = 0; k < 3; ++k) {
            unsigned value = (unsigned)corner_vertex[k];
            memcpy(bin + size + width * (size_t)k, &value, width); /* little-endian host */
        }
        appendf(views, sizeof views, ",{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu}", size, 3 * width);
        appendf(accessors, sizeof accessors,
                ",{\"bufferView\":%d,\"componentType\":%d,\"count\":3,\"type\":\"SCALAR\"}", view_count,
                v->index_type);
        snprintf(indices, sizeof indices, ",\"indices\":%d", next_accessor++);
        size += 3 * width;
    }

    char *uri = data_uri(bin, size);
    size_t cap = strlen(uri) + 8192;
    char *json = calloc(1, cap);
    const char *s = "0.70710678118654752";
    appendf(json, cap, "{\"asset\":{\"version\":\"2.0\"},");
    if (!v->no_scenes)
        appendf(json, cap, "\"scene\":1,\"scenes\":[{\"nodes\":[4]},{\"nodes\":[0,2]}],");
    appendf(json, cap,
            "\"nodes\":["
            "{\"translation\":[1,2,3],\"rotation\":[0,0,%s,%s],\"scale\":[%g,3,4],\"children\":[1]},"
            "{\"matrix\":[1,0,0,0, 0,0,0.5,0, 0,-1,0,0, 0.5,-1,2,1],\"mesh\":0},"
            "{\"translation\":[0,1,5],\"children\":[3]},"
            "{\"rotation\":[0,%s,0,%s],\"camera\":0},"
            "{\"translation\":[100,0,0],\"mesh\":0}],"
            "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.5,\"aspectRatio\":1.5,\"znear\":0.1}}],"
            "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1%s}%s}]}],"
            "\"buffers\":[{\"byteLength\":%zu,\"uri\":\"%s\"}],"
            "\"bufferViews\":[%s],\"accessors\":[%s]}",
            s, s, (double)v->sx, s, s, texcoord_attribute, indices, size, uri, views, accessors);
    const char *path = tmp_path(v->file);
    CHECK(write_bytes(path, json, strlen(json)) == 0);
    free(uri);
    free(json);
    return path;
}

static void check_triangle(const variant *v)
{
    scene s;
    gt_error e = {{0}};
    char printed[4096];
    const char *path = write_variant(v);
    int rc = load_capturing(path, &s, &e, printed, sizeof printed);
    CHECK_MSG(rc == 0, "%s", e.message);
    CHECK_MSG(printed[0] == '\0', "%s printed: %s", v->file, printed);
    if (rc != 0)
        return;
    CHECK(s.mesh_count == (v->no_scenes ? 2 : 1));
    const scene_mesh *m = &s.meshes[0];
    CHECK(m->triangle_count == 1 && m->vertex_count == 3);
    if (m->triangle_count != 1 || m->vertex_count != 3) {
        scene_free(&s);
        return;
    }
    vec3 n_expected = expected_normal(face_normal(), v->sx);
    vec3 w[3];
    /* A mirrored transform swaps corners 1 and 2 (and nothing else). */
    const int mirrored = v->sx < 0.0f;
    for (int k = 0; k < 3; ++k) {
        const int source_corner = mirrored && k > 0 ? 3 - k : k;
        const int vertex = corner_vertex[source_corner];
        const uint32_t i = m->indices[k];
        w[k] = v3_load(&m->positions[3 * i]);
        vec3 expect = expected_world(v3_load(local_p[vertex]), v->sx);
        CHECK_NEAR(w[k].x, expect.x, 1e-5);
        CHECK_NEAR(w[k].y, expect.y, 1e-5);
        CHECK_NEAR(w[k].z, expect.z, 1e-5);
        vec3 n = v3_load(&m->normals[3 * i]);
        CHECK_NEAR(n.x, n_expected.x, 1e-5);
        CHECK_NEAR(n.y, n_expected.y, 1e-5);
        CHECK_NEAR(n.z, n_expected.z, 1e-5);
        CHECK((m->texcoords != NULL) == (v->texcoord_type != NONE));
        if (m->texcoords && v->texcoord_type != NONE) {
            CHECK_NEAR(m->texcoords[2 * i], expected_texcoord(v->texcoord_type, vertex, 0), 1e-6);
            CHECK_NEAR(m->texcoords[2 * i + 1], expected_texcoord(v->texcoord_type, vertex, 1), 1e-6);
        }
    }
    /* The normal stays perpendicular to the transformed triangle (what the
     * inverse transpose is for) and on the side of its geometric normal. */
    vec3 g = v3_normalize(v3_cross(v3_sub(w[1], w[0]), v3_sub(w[2], w[0])));
    CHECK_NEAR(v3_dot(g, v3_load(&m->normals[3 * m->indices[0]])), 1.0, 1e-5);

    if (v->no_scenes) /* node 4's instance of the same mesh, 100 along x */
        for (uint32_t i = 0; i < s.meshes[1].vertex_count; ++i)
            CHECK(s.meshes[1].positions[3 * i] > 98.0f && s.meshes[1].positions[3 * i] < 102.0f);

    /* Camera at node 3: origin (0,1,5); Ry90 takes local -Z to -X, +Y stays. */
    CHECK(s.has_camera);
    CHECK_NEAR(s.camera.position.x, 0.0, 1e-6);
    CHECK_NEAR(s.camera.position.y, 1.0, 1e-6);
    CHECK_NEAR(s.camera.position.z, 5.0, 1e-6);
    CHECK_NEAR(s.camera.target.x, -1.0, 1e-6);
    CHECK_NEAR(s.camera.target.y, 1.0, 1e-6);
    CHECK_NEAR(s.camera.target.z, 5.0, 1e-6);
    CHECK_NEAR(s.camera.up.x, 0.0, 1e-6);
    CHECK_NEAR(s.camera.up.y, 1.0, 1e-6);
    CHECK_NEAR(s.camera.up.z, 0.0, 1e-6);
    CHECK_NEAR(s.camera.yfov, 0.5, 1e-7);
    CHECK(s.camera.width == 512 && s.camera.height == 341); /* round(512 / 1.5) */
    scene_free(&s);
}

int main(void)
{
    const variant variants[] = {
        {"tri-u8.gltf", U8, 0, NONE, 2.0f, 0},
        {"tri-u16.gltf", U16, 0, NONE, 2.0f, 0},
        {"tri-u32.gltf", U32, 0, NONE, 2.0f, 0},
        {"tri-noindex.gltf", NONE, 0, NONE, 2.0f, 0},
        {"tri-interleaved.gltf", U16, 1, NONE, 2.0f, 0},
        {"tri-uv-float.gltf", U32, 0, F32, 2.0f, 0},
        {"tri-uv-u8.gltf", U16, 1, U8, 2.0f, 0},
        {"tri-uv-u16.gltf", NONE, 0, U16, 2.0f, 0},
        {"tri-mirrored.gltf", U16, 0, F32, -2.0f, 0},
        {"tri-mirrored-noindex.gltf", NONE, 1, NONE, -2.0f, 0},
        {"tri-no-scenes.gltf", U8, 0, NONE, 2.0f, 1},
    };
    for (size_t i = 0; i < sizeof variants / sizeof variants[0]; ++i)
        check_triangle(&variants[i]);
    return check_report("test_gltf_transforms");
}
