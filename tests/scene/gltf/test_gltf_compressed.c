/* Compressed glTF against the plain file, on assimp-testmodels'
 * 2CylinderEngine (gltf_equivalence.h for the bounds):
 *  - EXT_meshopt_compression: gltfpack -c output (binary, and text with its
 *    fallback buffer that has no uri) loads to the same vertices as
 *    gltfpack's -noq output within the quantization bound (sqrt(3) / 2) s,
 *    s the position grid step the reader reports, and renders the same AO
 *    within 4 paired standard errors plus d / f; the .glb and .gltf forms
 *    load to the same bits; -cf (fallback buffers holding the uncompressed
 *    data, the extension not required) loads to -c's bits; -cc (its own
 *    vertex order, normals octahedral-filtered) has every vertex at a
 *    position of -c's (same grid) with a normal within the two encodings'
 *    bounds of one there, and renders the same AO within the bound;
 *  - KHR_draco_mesh_compression: the Draco file of the same model against
 *    the plain .glb. Draco drops degenerate triangles and reorders vertices,
 *    so its meshes are compared by their bounding boxes (each corner within
 *    the bound), then the AO as above. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "gltf_equivalence.h"
#include "gltf_test_files.h"
#include "scene/gltf/gltf_reader.h"
#include "tests/check.h"

#define MODELS "/usr/share/assimp/models/glTF2/"
#define ENGINE MODELS "2CylinderEngine-glTF-Binary/2CylinderEngine.glb"
#define DRACO MODELS "draco/2CylinderEngine.gltf"

/* -cc stores normals octahedrally in 8-bit signed components (the filter
 * OCTAHEDRAL): the encoder rounds the octahedron's 2D coordinates (x, y) to
 * steps of 1/127, at most 1/254 each, |d(x, y)| <= sqrt(2) / 254. The decode
 * is n = v / |v|, v = (x, y, 1 - |x| - |y|) (folded below): |dv| <= sqrt(3)
 * |d(x, y)| and |v| >= 1 / sqrt(3), so |dn| <= |dv| / |v| <= 3 |d(x, y)|. */
#define OCTAHEDRAL_NORMAL_BOUND (3.0 * 1.4142135623730951 / 254.0)

/* The vertex bound for a reported grid step, plus float rounding of the
 * world transform (4 ulp of the largest coordinate). */
static double vertex_bound(const scene *s, double step)
{
    vec3 lo, hi;
    scene_bounds(s, &lo, &hi);
    const double largest = fmax(fmax(fmax(fabs(lo.x), fabs(hi.x)), fmax(fabs(lo.y), fabs(hi.y))),
                                fmax(fabs(lo.z), fabs(hi.z)));
    return sqrt(3.0) / 2.0 * step + 4.0 * largest * 0x1p-23;
}

static int load(const char *path, scene *s, gltf_report *r)
{
    gt_error e;
    const int rc = gltf_load_report(path, s, r, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    return rc;
}

static void check_meshopt(void)
{
    char plain_path[4096], glb_path[4096], gltf_path[4096], cc_path[4096], cf_path[4096];
    snprintf(cc_path, sizeof cc_path, "%s", tmp_path("engine_meshopt_cc.glb"));
    snprintf(cf_path, sizeof cf_path, "%s", tmp_path("engine_meshopt_cf.glb"));
    snprintf(plain_path, sizeof plain_path, "%s", tmp_path("engine_plain.glb"));
    snprintf(glb_path, sizeof glb_path, "%s", tmp_path("engine_meshopt.glb"));
    snprintf(gltf_path, sizeof gltf_path, "%s", tmp_path("engine_meshopt.gltf"));
    const int rc = run_gltfpack(ENGINE, plain_path, "-noq");
    if (rc == 1) {
        printf("test_gltf_compressed: gltfpack is not installed (Debian package gltfpack; setup.sh installs it); "
               "meshopt cases skipped\n");
        return;
    }
    CHECK(rc == 0 && run_gltfpack(ENGINE, glb_path, "-c") == 0 && run_gltfpack(ENGINE, gltf_path, "-c") == 0 &&
          run_gltfpack(ENGINE, cc_path, "-cc") == 0 && run_gltfpack(ENGINE, cf_path, "-cf") == 0);
    scene plain, glb, gltf, cc, cf;
    gltf_report r, unused;
    if (load(plain_path, &plain, &unused) != 0 || load(glb_path, &glb, &r) != 0 || load(gltf_path, &gltf, &unused) ||
        load(cc_path, &cc, &unused) != 0 || load(cf_path, &cf, &unused) != 0)
        return;
    CHECK(r.meshopt_views > 0 && r.position_step > 0.0 && strstr(r.extensions_used, "EXT_meshopt_compression"));
    const double bound = vertex_bound(&plain, r.position_step);
    CHECK(check_same_geometry(&plain, &glb, bound, sqrt(3.0) / 127.0, "meshopt .glb") == 0);
    CHECK(check_same_geometry(&glb, &gltf, 0.0, 0.0, "meshopt .gltf vs .glb") == 0);
    CHECK(check_same_ao(&plain, &glb, bound, "meshopt") == 0);
    CHECK(check_same_vertex_sets(&glb, &cc, sqrt(3.0) / 127.0 + OCTAHEDRAL_NORMAL_BOUND, "meshopt -cc vs -c") == 0);
    CHECK(check_same_ao(&plain, &cc, bound, "meshopt -cc") == 0);
    CHECK(check_same_geometry(&glb, &cf, 0.0, 0.0, "meshopt -cf vs -c") == 0);
    scene_free(&plain), scene_free(&glb), scene_free(&gltf), scene_free(&cc), scene_free(&cf);
}

static void mesh_bounds(const scene_mesh *m, float lo[3], float hi[3])
{
    for (int k = 0; k < 3; ++k)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    for (uint32_t v = 0; v < m->vertex_count; ++v)
        for (int k = 0; k < 3; ++k)
            lo[k] = fminf(lo[k], m->positions[3 * v + k]), hi[k] = fmaxf(hi[k], m->positions[3 * v + k]);
}

static void check_draco(void)
{
    scene plain, draco;
    gltf_report r, unused;
    if (load(ENGINE, &plain, &unused) != 0 || load(DRACO, &draco, &r) != 0)
        return;
    CHECK(r.draco_primitives == draco.mesh_count && r.position_step > 0.0);
    CHECK(plain.mesh_count == draco.mesh_count);
    const double bound = vertex_bound(&plain, r.position_step);
    double worst = 0.0;
    for (int i = 0; i < plain.mesh_count && i < draco.mesh_count; ++i) {
        float lo_a[3], hi_a[3], lo_b[3], hi_b[3];
        mesh_bounds(&plain.meshes[i], lo_a, hi_a);
        mesh_bounds(&draco.meshes[i], lo_b, hi_b);
        for (int k = 0; k < 3; ++k)
            worst = fmax(worst, fmax(fabs(lo_a[k] - lo_b[k]), fabs(hi_a[k] - hi_b[k])));
    }
    printf("Draco: mesh bounding boxes at most %.3g apart per axis (bound %.3g)\n", worst, bound);
    CHECK(worst <= bound);
    CHECK(check_same_ao(&plain, &draco, bound, "Draco") == 0);
    scene_free(&plain), scene_free(&draco);
}

int main(void)
{
    struct stat st;
    if (stat(ENGINE, &st) != 0 || stat(DRACO, &st) != 0) {
        printf("test_gltf_compressed: %s not installed (assimp-testmodels); skipped\n", MODELS);
        return check_report("test_gltf_compressed");
    }
    check_meshopt();
    check_draco();
    return check_report("test_gltf_compressed");
}
