/* Adaptive Gauss-Kronrod quadrature (7-point Gauss / 15-point Kronrod, the
 * rule of QUADPACK's qk15, Piessens et al. 1983): an interval is accepted
 * when |K15 - G7| is within its share of the tolerance (or at 1e-9 of the
 * interval's integral, the level of rounding), else bisected. The
 * LUT generators integrate with it, and the tests check their tables with
 * it in other coordinates. */
#ifndef GTLAB_CORE_SAMPLING_QUADRATURE_H
#define GTLAB_CORE_SAMPLING_QUADRATURE_H

typedef double (*quadrature_fn)(double x, void *ctx);

/* The integral of f over [a, b] to about abs_tol (absolute). *error, if not
 * NULL, receives the sum of the accepted intervals' |K15 - G7| estimates (an
 * upper bound in practice: K15 is far more accurate than G7). */
double quadrature_gk15(quadrature_fn f, void *ctx, double a, double b, double abs_tol, double *error);

/* The same over [points[0], points[count-1]] split at the given increasing
 * points (kinks, or the scales of a peaked integrand), the tolerance shared
 * equally between the pieces. */
double quadrature_gk15_split(quadrature_fn f, void *ctx, const double *points, int count, double abs_tol,
                             double *error);

/* Several integrands evaluated together (they share their costly parts, e.g.
 * the transmittance of every species and channel): f(x, ctx, values)
 * writes `count` <= QUADRATURE_MAX_COMPONENTS values. The same rule and
 * bisection as above, over [points[0], points[n-1]] split at the given
 * points; an interval is accepted when every component's |K15 - G7| is
 * within its share of abs_tol[k] (or at the rounding level of its integral),
 * so each component meets its own tolerance. result[k] and error[k] (may be
 * NULL) as above, per component. */
enum { QUADRATURE_MAX_COMPONENTS = 16 };
typedef void (*quadrature_vector_fn)(double x, void *ctx, double *values);
void quadrature_gk15_vector_split(quadrature_vector_fn f, void *ctx, int count, const double *points, int n,
                                  const double *abs_tol, double *result, double *error);

#endif
