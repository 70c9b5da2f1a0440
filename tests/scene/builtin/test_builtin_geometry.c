/* Each built-in scene's geometry against its documented definition, checked
 * by independent computation: the sphere's solid angle from the floor by the
 * Van Oosterom-Strackee triangle formula against the exact cap solid angle,
 * the Menger sponge's area against the closed form of its recurrence, the box
 * field against the documented hash formula, and watertightness by matching
 * every directed edge with its reverse. */
#include <stdlib.h>
#include <string.h>

#include "scene/builtin_scenes.h"
#include "tests/check.h"
#include "tests/scene/builtin/mesh_math.h"

static const double pi = 3.14159265358979323846;

static void build(const char *name, scene *s)
{
    gt_error e;
    if (builtin_scene_build(name, s, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        exit(1);
    }
}

static int d3_equal(d3 a, d3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* Every triangle's geometric normal is `normal`, every vertex normal exactly
 * `normal`, and the triangles cover `area`. */
static void check_flat_mesh(const scene_mesh *m, d3 normal, double area, const char *what)
{
    for (uint32_t t = 0; t < m->triangle_count; ++t) {
        d3 g = tri_area_vector(m, t);
        CHECK_MSG(d3_dot(g, normal) / d3_length(g) > 1.0 - 1e-12, "%s: triangle %u", what, t);
    }
    for (uint32_t v = 0; v < m->vertex_count; ++v)
        CHECK_MSG(d3_equal(d3_of(&m->normals[3 * v]), normal), "%s: vertex %u", what, v);
    CHECK_NEAR(mesh_area(m), area, 1e-9 * area);
}

/* ---- plane ---------------------------------------------------------------- */

static void test_plane(void)
{
    scene s;
    build("plane", &s);
    CHECK(s.mesh_count == 1);
    const scene_mesh *m = &s.meshes[0];
    CHECK(m->vertex_count == 4 && m->triangle_count == 2);
    /* The four corners (+-50, 0, +-50), each exactly once. */
    int seen[4] = {0};
    for (uint32_t v = 0; v < m->vertex_count; ++v) {
        d3 p = d3_of(&m->positions[3 * v]);
        CHECK(p.y == 0.0 && fabs(p.x) == 50.0 && fabs(p.z) == 50.0);
        ++seen[(p.x > 0) + 2 * (p.z > 0)];
    }
    CHECK(seen[0] == 1 && seen[1] == 1 && seen[2] == 1 && seen[3] == 1);
    check_flat_mesh(m, (d3){0, 1, 0}, 100.0 * 100.0, "plane");
    scene_free(&s);
}

/* ---- corner --------------------------------------------------------------- */

/* Each triangle is classified by its geometric normal; the documented square
 * for that normal must contain its vertices, and the two triangles of each
 * square must cover 10 x 10. */
static void test_corner(void)
{
    scene s;
    build("corner", &s);
    CHECK(s.mesh_count == 1);
    const scene_mesh *m = &s.meshes[0];
    CHECK(m->vertex_count == 12 && m->triangle_count == 6);
    const d3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; /* walls x = 0, floor y = 0, wall z = 0 */
    double area[3] = {0};
    int count[3] = {0};
    for (uint32_t t = 0; t < m->triangle_count; ++t) {
        d3 g = tri_area_vector(m, t);
        int a = fabs(g.x) > 0 ? 0 : fabs(g.y) > 0 ? 1 : 2;
        CHECK_MSG(d3_dot(g, axes[a]) == d3_length(g), "triangle %u is not facing +x, +y or +z", t);
        ++count[a];
        area[a] += 0.5 * d3_length(g);
        for (int k = 0; k < 3; ++k) {
            d3 p = tri_position(m, t, k);
            double c[3] = {p.x, p.y, p.z};
            CHECK(c[a] == 0.0);
            for (int j = 0; j < 3; ++j)
                CHECK(c[j] >= 0.0 && c[j] <= 10.0);
            CHECK(d3_equal(tri_normal(m, t, k), axes[a]));
        }
    }
    for (int a = 0; a < 3; ++a) {
        CHECK(count[a] == 2);
        CHECK_NEAR(area[a], 100.0, 1e-9);
    }
    scene_free(&s);
}

/* ---- sphere-on-plane -------------------------------------------------------- */

/* Solid angle of triangle (a, b, c) seen from the origin, signed by its
 * winding: Van Oosterom and Strackee 1983, "The Solid Angle of a Plane
 * Triangle" (IEEE Trans. Biomed. Eng. 30(2)),
 *   tan(Omega / 2) = a . (b x c) / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|). */
static double triangle_solid_angle(d3 a, d3 b, d3 c)
{
    double la = d3_length(a), lb = d3_length(b), lc = d3_length(c);
    double numerator = d3_dot(a, d3_cross(b, c));
    double denominator = la * lb * lc + d3_dot(a, b) * lc + d3_dot(a, c) * lb + d3_dot(b, c) * la;
    return 2.0 * atan2(numerator, denominator);
}

/* A closed convex surface seen from outside is crossed twice by every ray
 * that meets it, once each way: its solid angle is half the sum of the
 * absolute triangle solid angles, and the signed sum is zero. */
static void check_sphere_solid_angle(const scene_mesh *m, d3 eye, d3 centre)
{
    double absolute = 0.0, signed_sum = 0.0;
    for (uint32_t t = 0; t < m->triangle_count; ++t) {
        double omega = triangle_solid_angle(d3_sub(tri_position(m, t, 0), eye), d3_sub(tri_position(m, t, 1), eye),
                                            d3_sub(tri_position(m, t, 2), eye));
        absolute += fabs(omega);
        signed_sum += omega;
    }
    double d = d3_length(d3_sub(centre, eye));
    double exact = 2.0 * pi * (1.0 - sqrt(1.0 - 1.0 / (d * d))); /* cap of a unit sphere at distance d */
    CHECK_NEAR(0.5 * absolute, exact, 1e-4);
    CHECK_NEAR(signed_sum, 0.0, 1e-9);
    printf("  solid angle from (%g, %g, %g): mesh %.9f, sphere %.9f, difference %.2e\n", eye.x, eye.y, eye.z,
           0.5 * absolute, exact, 0.5 * absolute - exact);
}

static int compare_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* Closed and consistently oriented: each directed edge a->b occurs once and
 * its reverse b->a also occurs, so each edge joins exactly two triangles
 * whose windings agree. */
static void check_closed(const scene_mesh *m)
{
    size_t n = 3 * (size_t)m->triangle_count;
    uint64_t *edges = malloc(n * sizeof *edges);
    for (uint32_t t = 0; t < m->triangle_count; ++t)
        for (int k = 0; k < 3; ++k)
            edges[3 * t + k] = (uint64_t)m->indices[3 * t + k] << 32 | m->indices[3 * t + (k + 1) % 3];
    qsort(edges, n, sizeof *edges, compare_u64);
    size_t repeated = 0, unmatched = 0;
    for (size_t i = 0; i < n; ++i) {
        repeated += i > 0 && edges[i] == edges[i - 1];
        uint64_t reverse = edges[i] << 32 | edges[i] >> 32;
        unmatched += bsearch(&reverse, edges, n, sizeof *edges, compare_u64) == NULL;
    }
    CHECK_MSG(repeated == 0, "%zu directed edges repeated", repeated);
    CHECK_MSG(unmatched == 0, "%zu edges without a neighbour", unmatched);
    free(edges);
}

static void test_sphere(void)
{
    scene s;
    build("sphere-on-plane", &s);
    CHECK(s.mesh_count == 2);
    CHECK(s.meshes[0].triangle_count == 2); /* the floor of 'plane' */
    check_flat_mesh(&s.meshes[0], (d3){0, 1, 0}, 100.0 * 100.0, "sphere-on-plane floor");
    const scene_mesh *m = &s.meshes[1];
    const d3 centre = {0.0, 1.5, 0.0};

    /* On the sphere, with the exact sphere normal. */
    double worst_radius = 0.0, worst_normal = 0.0;
    for (uint32_t v = 0; v < m->vertex_count; ++v) {
        d3 r = d3_sub(d3_of(&m->positions[3 * v]), centre);
        double len = d3_length(r);
        worst_radius = fmax(worst_radius, fabs(len - 1.0));
        worst_normal = fmax(worst_normal, 1.0 - d3_dot(r, d3_of(&m->normals[3 * v])) / len);
    }
    CHECK_MSG(worst_radius < 1e-6, "a vertex is %g off the sphere", worst_radius);
    CHECK_MSG(worst_normal < 1e-6, "a normal is off the radial direction (1 - cos = %g)", worst_normal);

    check_closed(m);

    /* Outward: the signed volume (divergence theorem) is +4/3 pi, less the
     * small slivers an inscribed polyhedron misses; r_in is the smallest
     * distance from the centre to a face plane. */
    double volume = 0.0, r_in = 1.0;
    for (uint32_t t = 0; t < m->triangle_count; ++t) {
        d3 a = d3_sub(tri_position(m, t, 0), centre);
        d3 n = tri_area_vector(m, t);
        volume += d3_dot(a, n) / 6.0;
        r_in = fmin(r_in, d3_dot(a, n) / d3_length(n));
    }
    CHECK_NEAR(volume, 4.0 / 3.0 * pi, 1e-3);
    CHECK(volume > 0.0);

    /* The polyhedron lies between the balls of radius r_in and 1, so from any
     * floor point its solid angle is within Omega(1) - Omega(r_in) of the
     * sphere's, largest at the nearest floor point, d = 1.5. */
    double d = 1.5;
    double bound = 2.0 * pi * (sqrt(1.0 - r_in * r_in / (d * d)) - sqrt(1.0 - 1.0 / (d * d)));
    CHECK_MSG(bound < 1e-4, "r_in = %.9f allows a solid-angle error of %.3g", r_in, bound);
    printf("  r_in = %.9f: solid-angle error bound on the floor %.3g sr\n", r_in, bound);

    const d3 floor_points[] = {{0, 0, 0}, {0.3, 0, -0.2}, {1.2, 0, 0.9}, {-3, 0, 4}, {10, 0, -7}, {-45, 0, 45}};
    for (size_t i = 0; i < sizeof floor_points / sizeof floor_points[0]; ++i)
        check_sphere_solid_angle(m, floor_points[i], centre);
    scene_free(&s);
}

/* ---- menger ------------------------------------------------------------------ */

/* Surface area of the level-n Menger sponge of side 1. Level n + 1 is 20
 * copies of level n scaled by 1/3 (area factor 1/9); the 12 edge cubes of the
 * level-1 frame each touch 2 corner cubes, and each of these 24 contacts hides
 * two coincident faces, each a level-n Sierpinski carpet of area (8/9)^n / 9:
 *   S_0 = 6,  S_{n+1} = (20/9) S_n - (48/9) (8/9)^n. */
static double menger_area(int n)
{
    double area = 6.0;
    for (int k = 0; k < n; ++k)
        area = 20.0 / 9.0 * area - 48.0 / 9.0 * pow(8.0 / 9.0, k);
    return area;
}

typedef struct {
    float from[3], to[3];
} position_edge;

static int compare_position_edge(const void *a, const void *b)
{
    const float *x = (const float *)a, *y = (const float *)b;
    for (int k = 0; k < 6; ++k)
        if (x[k] != y[k])
            return x[k] < y[k] ? -1 : 1;
    return 0;
}

/* Watertight by position (the quads do not share vertices): every directed
 * edge not on the floor rim has its reverse, so no ray can slip between two
 * faces. */
static void check_crack_free(const scene_mesh *m)
{
    size_t n = 3 * (size_t)m->triangle_count, unmatched = 0;
    position_edge *edges = malloc(n * sizeof *edges);
    for (uint32_t t = 0; t < m->triangle_count; ++t)
        for (int k = 0; k < 3; ++k) {
            memcpy(edges[3 * t + k].from, &m->positions[3 * m->indices[3 * t + k]], sizeof(float[3]));
            memcpy(edges[3 * t + k].to, &m->positions[3 * m->indices[3 * t + (k + 1) % 3]], sizeof(float[3]));
        }
    qsort(edges, n, sizeof *edges, compare_position_edge);
    for (size_t i = 0; i < n; ++i) {
        position_edge reverse;
        memcpy(reverse.from, edges[i].to, sizeof reverse.from);
        memcpy(reverse.to, edges[i].from, sizeof reverse.to);
        int on_floor = edges[i].from[1] == 0.0f && edges[i].to[1] == 0.0f;
        unmatched += !on_floor && !bsearch(&reverse, edges, n, sizeof *edges, compare_position_edge);
    }
    CHECK_MSG(unmatched == 0, "%zu edges above the floor without a neighbour", unmatched);
    free(edges);
}

static void test_menger(void)
{
    scene s;
    build("menger", &s);
    CHECK(s.mesh_count == 2);
    const scene_mesh *m = &s.meshes[1];
    /* Side 2 (area x 4), without the bottom face: a level-3 carpet on the floor. */
    double expected = 4.0 * (menger_area(3) - pow(8.0 / 9.0, 3));
    CHECK_NEAR(mesh_area(m), expected, 1e-6 * expected); /* one cell face too many or few: 5.7e-5 */
    printf("  menger area %.9f, closed form %.9f\n", mesh_area(m), expected);

    /* Every triangle is half a cell face (side 2/27): none degenerate. */
    const double half_cell_face = 0.5 * (2.0 / 27.0) * (2.0 / 27.0);
    size_t wrong_size = 0, in_tunnel = 0;
    for (uint32_t t = 0; t < m->triangle_count; ++t) {
        wrong_size += fabs(0.5 * d3_length(tri_area_vector(m, t)) - half_cell_face) > 1e-5 * half_cell_face;
        /* The level-1 tunnels (two of |x|, |y - 1|, |z| below 1/3) hold no surface. */
        d3 c = tri_position(m, t, 0), p1 = tri_position(m, t, 1), p2 = tri_position(m, t, 2);
        d3 centroid = {(c.x + p1.x + p2.x) / 3, (c.y + p1.y + p2.y) / 3 - 1.0, (c.z + p1.z + p2.z) / 3};
        double margin = 1.0 / 3.0 - 1e-6;
        in_tunnel += (fabs(centroid.x) < margin) + (fabs(centroid.y) < margin) + (fabs(centroid.z) < margin) >= 2;
    }
    CHECK_MSG(wrong_size == 0, "%zu triangles are not half a cell face", wrong_size);
    CHECK_MSG(in_tunnel == 0, "%zu triangles inside the level-1 tunnels", in_tunnel);

    vec3 lo = v3(INFINITY, INFINITY, INFINITY), hi = v3(-INFINITY, -INFINITY, -INFINITY);
    for (uint32_t v = 0; v < m->vertex_count; ++v) {
        lo = v3_min(lo, v3_load(&m->positions[3 * v]));
        hi = v3_max(hi, v3_load(&m->positions[3 * v]));
    }
    CHECK(lo.x == -1.0f && lo.y == 0.0f && lo.z == -1.0f && hi.x == 1.0f && hi.y == 2.0f && hi.z == 1.0f);
    check_crack_free(m);
    scene_free(&s);
}

/* ---- boxes ----------------------------------------------------------------------- */

/* PCG hash as published: Jarzynski and Olano 2020, "Hash Functions for GPU
 * Rendering", JCGT 9(3), listing "pcg". */
static uint32_t reference_pcg_hash(uint32_t v)
{
    uint32_t state = v * 747796405u + 2891336453u;
    uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

/* Box (r, c) from the formula in the scene's description: lo and hi corners. */
static void documented_box(int r, int c, d3 *lo, d3 *hi)
{
    double u[5];
    for (int k = 0; k < 5; ++k)
        u[k] = (double)(reference_pcg_hash((uint32_t)(5 * (8 * r + c) + k)) >> 8) / 16777216.0;
    double width = 0.5 + 2 * u[0], depth = 0.5 + 2 * u[1], height = 0.5 + 3.5 * u[2];
    double x = 3 * c - 10.5 + 1.5 * (u[3] - 0.5), z = 3 * r - 10.5 + 1.5 * (u[4] - 0.5);
    *lo = (d3){x - width / 2, 0.0, z - depth / 2};
    *hi = (d3){x + width / 2, height, z + depth / 2};
}

static int on_box_surface(d3 p, d3 lo, d3 hi, double eps)
{
    int inside = p.x > lo.x - eps && p.x < hi.x + eps && p.y > lo.y - eps && p.y < hi.y + eps &&
                 p.z > lo.z - eps && p.z < hi.z + eps;
    int on_face = fabs(p.x - lo.x) < eps || fabs(p.x - hi.x) < eps || fabs(p.y - hi.y) < eps ||
                  fabs(p.z - lo.z) < eps || fabs(p.z - hi.z) < eps;
    return inside && on_face;
}

static void test_boxes(void)
{
    scene s;
    build("boxes", &s);
    CHECK(s.mesh_count == 2);
    const scene_mesh *m = &s.meshes[1];
    CHECK(m->triangle_count == 64 * 5 * 2);
    d3 lo[64], hi[64];
    double area = 0.0, tallest = 0.0;
    for (int b = 0; b < 64; ++b) {
        documented_box(b / 8, b % 8, &lo[b], &hi[b]);
        double w = hi[b].x - lo[b].x, h = hi[b].y, d = hi[b].z - lo[b].z;
        area += w * d + 2.0 * h * (w + d); /* top and four sides */
        tallest = fmax(tallest, h);
    }
    CHECK_NEAR(mesh_area(m), area, 1e-5 * area);
    CHECK_NEAR(tallest, 3.894838, 1e-6); /* the height the description and test_builtin_scenes state */
    size_t stray = 0;
    for (uint32_t v = 0; v < m->vertex_count; ++v) {
        d3 p = d3_of(&m->positions[3 * v]);
        int found = 0;
        for (int b = 0; b < 64 && !found; ++b)
            found = on_box_surface(p, lo[b], hi[b], 1e-5);
        stray += !found;
    }
    CHECK_MSG(stray == 0, "%zu vertices on no documented box", stray);
    scene_free(&s);
}

/* ---- cornell ------------------------------------------------------------------------ */

static void check_colour(const scene *s, const scene_mesh *m, float r, float g, float b)
{
    const float *c = scene_mesh_material(s, m)->base_color;
    CHECK_MSG(c[0] == r && c[1] == g && c[2] == b, "colour (%g, %g, %g), expected (%g, %g, %g)", c[0], c[1], c[2], r,
              g, b);
}

static void test_cornell(void)
{
    scene s;
    build("cornell", &s);
    CHECK(s.mesh_count == 3);
    const double wall = 5.5 * 5.5, side = 1.65;
    check_colour(&s, &s.meshes[0], 0.73f, 0.73f, 0.73f);
    check_colour(&s, &s.meshes[1], 0.63f, 0.065f, 0.05f);
    check_colour(&s, &s.meshes[2], 0.14f, 0.45f, 0.091f);
    check_flat_mesh(&s.meshes[1], (d3){1, 0, 0}, wall, "red wall");
    check_flat_mesh(&s.meshes[2], (d3){-1, 0, 0}, wall, "green wall");
    for (uint32_t v = 0; v < s.meshes[1].vertex_count; ++v)
        CHECK(s.meshes[1].positions[3 * v] == -2.75f);
    for (uint32_t v = 0; v < s.meshes[2].vertex_count; ++v)
        CHECK(s.meshes[2].positions[3 * v] == 2.75f);

    /* White: floor, ceiling, back wall, and the blocks' tops and sides. */
    const scene_mesh *white = &s.meshes[0];
    double blocks = (side * side + 4 * side * side) + (side * side + 4 * side * 2 * side);
    CHECK_NEAR(mesh_area(white), 3 * wall + blocks, 1e-6 * (3 * wall + blocks));
    size_t open_front = 0, outside = 0;
    for (uint32_t t = 0; t < white->triangle_count; ++t) {
        int at_front = 1;
        for (int k = 0; k < 3; ++k) {
            d3 p = tri_position(white, t, k);
            at_front &= p.z == 2.75;
            outside += fabs(p.x) > 2.75 || p.y < 0 || p.y > 5.5 || fabs(p.z) > 2.75;
        }
        open_front += at_front;
    }
    CHECK_MSG(open_front == 0, "the front z = 2.75 is not open");
    CHECK(outside == 0);
    scene_free(&s);
}

int main(void)
{
    test_plane();
    test_corner();
    test_sphere();
    test_menger();
    test_boxes();
    test_cornell();
    return check_report("test_builtin_geometry");
}
