#include "core/sampling/quadrature.h"

#include <math.h>

/* Kronrod nodes (the odd indices are the 7-point Gauss nodes) and weights. */
static const double xgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                              0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                              0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                              0.207784955007898467600689403773245, 0.0};
static const double wgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                              0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                              0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                              0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                             0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

/* Bisection stops at depth 30 or when |K15 - G7| is at the level of
 * the integrand's own rounding noise (a tolerance below that cannot be
 * met; GGX D from n.h near 1 carries ~1e-9 relative noise). */
enum { MAX_DEPTH = 30 };
static const double ROUNDING_LEVEL = 1e-9;

static double rule(quadrature_fn f, void *ctx, double a, double b, double *gauss)
{
    double centre = 0.5 * (a + b), half = 0.5 * (b - a);
    double fc = f(centre, ctx);
    double k = wgk[7] * fc, g = wg[3] * fc;
    for (int j = 0; j < 7; ++j) {
        double dx = half * xgk[j];
        double sum = f(centre - dx, ctx) + f(centre + dx, ctx);
        k += wgk[j] * sum;
        if (j & 1)
            g += wg[j / 2] * sum;
    }
    *gauss = g * half;
    return k * half;
}

static double adapt(quadrature_fn f, void *ctx, double a, double b, double tol, int depth, double *error)
{
    double g, k = rule(f, ctx, a, b, &g);
    double estimate = fabs(k - g);
    if (estimate <= tol || estimate <= ROUNDING_LEVEL * fabs(k) || depth >= MAX_DEPTH || !(b > a)) {
        *error += estimate;
        return k;
    }
    double mid = 0.5 * (a + b);
    return adapt(f, ctx, a, mid, 0.5 * tol, depth + 1, error) + adapt(f, ctx, mid, b, 0.5 * tol, depth + 1, error);
}

double quadrature_gk15(quadrature_fn f, void *ctx, double a, double b, double abs_tol, double *error)
{
    double local = 0.0;
    double result = adapt(f, ctx, a, b, abs_tol, 0, &local);
    if (error)
        *error = local;
    return result;
}

double quadrature_gk15_split(quadrature_fn f, void *ctx, const double *points, int count, double abs_tol,
                             double *error)
{
    double total = 0.0, local = 0.0;
    for (int i = 0; i + 1 < count; ++i) {
        double a = points[i], b = points[i + 1];
        if (b > a)
            total += adapt(f, ctx, a, b, abs_tol / (count - 1), 0, &local);
    }
    if (error)
        *error = local;
    return total;
}

/* ---- Several components at once ------------------------------------------ */

typedef struct {
    quadrature_vector_fn f;
    void *ctx;
    int count;
} vector_problem;

/* K15 into k[], G7 into g[], on [a, b]. */
static void vector_rule(const vector_problem *q, double a, double b, double *k, double *g)
{
    double centre = 0.5 * (a + b), half = 0.5 * (b - a), lo[QUADRATURE_MAX_COMPONENTS], hi[QUADRATURE_MAX_COMPONENTS];
    q->f(centre, q->ctx, lo);
    for (int c = 0; c < q->count; ++c)
        k[c] = wgk[7] * lo[c], g[c] = wg[3] * lo[c];
    for (int j = 0; j < 7; ++j) {
        q->f(centre - half * xgk[j], q->ctx, lo);
        q->f(centre + half * xgk[j], q->ctx, hi);
        for (int c = 0; c < q->count; ++c) {
            k[c] += wgk[j] * (lo[c] + hi[c]);
            g[c] += (j & 1) ? wg[j / 2] * (lo[c] + hi[c]) : 0.0;
        }
    }
    for (int c = 0; c < q->count; ++c)
        k[c] *= half, g[c] *= half;
}

static void vector_adapt(const vector_problem *q, double a, double b, const double *tol, int depth, double *sum,
                         double *error)
{
    double k[QUADRATURE_MAX_COMPONENTS], g[QUADRATURE_MAX_COMPONENTS];
    vector_rule(q, a, b, k, g);
    int refine = 0;
    for (int c = 0; c < q->count; ++c) {
        double estimate = fabs(k[c] - g[c]);
        refine |= !(estimate <= tol[c] || estimate <= ROUNDING_LEVEL * fabs(k[c]));
    }
    if (!refine || depth >= MAX_DEPTH || !(b > a)) {
        for (int c = 0; c < q->count; ++c)
            sum[c] += k[c], error[c] += fabs(k[c] - g[c]);
        return;
    }
    double half_tol[QUADRATURE_MAX_COMPONENTS], mid = 0.5 * (a + b);
    for (int c = 0; c < q->count; ++c)
        half_tol[c] = 0.5 * tol[c];
    vector_adapt(q, a, mid, half_tol, depth + 1, sum, error);
    vector_adapt(q, mid, b, half_tol, depth + 1, sum, error);
}

void quadrature_gk15_vector_split(quadrature_vector_fn f, void *ctx, int count, const double *points, int n,
                                  const double *abs_tol, double *result, double *error)
{
    vector_problem q = {f, ctx, count};
    double tol[QUADRATURE_MAX_COMPONENTS], local[QUADRATURE_MAX_COMPONENTS];
    for (int c = 0; c < count; ++c)
        tol[c] = abs_tol[c] / (n - 1), result[c] = 0.0, local[c] = 0.0;
    for (int i = 0; i + 1 < n; ++i)
        if (points[i + 1] > points[i])
            vector_adapt(&q, points[i], points[i + 1], tol, 0, result, local);
    for (int c = 0; error && c < count; ++c)
        error[c] = local[c];
}
