/* The AO reference against closed forms:
 *  - a lone plane: V_d = V_u = 1 exactly, bent normal = the normal, also seen
 *    at a grazing angle (no self-intersection, no acne);
 *  - floor under a sphere (fully above the horizon): V_d = 1 - cos(theta) (r/d)^2
 *    (Nusselt: the view factor of a sphere) and V_u = sqrt(1 - (r/d)^2)
 *    (one minus its solid angle 2 pi (1 - sqrt(1 - (r/d)^2)) over 2 pi);
 *  - the 90-degree corner: each face sees the two others as rectangles, whose
 *    view factors follow from Lambert's contour formula; V_d = 1 - F1 - F2;
 *  - --max-distance shorter than any occluder gives 1.
 * Monte Carlo checks are within 4 standard errors taken from the render. */
#include <math.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/sampling/hemisphere_sampling.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

static image render(const char *spec, const camera *cam_override, int size, int spp, float max_distance,
                    scene *s_out)
{
    gt_error e;
    scene s;
    image img = {0};
    if (scene_load(spec, &s, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        CHECK(0);
        return img;
    }
    camera cam;
    if (cam_override)
        cam = *cam_override;
    else
        CHECK(scene_choose_camera(&s, NULL, size, size, &cam, &e) == 0);
    ao_render_settings ao = {{QUANTITY_AO}, .max_distance = max_distance};
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = spp, .seed = 7, .threads = 2},
                             .normals = NORMAL_SHADING, .settings = &ao.header};
    render_stats stats;
    CHECK(reference_render(&s, spec, &cam, &req, &img, &stats, &e) == 0);
    if (s_out)
        *s_out = s;
    else
        scene_free(&s);
    return img;
}

static int covered_pixels(const image *img)
{
    const float *mask = image_channel_data(img, "mask.A");
    int n = 0;
    for (size_t i = 0; i < image_pixel_count(img); ++i)
        n += mask[i] != 0.0f;
    return n;
}

static void check_plane_exact(const image *img, const char *label)
{
    const float *mask = image_channel_data(img, "mask.A"), *v = image_channel_data(img, "ao.V");
    const float *vu = image_channel_data(img, "ao.Vuniform");
    const float *b[3] = {image_channel_data(img, "bent.X"), image_channel_data(img, "bent.Y"),
                         image_channel_data(img, "bent.Z")};
    const float *be[3] = {image_channel_data(img, "bent.X.stderr"), image_channel_data(img, "bent.Y.stderr"),
                          image_channel_data(img, "bent.Z.stderr")};
    int not_one = 0, bent_off = 0;
    const float normal[3] = {0.0f, 1.0f, 0.0f};
    for (size_t i = 0; i < image_pixel_count(img); ++i) {
        if (mask[i] == 0.0f)
            continue;
        not_one += v[i] != 1.0f || vu[i] != 1.0f;
        for (int a = 0; a < 3; ++a)
            bent_off += fabsf(b[a][i] - normal[a]) > 4.0f * be[a][i] + 1e-6f;
    }
    CHECK_MSG(covered_pixels(img) > 100, "%s: too few plane pixels", label);
    CHECK_MSG(not_one == 0, "%s: %d pixels with AO != 1", label, not_one);
    CHECK_MSG(bent_off == 0, "%s: %d pixels whose bent normal is off the normal", label, bent_off);
}

static void test_plane(void)
{
    /* 128 x 128 pixels x 1024 samples x 2 rays: 33 million rays, enough to
     * meet the 2^-24-probability corner cases of the samplers. */
    image img = render("builtin:plane", NULL, 128, 1024, INFINITY, NULL);
    check_plane_exact(&img, "plane");
    image_free(&img);
    /* Grazing: the eye 1 cm above the plane, looking 40 m away. */
    camera grazing = {v3(0.0f, 0.01f, 45.0f), v3(0.0f, 0.0f, 5.0f), v3(0.0f, 1.0f, 0.0f), 0.5f, 128, 64};
    img = render("builtin:plane", &grazing, 0, 1024, INFINITY, NULL);
    check_plane_exact(&img, "plane at a grazing angle");
    image_free(&img);
}

/* Counts pixels whose estimate is more than 4 standard errors from `expected`.
 * The estimators here average 0/1 visibilities, so under the hypothesis that
 * the mean is p their standard error is sqrt(p (1 - p) / n); a pixel whose n
 * samples happen to agree has a sample standard error of 0 but not an exact
 * mean, so the larger of the two is used. */
typedef struct {
    int compared, outliers;
    double worst_z;
    double sum_error, sum_variance; /* for the aggregate test below */
} z_summary;

static void z_add(z_summary *z, double estimate, double stderr_, double expected, double n)
{
    double null_stderr = sqrt(fmax(expected * (1.0 - expected), 0.0) / n);
    double dz = fabs(estimate - expected) / fmax(fmax(stderr_, null_stderr), 1e-12);
    z->compared++;
    z->outliers += dz > 4.0;
    z->worst_z = fmax(z->worst_z, dz);
    z->sum_error += estimate - expected;
    z->sum_variance += fmax(stderr_ * stderr_, null_stderr * null_stderr);
}

/* Pixels have independent seeds, so their errors add in quadrature: the mean
 * error over all pixels must be within 4 of its standard errors. This sees a
 * bias far below what one pixel can. */
static double aggregate_z(const z_summary *z) { return fabs(z->sum_error) / sqrt(fmax(z->sum_variance, 1e-300)); }

static void test_sphere_on_plane(void)
{
    image img = render("builtin:sphere-on-plane", NULL, 48, 1024, INFINITY, NULL);
    const float *mask = image_channel_data(&img, "mask.A");
    const float *px = image_channel_data(&img, "P.X"), *py = image_channel_data(&img, "P.Y");
    const float *pz = image_channel_data(&img, "P.Z");
    const float *v = image_channel_data(&img, "ao.V"), *ve = image_channel_data(&img, "ao.V.stderr");
    const float *vu = image_channel_data(&img, "ao.Vuniform"), *vue = image_channel_data(&img, "ao.Vuniform.stderr");
    z_summary cosine = {0}, uniform = {0};
    double min_v = 1.0;
    for (size_t i = 0; i < image_pixel_count(&img); ++i) {
        if (mask[i] == 0.0f || py[i] != 0.0f)
            continue; /* floor pixels only */
        double dx = 0.0 - px[i], dy = 1.5 - py[i], dz = 0.0 - pz[i];
        double d2 = dx * dx + dy * dy + dz * dz, d = sqrt(d2);
        double cos_theta = dy / d;
        z_add(&cosine, v[i], ve[i], 1.0 - cos_theta / d2, 1024);
        z_add(&uniform, vu[i], vue[i], sqrt(1.0 - 1.0 / d2), 1024);
        min_v = fmin(min_v, v[i]);
    }
    CHECK_MSG(cosine.compared > 500, "only %d floor pixels", cosine.compared);
    CHECK_MSG(min_v < 0.7, "the view does not include strongly occluded floor (min AO %g)", min_v);
    CHECK_MSG(cosine.outliers == 0, "cosine AO: %d of %d floor pixels beyond 4 stderr (worst %.2f)", cosine.outliers,
              cosine.compared, cosine.worst_z);
    CHECK_MSG(aggregate_z(&cosine) < 4.0, "cosine AO: mean error %.2e is %.2f standard errors",
              cosine.sum_error / cosine.compared, aggregate_z(&cosine));
    CHECK_MSG(aggregate_z(&uniform) < 4.0, "uniform AO: mean error %.2e is %.2f standard errors",
              uniform.sum_error / uniform.compared, aggregate_z(&uniform));
    CHECK_MSG(uniform.outliers == 0, "uniform AO: %d of %d floor pixels beyond 4 stderr (worst %.2f)",
              uniform.outliers, uniform.compared, uniform.worst_z);
    image_free(&img);

    /* Rays stopped at 0.4 never reach the sphere (its bottom is 0.5 above the floor). */
    img = render("builtin:sphere-on-plane", NULL, 32, 16, 0.4f, NULL);
    mask = image_channel_data(&img, "mask.A");
    py = image_channel_data(&img, "P.Y");
    v = image_channel_data(&img, "ao.V");
    int not_one = 0;
    for (size_t i = 0; i < image_pixel_count(&img); ++i)
        not_one += mask[i] != 0.0f && py[i] == 0.0f && v[i] != 1.0f;
    CHECK_MSG(not_one == 0, "with --max-distance 0.4, %d floor pixels are occluded", not_one);
    image_free(&img);
}

/* Lambert's contour formula: the view factor from a point p with normal n to
 * a planar polygon fully above its horizon,
 *   F = (1 / 2 pi) | sum_i angle(v_i, v_i+1) n . (v_i x v_i+1) / |v_i x v_i+1| |
 * with v_i the unit vectors from p to the vertices. */
static double polygon_view_factor(const double p[3], const double n[3], const double quad[4][3])
{
    double u[4][3], sum = 0.0;
    for (int k = 0; k < 4; ++k) {
        double len = 0.0;
        for (int a = 0; a < 3; ++a) {
            u[k][a] = quad[k][a] - p[a];
            len += u[k][a] * u[k][a];
        }
        for (int a = 0; a < 3; ++a)
            u[k][a] /= sqrt(len);
    }
    for (int k = 0; k < 4; ++k) {
        const double *a = u[k], *b = u[(k + 1) % 4];
        double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        double clen = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        if (clen < 1e-15)
            continue;
        double angle = atan2(clen, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
        sum += angle * (n[0] * c[0] + n[1] * c[1] + n[2] * c[2]) / clen;
    }
    return fabs(sum) / (2.0 * M_PI);
}

static void test_corner(void)
{
    /* The corner scene's three 10 x 10 faces (builtin_scenes.c documents them). */
    static const double faces[3][4][3] = {
        {{0, 0, 0}, {10, 0, 0}, {10, 0, 10}, {0, 0, 10}},   /* floor y = 0 */
        {{0, 0, 0}, {0, 10, 0}, {0, 10, 10}, {0, 0, 10}},   /* wall x = 0 */
        {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}}};  /* wall z = 0 */
    static const double normals[3][3] = {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
    image img = render("builtin:corner", NULL, 48, 1024, INFINITY, NULL);
    const float *mask = image_channel_data(&img, "mask.A");
    const char *pn[3] = {"P.X", "P.Y", "P.Z"};
    const float *P[3];
    for (int a = 0; a < 3; ++a)
        P[a] = image_channel_data(&img, pn[a]);
    const float *v = image_channel_data(&img, "ao.V"), *ve = image_channel_data(&img, "ao.V.stderr");
    z_summary z = {0};
    int per_face[3] = {0};
    for (size_t i = 0; i < image_pixel_count(&img); ++i) {
        if (mask[i] == 0.0f)
            continue;
        double p[3] = {P[0][i], P[1][i], P[2][i]};
        /* The face the pixel lies on: the coordinate that is exactly 0 (x on
         * wall x = 0, y on the floor, z on wall z = 0); skip the seams. */
        int face = -1, zeros = 0;
        const int axis_face[3] = {1, 0, 2};
        for (int a = 0; a < 3; ++a)
            if (p[a] == 0.0) {
                face = axis_face[a];
                ++zeros;
            }
        if (zeros != 1)
            continue;
        double expected = 1.0;
        for (int f = 0; f < 3; ++f)
            if (f != face)
                expected -= polygon_view_factor(p, normals[face], faces[f]);
        z_add(&z, v[i], ve[i], expected, 1024);
        per_face[face]++;
    }
    CHECK_MSG(per_face[0] > 100 && per_face[1] > 100 && per_face[2] > 100, "face pixels %d %d %d", per_face[0],
              per_face[1], per_face[2]);
    CHECK_MSG(aggregate_z(&z) < 4.0, "corner: mean error %.2e is %.2f standard errors", z.sum_error / z.compared,
              aggregate_z(&z));
    CHECK_MSG(z.outliers == 0, "corner: %d of %d pixels beyond 4 stderr (worst %.2f)", z.outliers, z.compared,
              z.worst_z);
    image_free(&img);
}

int main(void)
{
    test_plane();
    test_sphere_on_plane();
    test_corner();
    return check_report("test_ao_closed_forms");
}
