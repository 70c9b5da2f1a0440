/* Spherical Gaussians: evaluation and integrals (see the header). */
#include "core/optics/spherical_gaussian.h"

#include <math.h>

#include <stddef.h>

#include "core/sampling/quadrature.h"
#include "core/optics/shared_math_c.h"

double sg_evaluate(const spherical_gaussian *g, const double v[3])
{
    double t = g->axis[0] * v[0] + g->axis[1] * v[1] + g->axis[2] * v[2];
    return g->amplitude * exp(g->sharpness * (t - 1.0));
}

double sg_sum_evaluate(const spherical_gaussian *lobes, int count, const double v[3])
{
    double sum = 0.0;
    for (int i = 0; i < count; ++i)
        sum += sg_evaluate(&lobes[i], v);
    return sum;
}

/* sg_sphere_integral, the text the shaders embed too. */
#include "core/optics/spherical_gaussian.inc"

double sg_axial_cosine_integral(double sharpness, double amplitude)
{
    double l = sharpness;
    if (l < 1e-4) /* series: int_0^1 t (1 + l (t - 1)) dt = 1/2 - l/6 */
        return 2.0 * M_PI * amplitude * (0.5 - l / 6.0);
    return 2.0 * M_PI * amplitude * (l + expm1(-l)) / (l * l);
}

/* The phi integral of G(v) v.z on the ring cos theta = c: with rho = |p_xy|
 * and s = sin theta, G = mu exp(lambda (c p_z + s rho cos(phi') - 1)), so
 * the ring integral is mu c exp(lambda (c p_z - 1) + x) int_0^2pi
 * exp(x (cos phi' - 1)) dphi', x = lambda s rho. The last integral is taken
 * by the trapezoid rule, spectrally accurate for a periodic integrand once
 * the nodes resolve its width 1/sqrt(x). */
typedef struct {
    const spherical_gaussian *g;
} ring_ctx;

static double ring_integral(double c, void *ctx_)
{
    const spherical_gaussian *g = ((ring_ctx *)ctx_)->g;
    double s = sqrt(fmax(0.0, 1.0 - c * c));
    double rho = hypot(g->axis[0], g->axis[1]);
    double x = g->sharpness * s * rho;
    int n = 64 + (int)fmin(4096.0, 4.0 * sqrt(x) * 8.0);
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        sum += exp(x * (cos(2.0 * M_PI * i / n) - 1.0));
    double log_front = g->sharpness * (c * g->axis[2] - 1.0) + x;
    return g->amplitude * c * exp(log_front) * sum * (2.0 * M_PI / n);
}

double sg_projected_area_integral(const spherical_gaussian *g)
{
    ring_ctx ctx = {g};
    /* Split at the axis' elevation and one and three widths about it. */
    double cz = fmin(1.0, fmax(0.0, g->axis[2])), w = 1.0 / sqrt(fmax(g->sharpness, 1e-12));
    double theta0 = acos(cz), pts[7];
    double t[5] = {theta0 - 3 * w, theta0 - w, theta0, theta0 + w, theta0 + 3 * w};
    int count = 0;
    pts[count++] = 0.0;
    for (int i = 4; i >= 0; --i) { /* increasing cos theta */
        double c = cos(fmin(M_PI / 2, fmax(0.0, t[i])));
        if (c > pts[count - 1] && c < 1.0)
            pts[count++] = c;
    }
    pts[count++] = 1.0;
    double scale = sg_sphere_integral(g->sharpness, fabs(g->amplitude));
    return quadrature_gk15_split(ring_integral, &ctx, pts, count, 1e-12 * fmax(scale, 1e-300), NULL);
}

/* Duff et al. 2017's orthonormal basis about p, in doubles. */
static void basis_about(const double p[3], double t[3], double b[3])
{
    double sign = copysign(1.0, p[2]), a = -1.0 / (sign + p[2]), c = p[0] * p[1] * a;
    t[0] = 1.0 + sign * p[0] * p[0] * a;
    t[1] = sign * c;
    t[2] = -sign * p[0];
    b[0] = c;
    b[1] = sign + p[1] * p[1] * a;
    b[2] = -p[1];
}

void sg_sample(const spherical_gaussian *g, const double u[2], double v[3])
{
    double l = fmax(g->sharpness, 1e-12);
    double cos_t = fmax(-1.0, 1.0 + log1p(u[0] * expm1(-2.0 * l)) / l);
    double sin_t = sqrt(fmax(0.0, 1.0 - cos_t * cos_t)), phi = 2.0 * M_PI * u[1], t[3], b[3];
    basis_about(g->axis, t, b);
    for (int i = 0; i < 3; ++i)
        v[i] = sin_t * (cos(phi) * t[i] + sin(phi) * b[i]) + cos_t * g->axis[i];
}

void sg_axis_from_gnomonic(double a, double b, double axis[3], double d_axis[6])
{
    double inv = 1.0 / sqrt(1.0 + a * a + b * b);
    axis[0] = a * inv;
    axis[1] = b * inv;
    axis[2] = inv;
    if (!d_axis)
        return;
    double inv3 = inv * inv * inv; /* d inv / da = -a inv^3 */
    d_axis[0] = inv - a * a * inv3;
    d_axis[1] = -a * b * inv3;
    d_axis[2] = -a * inv3;
    d_axis[3] = -a * b * inv3;
    d_axis[4] = inv - b * b * inv3;
    d_axis[5] = -b * inv3;
}
