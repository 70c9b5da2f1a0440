/* Adaptive Gauss-Kronrod quadrature (7-point Gauss / 15-point Kronrod, the
 * rule of QUADPACK's qk15, Piessens et al. 1983): an interval is accepted
 * when |K15 - G7| is within its share of the tolerance (or at 1e-9 of the
 * interval's integral, the level of rounding), else bisected. The
 * LUT generators integrate with it, and the tests check their tables with
 * it in other coordinates. */
#ifndef GTLAB_CORE_QUADRATURE_H
#define GTLAB_CORE_QUADRATURE_H

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

#endif
