/* Spherical Gaussians (SG): the lobe basis of Wang et al. 2009, "All-
 * Frequency Rendering of Dynamic, Spatially-Varying Reflectance" ([WRGSG09]
 * of Kaplanyan's CryENGINE 3 talk, SIGGRAPH 2010), with unit axis p,
 * sharpness lambda > 0 and amplitude mu:
 *
 *   G(v; p, lambda, mu) = mu exp(lambda (v.p - 1))                     (WRGSG09 eq. 3)
 *
 * Integrals (v over the unit sphere S^2, t = v.p, dv = 2 pi dt about p):
 *
 *   int_S2 G dv           = 2 pi mu / lambda (1 - exp(-2 lambda))
 *   int_S2 G max(0, v.p) dv = 2 pi mu (lambda - 1 + exp(-lambda)) / lambda^2
 *                            (= 2 pi mu int_0^1 t exp(lambda (t - 1)) dt: the
 *                            projected-area integral of a lobe whose axis is the
 *                            normal; for other axes gtlab integrates by
 *                            quadrature, sg_projected_area_integral)
 *
 * Directions are doubles in the local frame of the surface (n = +z). */
#ifndef GTLAB_CORE_OPTICS_SPHERICAL_GAUSSIAN_H
#define GTLAB_CORE_OPTICS_SPHERICAL_GAUSSIAN_H

#include <math.h>

/* Strict C11 <math.h> does not define it. */
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef struct {
    double axis[3];   /* unit vector p */
    double sharpness; /* lambda > 0 */
    double amplitude; /* mu */
} spherical_gaussian;

/* G(v) for a unit direction v. */
double sg_evaluate(const spherical_gaussian *g, const double v[3]);

/* The sum of count lobes at v. */
double sg_sum_evaluate(const spherical_gaussian *lobes, int count, const double v[3]);

/* int over S^2 of G: 2 pi mu / lambda (1 - exp(-2 lambda)), with expm1 for
 * small lambda (the limit lambda -> 0 is 4 pi mu). */
double sg_sphere_integral(double sharpness, double amplitude);

/* int over S^2 of G max(0, v.p): 2 pi mu (lambda - 1 + exp(-lambda)) / lambda^2. */
double sg_axial_cosine_integral(double sharpness, double amplitude);

/* int over the upper hemisphere (v.z > 0) of G(v) v.z, any axis, by a
 * product Gauss-Legendre rule in (cos theta, phi) fine enough for lambda
 * up to ~1e4 (adaptive in theta about the axis' elevation). */
double sg_projected_area_integral(const spherical_gaussian *g);

/* A direction v with density G(v) / int_S2 G over the whole sphere, from u
 * in [0, 1)^2: v.p = 1 + log(1 - u0 (1 - exp(-2 lambda))) / lambda, the
 * azimuth about p 2 pi u1 (the inverse CDF of exp(lambda (t - 1)) on
 * t in [-1, 1]; Jakob 2012, "Numerically stable sampling of the von
 * Mises-Fisher distribution on S^2"). */
void sg_sample(const spherical_gaussian *g, const double u[2], double v[3]);

/* The unit axis of gnomonic coordinates (a, b) about n = +z:
 * (a, b, 1) / sqrt(1 + a^2 + b^2); a = tan theta cos phi, b = tan theta sin phi.
 * The fit parametrises axes so: smooth at the normal, where (theta, phi)
 * is singular. d_axis (may be NULL) receives d axis / da (0..2) and d axis / db (3..5). */
void sg_axis_from_gnomonic(double a, double b, double axis[3], double d_axis[6]);

#endif
