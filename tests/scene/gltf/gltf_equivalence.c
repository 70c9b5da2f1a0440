/* glTF equivalence checks: see gltf_equivalence.h. */
#define _POSIX_C_SOURCE 200809L
#include "gltf_equivalence.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raytracer/reference_render.h"
#include "tests/check.h"

int run_gltfpack(const char *in, const char *out, const char *flags)
{
    if (system("command -v gltfpack >/dev/null 2>&1") != 0)
        return 1;
    char command[8192];
    snprintf(command, sizeof command, "gltfpack -i '%s' -o '%s' %s >/dev/null 2>&1", in, out, flags);
    return system(command) == 0 ? 0 : -1;
}

static double distance3(const float *a, const float *b)
{
    const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return sqrt(x * x + y * y + z * z);
}

/* Triangle t of a and of b have the same corners in the same cyclic order
 * (a codec may start a triangle at another corner; the winding stays). */
static int same_triangle(const uint32_t *a, const uint32_t *b)
{
    for (int r = 0; r < 3; ++r)
        if (a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3])
            return 1;
    return 0;
}

static int same_triangles(const scene_mesh *a, const scene_mesh *b)
{
    if (a->vertex_count != b->vertex_count || a->triangle_count != b->triangle_count)
        return 0;
    for (uint32_t t = 0; t < a->triangle_count; ++t)
        if (!same_triangle(&a->indices[3 * t], &b->indices[3 * t]))
            return 0;
    return 1;
}

double check_same_geometry(const scene *a, const scene *b, double position_bound, double normal_bound,
                           const char *what)
{
    CHECK_MSG(a->mesh_count == b->mesh_count, "%s: %d vs %d meshes", what, a->mesh_count, b->mesh_count);
    double worst = 0.0, worst_normal = 0.0;
    int different = -1;
    for (int i = 0; i < a->mesh_count && i < b->mesh_count; ++i) {
        const scene_mesh *ma = &a->meshes[i], *mb = &b->meshes[i];
        if (!same_triangles(ma, mb)) {
            different = different < 0 ? i : different;
            continue;
        }
        for (uint32_t v = 0; v < ma->vertex_count; ++v) {
            worst = fmax(worst, distance3(&ma->positions[3 * v], &mb->positions[3 * v]));
            worst_normal = fmax(worst_normal, distance3(&ma->normals[3 * v], &mb->normals[3 * v]));
        }
    }
    CHECK_MSG(different < 0, "%s: mesh %d has other triangles", what, different);
    printf("%s: vertices at most %.3g apart (bound %.3g), normals %.3g (bound %.3g)\n", what, worst, position_bound,
           worst_normal, normal_bound);
    CHECK_MSG(worst <= position_bound, "%s: a vertex moved %.6g > %.6g", what, worst, position_bound);
    if (normal_bound >= 0.0)
        CHECK_MSG(worst_normal <= normal_bound, "%s: a normal moved %.6g > %.6g", what, worst_normal, normal_bound);
    return worst;
}

static int render_ao(const scene *s, const camera *cam, image *out)
{
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = 16, .seed = 7, .threads = 2},
                             .normals = NORMAL_SHADING, .max_distance = INFINITY};
    render_stats stats;
    gt_error e;
    return reference_render(s, "test", cam, &req, out, &stats, &e);
}

/* The side of a pixel at the distance from the camera to the nearest point
 * of the scene's bounding box (0 when the camera is inside it). */
static double nearest_pixel_footprint(const scene *s, const camera *cam)
{
    vec3 lo, hi;
    scene_bounds(s, &lo, &hi);
    const vec3 p = cam->position;
    const double dx = fmax(fmax(lo.x - p.x, p.x - hi.x), 0.0), dy = fmax(fmax(lo.y - p.y, p.y - hi.y), 0.0),
                 dz = fmax(fmax(lo.z - p.z, p.z - hi.z), 0.0);
    return 2.0 * sqrt(dx * dx + dy * dy + dz * dz) * tan(0.5 * cam->yfov) / cam->height;
}

void check_same_ao(const scene *a, const scene *b, double displacement, const char *what)
{
    camera cam;
    gt_error e;
    CHECK(scene_choose_camera(a, NULL, 64, 48, &cam, &e) == 0);
    const double footprint = nearest_pixel_footprint(a, &cam);
    CHECK_MSG(footprint > 0.0, "%s: the camera is inside the scene's bounds", what);
    const double geometric = displacement / footprint;
    image ia, ib;
    if (render_ao(a, &cam, &ia) != 0 || render_ao(b, &cam, &ib) != 0) {
        CHECK_MSG(0, "%s: render failed", what);
        return;
    }
    const float *va = image_channel_data(&ia, "ao.V"), *vb = image_channel_data(&ib, "ao.V");
    const size_t n = (size_t)cam.width * (size_t)cam.height;
    double sum = 0.0, sum2 = 0.0, mean_a = 0.0;
    size_t changed = 0;
    for (size_t i = 0; i < n; ++i) {
        const double d = (double)va[i] - (double)vb[i];
        sum += d, sum2 += d * d, mean_a += va[i], changed += d != 0.0;
    }
    const double mean = sum / (double)n, se = sqrt(fmax(sum2 / (double)n - mean * mean, 0.0) / (double)(n - 1));
    printf("%s: mean AO %.5f, mean difference %.3g, 4 SE %.3g, geometric %.3g, %zu of %zu pixels differ\n", what,
           mean_a / (double)n, mean, 4.0 * se, geometric, changed, n);
    CHECK_MSG(fabs(mean) <= 4.0 * se + geometric, "%s: mean AO differs by %.6g", what, mean);
    image_free(&ia);
    image_free(&ib);
}
