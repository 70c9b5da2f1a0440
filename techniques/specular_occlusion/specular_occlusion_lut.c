/* The GTSO cone/lobe LUT (Jimenez et al. 2016, slides "Intersection with
 * Accurate Reflection Lobes"): generator, axis parametrisations and the
 * trilinear lookup a shader would do. See the header for the integral, the
 * lobe at normal incidence and the quadrature. */
#include "specular_occlusion/specular_occlusion_lut.h"

#include <math.h>
#include <stdlib.h>

#include "core/optics/ggx.h"
#include "core/optics/phong.h"
#include "core/sampling/quadrature.h"
#include "core/sampling/splitmix64.h"
#include "core/vec3.h" /* M_PI */

enum { MAX_BREAKS = 40 };
static const double QUADRATURE_TOLERANCE = 1e-8; /* absolute, on V_s (and relative on the normaliser) */

const char *so_lobe_name(so_lobe lobe)
{
    static const char *const names[SO_LOBE_COUNT] = {"ggx", "ggx-d", "phong"};
    return (int)lobe >= 0 && lobe < SO_LOBE_COUNT ? names[lobe] : "unknown";
}

const char *so_lut_axes_name(so_lut_axes axes)
{
    static const char *const names[SO_AXES_COUNT] = {"cosines", "angles"};
    return (int)axes >= 0 && axes < SO_AXES_COUNT ? names[axes] : "unknown";
}

const char *so_lut_axes_description(so_lut_axes axes)
{
    return axes == SO_AXES_COSINES
               ? "V_s(a_v, beta, r) at data[(k*N + j)*N + i]; grid point index/(N-1) along each axis; "
                 "i: t = cos(a_v), a_v = visibility cone half-angle in [0, pi/2]; "
                 "j: t = 0.5*cos(beta) + 0.5, beta = angle between bent normal and reflection vector in [0, pi]; "
                 "k: t = r, perceptual roughness in [0, 1] (GGX alpha = r^2)"
               : "V_s(a_v, beta, r) at data[(k*N + j)*N + i]; grid point index/(N-1) along each axis; "
                 "i: t = a_v / (pi/2), a_v = visibility cone half-angle in [0, pi/2]; "
                 "j: t = beta / pi, beta = angle between bent normal and reflection vector in [0, pi]; "
                 "k: t = r, perceptual roughness in [0, 1] (GGX alpha = r^2)";
}

/* alpha >= 1e-3 (core/optics/ggx.h says why). */
static double lobe_alpha(double roughness) { return ggx_alpha_tabulated(roughness); }

double so_lobe_value(so_lobe lobe, double c, double roughness)
{
    if (c <= 0.0)
        return 0.0;
    double alpha = lobe_alpha(roughness), ch = sqrt(0.5 * (1.0 + c)); /* n.h with n = R: cos(theta / 2) */
    switch (lobe) {
    case SO_LOBE_GGX: return ggx_ndf(ch, alpha) * ggx_smith_g2(1.0, c, alpha) / 4.0;
    case SO_LOBE_GGX_D: return ggx_ndf(ch, alpha) * c;
    case SO_LOBE_PHONG: return phong_ndf(ch, phong_exponent(alpha)) * c;
    default: return 0.0;
    }
}

typedef struct {
    so_lobe lobe;
    double roughness, cos_av, cos_beta, sin_beta;
} lobe_integrand;

/* Length of the arc of the circle at angle theta from R inside the cone. */
static double arc_inside(const lobe_integrand *q, double theta)
{
    double s = sin(theta) * q->sin_beta, num = q->cos_av - cos(theta) * q->cos_beta;
    if (s <= 1e-300)
        return num <= 0.0 ? 2.0 * M_PI : 0.0;
    double c = num / s;
    return c <= -1.0 ? 2.0 * M_PI : c >= 1.0 ? 0.0 : 2.0 * acos(c);
}

static double full_circle(double theta, void *ctx)
{
    const lobe_integrand *q = ctx;
    return so_lobe_value(q->lobe, cos(theta), q->roughness) * sin(theta) * 2.0 * M_PI;
}

static double inside_cone(double theta, void *ctx)
{
    const lobe_integrand *q = ctx;
    double arc = arc_inside(q, theta);
    return arc > 0.0 ? so_lobe_value(q->lobe, cos(theta), q->roughness) * sin(theta) * arc : 0.0;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Break points in [0, pi/2]: the lobe's scale 2 alpha 2^k and the given kinks. */
static int break_points(double roughness, const double *kinks, int kink_count, double *points)
{
    int n = 0;
    points[n++] = 0.0;
    points[n++] = 0.5 * M_PI;
    for (double s = 0.25 * lobe_alpha(roughness); s < 0.5 * M_PI && n < MAX_BREAKS - kink_count; s *= 2.0)
        points[n++] = s;
    for (int i = 0; i < kink_count; ++i)
        if (kinks[i] > 0.0 && kinks[i] < 0.5 * M_PI)
            points[n++] = kinks[i];
    qsort(points, (size_t)n, sizeof *points, compare_doubles);
    return n;
}

double so_lobe_normaliser(so_lobe lobe, double roughness)
{
    lobe_integrand q = {lobe, roughness, 0.0, 1.0, 0.0};
    double points[MAX_BREAKS];
    int n = break_points(roughness, NULL, 0, points);
    return quadrature_gk15_split(full_circle, &q, points, n, 1e-3 * QUADRATURE_TOLERANCE, NULL);
}

double so_cone_lobe(so_lobe lobe, double alpha_v, double beta, double roughness, double normaliser, double *error)
{
    lobe_integrand q = {lobe, roughness, cos(alpha_v), cos(beta), sin(beta)};
    double kinks[2] = {fabs(alpha_v - beta), alpha_v + beta}, points[MAX_BREAKS], err = 0.0;
    int n = break_points(roughness, kinks, 2, points);
    double value = quadrature_gk15_split(inside_cone, &q, points, n, QUADRATURE_TOLERANCE * normaliser, &err);
    if (error)
        *error = err / normaliser;
    return fmin(1.0, fmax(0.0, value / normaliser));
}

void so_lut_coordinates(so_lut_axes axes, double alpha_v, double beta, double roughness, double t[3])
{
    if (axes == SO_AXES_COSINES) {
        t[0] = cos(alpha_v), t[1] = 0.5 * cos(beta) + 0.5;
    } else {
        t[0] = alpha_v / (0.5 * M_PI), t[1] = beta / M_PI;
    }
    t[2] = roughness;
}

void so_lut_point(so_lut_axes axes, const double t[3], double *alpha_v, double *beta, double *roughness)
{
    if (axes == SO_AXES_COSINES) {
        *alpha_v = acos(fmax(-1.0, fmin(1.0, t[0])));
        *beta = acos(fmax(-1.0, fmin(1.0, 2.0 * t[1] - 1.0)));
    } else {
        *alpha_v = t[0] * 0.5 * M_PI, *beta = t[1] * M_PI;
    }
    *roughness = t[2];
}

int so_lut_build(so_lut *lut, int size, so_lobe lobe, so_lut_axes axes, int threads)
{
    lut->size = size, lut->lobe = lobe, lut->axes = axes, lut->max_error_estimate = 0.0, lut->bc4 = 0;
    lut->data = malloc(sizeof *lut->data * (size_t)size * (size_t)size * (size_t)size);
    double *normalisers = malloc(sizeof *normalisers * (size_t)size);
    if (!lut->data || !normalisers) {
        free(normalisers);
        so_lut_free(lut);
        return -1;
    }
    double step = 1.0 / (size - 1), max_error = 0.0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int k = 0; k < size; ++k)
        normalisers[k] = so_lobe_normaliser(lobe, k * step);
#pragma omp parallel for collapse(2) schedule(dynamic, 1) num_threads(threads) reduction(max : max_error)
    for (int k = 0; k < size; ++k)
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i) {
                double t[3] = {i * step, j * step, k * step}, av, beta, r, err;
                so_lut_point(axes, t, &av, &beta, &r);
                lut->data[((size_t)k * size + j) * size + i] = (float)so_cone_lobe(lobe, av, beta, r, normalisers[k], &err);
                max_error = fmax(max_error, err);
            }
    lut->max_error_estimate = max_error;
    free(normalisers);
    return 0;
}

void so_lut_free(so_lut *lut)
{
    free(lut->data);
    lut->data = NULL;
}

double so_lut_lookup(const so_lut *lut, double alpha_v, double beta, double roughness)
{
    double t[3];
    int base[3], n = lut->size;
    double frac[3];
    so_lut_coordinates(lut->axes, alpha_v, beta, roughness, t);
    for (int a = 0; a < 3; ++a) {
        double x = fmin(1.0, fmax(0.0, t[a])) * (n - 1);
        base[a] = (int)fmin(floor(x), n - 2);
        frac[a] = x - base[a];
    }
    double value = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        int di = corner & 1, dj = (corner >> 1) & 1, dk = corner >> 2;
        double w = (di ? frac[0] : 1.0 - frac[0]) * (dj ? frac[1] : 1.0 - frac[1]) * (dk ? frac[2] : 1.0 - frac[2]);
        value += w * lut->data[((size_t)(base[2] + dk) * n + base[1] + dj) * n + base[0] + di];
    }
    return value;
}

/* The lookup's error at random point s (its own generator state). */
static double interpolation_error_at(const so_lut *lut, unsigned seed, int s)
{
    unsigned long long state = ((unsigned long long)seed << 32) ^ (unsigned long long)s;
    double t[3] = {splitmix64_uniform01(&state), splitmix64_uniform01(&state), splitmix64_uniform01(&state)}, av, beta, r;
    so_lut_point(lut->axes, t, &av, &beta, &r);
    double exact = so_cone_lobe(lut->lobe, av, beta, r, so_lobe_normaliser(lut->lobe, r), NULL);
    return fabs(so_lut_lookup(lut, av, beta, r) - exact);
}

/* The points are evaluated in parallel, then summed in their order, so the
 * RMS does not depend on the thread count (a reduction's order would). */
void so_lut_interpolation_error(const so_lut *lut, int count, unsigned seed, int threads, double *max_error,
                                double *rms_error)
{
    double *errors = malloc(sizeof *errors * (size_t)(count > 0 ? count : 1));
    double max_e = 0.0, sum_sq = 0.0;
    if (!errors) {
        *max_error = *rms_error = NAN;
        return;
    }
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
    for (int s = 0; s < count; ++s)
        errors[s] = interpolation_error_at(lut, seed, s);
    for (int s = 0; s < count; ++s) {
        max_e = fmax(max_e, errors[s]);
        sum_sq += errors[s] * errors[s];
    }
    free(errors);
    *max_error = max_e;
    *rms_error = sqrt(sum_sq / count);
}
