/* The SG-NDF specular images: at sphere pixels, the Monte Carlo mean of
 * the true NDF's image and of an SG sum's image against nested adaptive
 * integration of the header's integral (same geometry, computed here from
 * its definition), within 5 standard errors; one and two threads give the
 * same bits; bad options are errors. Roughness is small enough that the
 * [r.n > 0] edge (45 degrees from n at the centre) carries < 1e-20 of D. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/optics/sky_environment.h"
#include "sg_ndf/sg_ndf_images.h"
#include "tests/check.h"

typedef struct {
    const anisotropic_ndf *ndf;
    const spherical_gaussian *lobes;
    int count;
    double n[3], t[3], b[3];
    double theta;
} pixel_ctx;

static double integrand(double phi, void *c_)
{
    const pixel_ctx *c = c_;
    double s = sin(c->theta), ml[3] = {s * cos(phi), s * sin(phi), cos(c->theta)}, m[3], r[3];
    double d = c->ndf ? anisotropic_ndf_evaluate(c->ndf, ml) : sg_sum_evaluate(c->lobes, c->count, ml);
    for (int i = 0; i < 3; ++i)
        m[i] = c->t[i] * ml[0] + c->b[i] * ml[1] + c->n[i] * ml[2];
    for (int i = 0; i < 3; ++i)
        r[i] = 2.0 * m[2] * m[i] - (i == 2);
    if (r[0] * c->n[0] + r[1] * c->n[1] + r[2] * c->n[2] <= 0.0)
        return 0.0;
    return d * ml[2] * s * sky_radiance(v3((float)r[0], (float)r[1], (float)r[2]));
}

/* A 1024 x 1024 midpoint rule in (u, phi), theta = atan(c tan(pi u / 2))
 * (c: the lobe's slope scale), weights sin theta dtheta/du: the integrand
 * is smooth where it matters. */
static double pixel_quadrature(const anisotropic_ndf *ndf, const spherical_gaussian *lobes, int count, int size,
                               int x, int y, double c_scale)
{
    pixel_ctx c = {ndf, lobes, count, {0}, {0}, {0}, 0.0};
    double px = 2.0 * (x + 0.5) / size - 1.0, py = 1.0 - 2.0 * (y + 0.5) / size;
    c.n[0] = px, c.n[1] = py, c.n[2] = sqrt(1.0 - px * px - py * py);
    double len = hypot(c.n[2], c.n[0]);
    c.t[0] = c.n[2] / len, c.t[2] = -c.n[0] / len;
    c.b[0] = c.n[1] * c.t[2], c.b[1] = c.n[2] * c.t[0] - c.n[0] * c.t[2], c.b[2] = -c.n[1] * c.t[0];
    enum { N = 1024 };
    double sum = 0.0;
    for (int i = 0; i < N; ++i) {
        double t = tan(0.5 * M_PI * (i + 0.5) / N);
        double dtheta = c_scale * 0.5 * M_PI * (1.0 + t * t) / (1.0 + c_scale * c_scale * t * t) / N;
        c.theta = atan(c_scale * t);
        for (int j = 0; j < N; ++j)
            sum += integrand(2.0 * M_PI * (j + 0.5) / N, &c) * dtheta * (2.0 * M_PI / N);
    }
    return sum;
}

static void check_pixels(const anisotropic_ndf *ndf, const spherical_gaussian *lobes, int count, double c_scale,
                         const char *what)
{
    enum { SIZE = 32 };
    sg_image_options o = {SIZE, 4096, 7u, 2};
    float *mean = calloc(SIZE * SIZE, sizeof(float)), *se = calloc(SIZE * SIZE, sizeof(float));
    sg_image_planes planes = {mean, se, NULL, NULL};
    gt_error e = {{0}};
    CHECK(sg_image_render(ndf, lobes, count, &o, &planes, &e) == 0);
    const int px[3][2] = {{16, 16}, {9, 20}, {22, 11}};
    for (int i = 0; i < 3; ++i) {
        size_t p = (size_t)px[i][1] * SIZE + px[i][0];
        double q = pixel_quadrature(ndf, lobes, count, SIZE, px[i][0], px[i][1], c_scale);
        CHECK_MSG(fabs(mean[p] - q) <= 5.0 * se[p] + 1e-5 * q && se[p] > 0.0, "%s pixel (%d, %d): %.6f vs %.6f, se %.2g",
                  what, px[i][0], px[i][1], mean[p], q, se[p]);
    }
    CHECK(mean[0] == 0.0f);
    free(mean);
    free(se);
}

static void test_threads(void)
{
    enum { SIZE = 24 };
    anisotropic_ndf ndf = {NDF_WARD, 0.3, 0.1};
    sg_image_options o1 = {SIZE, 64, 3u, 1}, o2 = o1;
    o2.threads = 2;
    float a[SIZE * SIZE], b[SIZE * SIZE];
    sg_image_planes pa = {a, NULL, NULL, NULL}, pb = {b, NULL, NULL, NULL};
    gt_error e = {{0}};
    CHECK(sg_image_render(&ndf, NULL, 0, &o1, &pa, &e) == 0 && sg_image_render(&ndf, NULL, 0, &o2, &pb, &e) == 0);
    CHECK(memcmp(a, b, sizeof a) == 0);
    o1.samples = 3;
    CHECK(sg_image_render(&ndf, NULL, 0, &o1, &pa, &e) == -1);
    spherical_gaussian bad = {{0, 0, 1}, -1.0, 1.0};
    o1.samples = 4;
    CHECK(sg_image_render(NULL, &bad, 1, &o1, &pa, &e) == -1 && strstr(e.message, "sharpness"));
}

int main(void)
{
    for (int k = 0; k < 2; ++k) {
        anisotropic_ndf ndf = {(ndf_kind)k, 0.12, 0.05};
        check_pixels(&ndf, NULL, 0, sqrt(0.12 * 0.05), ndf_kind_name(ndf.kind));
    }
    spherical_gaussian lobes[2] = {{{0, 0, 1}, 300.0, 20.0}, {{0, 0, 1}, 800.0, 30.0}};
    sg_axis_from_gnomonic(0.08, -0.03, lobes[1].axis, NULL);
    check_pixels(NULL, lobes, 2, 0.06, "sg sum");
    test_threads();
    return check_report("test_sg_ndf_images");
}
