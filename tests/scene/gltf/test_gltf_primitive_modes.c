/* Triangle strips and fans (glTF 2.0, "Primitive topology";
 * scene/gltf/primitive_topology.h):
 *  - the triangulation itself: counts n - 2, the spec's corner formulas
 *    written out by hand for n = 5, and every triangle of a zig-zag strip and
 *    of a convex fan in the z = 0 plane facing +z like the first (the strip's
 *    alternating corner order keeps the winding);
 *  - the glTF Asset Generator's Mesh_PrimitiveMode files (assimp-testmodels):
 *    strips 04 (no indices) and 11 (indices [0, 3, 1, 2]) load to the same
 *    triangles, bit for bit, as their TRIANGLES counterparts 06 and 13 (each
 *    triangle up to a rotation of its corners, which keeps its winding); the
 *    fans 05 and 12 split the same square along the other diagonal, so their
 *    triangles are checked against the fan formula and their face normals
 *    bit for bit against the list's; and all four render the same AO image,
 *    bit for bit, as their counterparts (same camera, same seed). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "ao/ao_quantity.h"
#include "raytracer/reference_render.h"
#include "scene/gltf/gltf_reader.h"
#include "scene/gltf/primitive_topology.h"
#include "tests/check.h"

#define MODES "/usr/share/assimp/models/glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_"

static void check_hand_expansion(void)
{
    const uint32_t v[5] = {10, 11, 12, 13, 14};
    const uint32_t strip[9] = {10, 11, 12, 11, 13, 12, 12, 13, 14};
    const uint32_t fan[9] = {11, 12, 10, 12, 13, 10, 13, 14, 10};
    uint32_t out[9];
    CHECK(gltf_mode_triangle_count(GLTF_MODE_TRIANGLE_STRIP, 5) == 3);
    CHECK(gltf_mode_triangle_count(GLTF_MODE_TRIANGLE_FAN, 2) == 0);
    CHECK(gltf_mode_triangle_count(GLTF_MODE_TRIANGLES, 9) == 3);
    CHECK(!gltf_mode_has_triangles(3) && gltf_mode_has_triangles(6));
    gltf_triangulate(GLTF_MODE_TRIANGLE_STRIP, 5, v, out);
    CHECK(memcmp(out, strip, sizeof strip) == 0);
    gltf_triangulate(GLTF_MODE_TRIANGLE_FAN, 5, v, out);
    CHECK(memcmp(out, fan, sizeof fan) == 0);
}

/* z of (b - a) x (c - a) for 2D points. */
static double cross_z(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static void check_windings(int mode, const double (*p)[2], size_t n)
{
    uint32_t seq[16], tri[3 * 16];
    for (size_t i = 0; i < n; ++i)
        seq[i] = (uint32_t)i;
    gltf_triangulate(mode, n, seq, tri);
    for (size_t t = 0; t < n - 2; ++t)
        CHECK_MSG(cross_z(p[tri[3 * t]], p[tri[3 * t + 1]], p[tri[3 * t + 2]]) > 0.0, "mode %d triangle %zu", mode, t);
}

static void check_triangulation(void)
{
    check_hand_expansion();
    double zigzag[9][2], polygon[9][2];
    for (int i = 0; i < 9; ++i) {
        zigzag[i][0] = 0.5 * i, zigzag[i][1] = i % 2 ? 0.0 : 1.0; /* first triangle counter-clockwise */
        polygon[i][0] = cos(0.6 * i), polygon[i][1] = sin(0.6 * i); /* convex, counter-clockwise */
    }
    check_windings(GLTF_MODE_TRIANGLE_STRIP, (const double (*)[2])zigzag, 9);
    check_windings(GLTF_MODE_TRIANGLE_FAN, (const double (*)[2])polygon, 9);
}

/* ------------------------------------------------ the Asset Generator files */

typedef struct {
    float v[3][3], n[3];
} triangle;

static int compare_bytes(const void *a, const void *b, size_t size) { return memcmp(a, b, size); }
static int compare_vertex(const void *a, const void *b) { return compare_bytes(a, b, 3 * sizeof(float)); }
static int compare_triangle(const void *a, const void *b) { return compare_bytes(a, b, sizeof(triangle)); }

/* The loaded file's triangles (one mesh, flat-shaded), each rotated to start
 * at its smallest corner, sorted. Returns the count (<= max). */
static size_t canonical_triangles(const scene *s, triangle *out, size_t max)
{
    size_t count = 0;
    for (int i = 0; i < s->mesh_count; ++i) {
        const scene_mesh *m = &s->meshes[i];
        for (uint32_t t = 0; t < m->triangle_count && count < max; ++t, ++count) {
            int first = 0;
            for (int k = 1; k < 3; ++k)
                if (compare_vertex(&m->positions[3 * m->indices[3 * t + k]], &m->positions[3 * m->indices[3 * t + first]]) < 0)
                    first = k;
            for (int k = 0; k < 3; ++k)
                memcpy(out[count].v[k], &m->positions[3 * m->indices[3 * t + (first + k) % 3]], sizeof out[count].v[k]);
            memcpy(out[count].n, &m->normals[3 * m->indices[3 * t]], sizeof out[count].n);
        }
    }
    qsort(out, count, sizeof *out, compare_triangle);
    return count;
}

static int load(const char *number, scene *s)
{
    char path[512];
    snprintf(path, sizeof path, MODES "%s.gltf", number);
    gt_error e;
    const int rc = gltf_load(path, s, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    return rc;
}

static int render_ao(const scene *s, const camera *cam, image *out)
{
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = 4, .seed = 11, .threads = 2},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    gt_error e;
    return reference_render(s, "test", cam, &req, out, &stats, &e);
}

static void check_same_ao(const scene *a, const scene *b, const char *what)
{
    vec3 lo, hi;
    scene_bounds(b, &lo, &hi);
    camera cam = camera_auto_framing(lo, hi, 24, 24);
    image ia, ib;
    CHECK(render_ao(a, &cam, &ia) == 0 && render_ao(b, &cam, &ib) == 0);
    const float *va = image_channel_data(&ia, "ao.V"), *vb = image_channel_data(&ib, "ao.V");
    CHECK_MSG(va && vb && memcmp(va, vb, sizeof(float) * 24 * 24) == 0, "%s: AO differs", what);
    image_free(&ia);
    image_free(&ib);
}

/* A strip against its list: the same triangles bit for bit, and the same AO. */
static void check_strip(const char *strip, const char *list)
{
    scene s, l;
    if (load(strip, &s) != 0 || load(list, &l) != 0)
        return;
    triangle ts[8], tl[8];
    const size_t ns = canonical_triangles(&s, ts, 8), nl = canonical_triangles(&l, tl, 8);
    CHECK_MSG(ns == 2 && nl == 2 && memcmp(ts, tl, sizeof(triangle) * 2) == 0, "strip %s vs list %s", strip, list);
    check_same_ao(&s, &l, strip);
    scene_free(&s);
    scene_free(&l);
}

/* A fan against its list: the fan formula's triangles of the square's
 * corners a, b, c, d in sequence order, the list's face normal, the same AO. */
static void check_fan(const char *fan, const char *list, const float corners[4][3])
{
    scene f, l;
    if (load(fan, &f) != 0 || load(list, &l) != 0)
        return;
    CHECK(f.mesh_count == 1 && f.meshes[0].triangle_count == 2);
    const scene_mesh *m = &f.meshes[0];
    const int expected[2][3] = {{1, 2, 0}, {2, 3, 0}}; /* p_i = {v_i+1, v_i+2, v_0} */
    for (int t = 0; t < 2 && m->triangle_count == 2; ++t)
        for (int k = 0; k < 3; ++k) {
            CHECK(memcmp(&m->positions[3 * m->indices[3 * t + k]], corners[expected[t][k]], 12) == 0);
            CHECK(memcmp(&m->normals[3 * m->indices[3 * t + k]], &l.meshes[0].normals[0], 12) == 0);
        }
    check_same_ao(&f, &l, fan);
    scene_free(&f);
    scene_free(&l);
}

static void check_asset_generator(void)
{
    struct stat st;
    if (stat(MODES "04.gltf", &st) != 0) {
        printf("test_gltf_primitive_modes: %s not installed (Debian package assimp-testmodels); skipped\n", MODES);
        return;
    }
    check_strip("04", "06");
    check_strip("11", "13");
    /* 05 stores its vertices in fan order; 12 indexes [0, 3, 2, 1] of its four. */
    const float fan05[4][3] = {{0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}, {-0.5f, -0.5f, 0}};
    const float fan12[4][3] = {{0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}, {-0.5f, -0.5f, 0}};
    check_fan("05", "06", fan05);
    check_fan("12", "13", fan12);
}

int main(void)
{
    check_triangulation();
    check_asset_generator();
    return check_report("test_gltf_primitive_modes");
}
