/* glTF equivalence checks: see gltf_equivalence.h. Each function prints
 * every failure (file, line, why) and returns how many there were; the test
 * CHECKs that the count is 0 (tests/check.h counts per translation unit). */
#define _POSIX_C_SOURCE 200809L
#include "ao/ao_quantity.h"
#include "gltf_equivalence.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raytracer/reference_render.h"

/* 0 when cond holds, else prints the message and returns 1. */
static int expect(int cond, const char *fmt, ...)
{
    if (cond)
        return 0;
    va_list ap;
    va_start(ap, fmt);
    fputs("gltf_equivalence: FAILED: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return 1;
}

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

int check_same_geometry(const scene *a, const scene *b, double position_bound, double normal_bound, const char *what)
{
    int failed = expect(a->mesh_count == b->mesh_count, "%s: %d vs %d meshes", what, a->mesh_count, b->mesh_count);
    double worst = 0.0, worst_normal = 0.0;
    for (int i = 0; i < a->mesh_count && i < b->mesh_count; ++i) {
        const scene_mesh *ma = &a->meshes[i], *mb = &b->meshes[i];
        if (expect(same_triangles(ma, mb), "%s: mesh %d has other triangles", what, i)) {
            ++failed;
            continue;
        }
        for (uint32_t v = 0; v < ma->vertex_count; ++v) {
            worst = fmax(worst, distance3(&ma->positions[3 * v], &mb->positions[3 * v]));
            worst_normal = fmax(worst_normal, distance3(&ma->normals[3 * v], &mb->normals[3 * v]));
        }
    }
    printf("%s: vertices at most %.3g apart (bound %.3g), normals %.3g (bound %.3g)\n", what, worst, position_bound,
           worst_normal, normal_bound);
    failed += expect(worst <= position_bound, "%s: a vertex moved %.6g > %.6g", what, worst, position_bound);
    if (normal_bound >= 0.0)
        failed += expect(worst_normal <= normal_bound, "%s: a normal moved %.6g > %.6g", what, worst_normal,
                         normal_bound);
    return failed;
}

/* ---------------------------------------------- vertices as sets (-cc) */

static const float *sort_positions; /* the array qsort's comparison reads */

static int compare_vertex(const void *x, const void *y)
{
    return memcmp(&sort_positions[3 * *(const uint32_t *)x], &sort_positions[3 * *(const uint32_t *)y], 12);
}

/* The smallest normal distance from b's vertex v to a vertex of a at the
 * same position bits (a's vertices sorted in `order`), or INFINITY. */
static double nearest_normal(const scene_mesh *a, const uint32_t *order, const scene_mesh *b, uint32_t v)
{
    size_t lo = 0, hi = a->vertex_count;
    while (lo < hi) { /* first of a's sorted vertices not below v's position */
        const size_t mid = (lo + hi) / 2;
        if (memcmp(&a->positions[3 * order[mid]], &b->positions[3 * v], 12) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    double best = INFINITY;
    for (size_t k = lo; k < a->vertex_count && memcmp(&a->positions[3 * order[k]], &b->positions[3 * v], 12) == 0; ++k)
        best = fmin(best, distance3(&a->normals[3 * order[k]], &b->normals[3 * v]));
    return best;
}

int check_same_vertex_sets(const scene *a, const scene *b, double normal_bound, const char *what)
{
    int failed = expect(a->mesh_count == b->mesh_count, "%s: %d vs %d meshes", what, a->mesh_count, b->mesh_count);
    double worst = 0.0;
    for (int i = 0; i < a->mesh_count && i < b->mesh_count; ++i) {
        const scene_mesh *ma = &a->meshes[i], *mb = &b->meshes[i];
        uint32_t *order = malloc(sizeof *order * (ma->vertex_count + 1));
        for (uint32_t v = 0; v < ma->vertex_count; ++v)
            order[v] = v;
        sort_positions = ma->positions;
        qsort(order, ma->vertex_count, sizeof *order, compare_vertex);
        for (uint32_t v = 0; v < mb->vertex_count; ++v)
            worst = fmax(worst, nearest_normal(ma, order, mb, v));
        free(order);
        failed += expect(ma->triangle_count == mb->triangle_count, "%s: mesh %d: %u vs %u triangles", what, i,
                         ma->triangle_count, mb->triangle_count);
    }
    printf("%s: every vertex at a position of the other file, normals at most %.3g apart (bound %.3g)\n", what,
           worst, normal_bound);
    return failed + expect(worst <= normal_bound, "%s: a normal moved %.6g > %.6g (or a position is not there)",
                           what, worst, normal_bound);
}

/* ------------------------------------------------------------------- AO */

static int render_ao(const scene *s, const camera *cam, image *out)
{
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = 16, .seed = 7, .threads = 2},
                             .normals = NORMAL_SHADING};
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

/* Mean and standard error of the per-pixel differences a - b. */
static void paired_difference(const float *a, const float *b, size_t n, double *mean, double *se, double *mean_a)
{
    double sum = 0.0, sum2 = 0.0;
    *mean_a = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double d = (double)a[i] - (double)b[i];
        sum += d, sum2 += d * d, *mean_a += a[i];
    }
    *mean = sum / (double)n;
    *mean_a /= (double)n;
    *se = sqrt(fmax(sum2 / (double)n - *mean * *mean, 0.0) / (double)(n - 1));
}

int check_same_ao(const scene *a, const scene *b, double displacement, const char *what)
{
    camera cam;
    gt_error e;
    image ia, ib;
    if (expect(scene_choose_camera(a, NULL, 64, 48, &cam, &e) == 0, "%s: %s", what, e.message) ||
        expect(render_ao(a, &cam, &ia) == 0, "%s: render failed", what))
        return 1;
    if (expect(render_ao(b, &cam, &ib) == 0, "%s: render failed", what)) {
        image_free(&ia);
        return 1;
    }
    const double footprint = nearest_pixel_footprint(a, &cam), geometric = displacement / footprint;
    double mean, se, mean_a;
    paired_difference(image_channel_data(&ia, "ao.V"), image_channel_data(&ib, "ao.V"),
                      (size_t)cam.width * (size_t)cam.height, &mean, &se, &mean_a);
    printf("%s: mean AO %.5f, mean difference %.3g, 4 SE %.3g, geometric %.3g\n", what, mean_a, mean, 4.0 * se,
           geometric);
    image_free(&ia);
    image_free(&ib);
    return expect(footprint > 0.0, "%s: the camera is inside the scene's bounds", what) +
           expect(fabs(mean) <= 4.0 * se + geometric, "%s: mean AO differs by %.6g", what, mean);
}
