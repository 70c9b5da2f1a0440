/* KHR_mesh_quantization as gltfpack writes it (its default output; made here
 * at run time from assimp-testmodels' 2CylinderEngine.glb) against gltfpack's
 * -noq output of the same model (plain floats, same vertices in the same
 * order). gltfpack rounds positions to 14-bit integers over the scene's
 * largest bounding-box side L (one grid for the scene, whose step
 * s = L / (2^14 - 1) the node transforms carry) and normals to 8-bit
 * normalized integers; the bounds of gltf_equivalence.h follow: every vertex
 * within (sqrt(3) / 2) s plus float rounding of the world transform (4 ulp
 * of the largest coordinate), every unit normal within sqrt(3) / 127, and
 * the AO image mean within 4 paired standard errors plus the geometric term.
 * Texture coordinates (BoxTextured, the same way): gltfpack rounds them to
 * 12 bits over their range R per axis and stores the scale in a
 * KHR_texture_transform, so each lies within R / (2 (2^12 - 1)) (plus 4 ulp)
 * of the -noq file's once the transform is applied. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "gltf_equivalence.h"
#include "gltf_test_files.h"
#include "scene/gltf/gltf_reader.h"
#include "tests/check.h"

#define ENGINE "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"
#define BOX "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"

static void check_texcoords(void)
{
    char plain_path[4096], quantized_path[4096];
    snprintf(plain_path, sizeof plain_path, "%s", tmp_path("box_noq.glb"));
    snprintf(quantized_path, sizeof quantized_path, "%s", tmp_path("box_q.glb"));
    CHECK(run_gltfpack(BOX, plain_path, "-noq") == 0 && run_gltfpack(BOX, quantized_path, "") == 0);
    scene plain, quantized;
    gt_error e;
    if (gltf_load(plain_path, &plain, &e) != 0 || gltf_load(quantized_path, &quantized, &e) != 0) {
        CHECK_MSG(0, "%s", e.message);
        return;
    }
    const scene_mesh *a = &plain.meshes[0], *b = &quantized.meshes[0];
    CHECK(a->texcoords && b->texcoords && a->vertex_count == b->vertex_count);
    for (int k = 0; k < 2 && a->texcoords && b->texcoords && a->vertex_count == b->vertex_count; ++k) {
        float lo = INFINITY, hi = -INFINITY, worst = 0.0f;
        for (uint32_t v = 0; v < a->vertex_count; ++v)
            lo = fminf(lo, a->texcoords[2 * v + k]), hi = fmaxf(hi, a->texcoords[2 * v + k]);
        for (uint32_t v = 0; v < a->vertex_count; ++v)
            worst = fmaxf(worst, fabsf(a->texcoords[2 * v + k] - b->texcoords[2 * v + k]));
        const double bound = (hi - lo) / (2.0 * 4095.0) + 4.0 * fmax(fabs(lo), fabs(hi)) * 0x1p-23;
        printf("texcoord %d: at most %.3g apart (bound %.3g)\n", k, worst, bound);
        CHECK(worst <= bound);
    }
    scene_free(&plain);
    scene_free(&quantized);
}

int main(void)
{
    struct stat st;
    if (stat(ENGINE, &st) != 0) {
        printf("test_gltf_quantized: %s not installed (assimp-testmodels); skipped\n", ENGINE);
        return check_report("test_gltf_quantized");
    }
    char plain_path[4096], quantized_path[4096];
    snprintf(plain_path, sizeof plain_path, "%s", tmp_path("engine_noq.glb"));
    snprintf(quantized_path, sizeof quantized_path, "%s", tmp_path("engine_q.glb"));
    const int rc = run_gltfpack(ENGINE, plain_path, "-noq");
    if (rc == 1) {
        printf("test_gltf_quantized: gltfpack is not installed (Debian package gltfpack; setup.sh installs it); "
               "skipped\n");
        return check_report("test_gltf_quantized");
    }
    CHECK(rc == 0 && run_gltfpack(ENGINE, quantized_path, "") == 0);
    scene plain, quantized;
    gltf_report report;
    gt_error e;
    CHECK_MSG(gltf_load(plain_path, &plain, &e) == 0, "%s", e.message);
    CHECK_MSG(gltf_load_report(quantized_path, &quantized, &report, &e) == 0, "%s", e.message);
    CHECK(report.quantized_primitives > 0 && strstr(report.extensions_used, "KHR_mesh_quantization"));
    vec3 lo, hi;
    scene_bounds(&plain, &lo, &hi);
    const double side = fmax(fmax(hi.x - lo.x, hi.y - lo.y), hi.z - lo.z);
    const double largest = fmax(fmax(fmax(fabs(lo.x), fabs(hi.x)), fmax(fabs(lo.y), fabs(hi.y))), fmax(fabs(lo.z), fabs(hi.z)));
    const double step = side / 16383.0;
    const double bound = sqrt(3.0) / 2.0 * step + 4.0 * largest * 0x1p-23;
    CHECK(check_same_geometry(&plain, &quantized, bound, sqrt(3.0) / 127.0, "quantized") == 0);
    CHECK(check_same_ao(&plain, &quantized, bound, "quantized") == 0);
    check_texcoords();
    scene_free(&plain);
    scene_free(&quantized);
    return check_report("test_gltf_quantized");
}
