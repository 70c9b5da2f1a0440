/* GTAO multi-bounce (Jimenez et al. 2016, "Multiple Bounces" to "Shader
 * Code"); see multibounce.h for the formula and the correction of the
 * slide's coefficient naming. The formula itself is multibounce/multibounce.inc,
 * compiled here in double, and embedded in the generated shaders. */
#include "multibounce/multibounce.h"

#include <math.h>

/* The C dialect of multibounce/multibounce.inc: double throughout, C's fmax for
 * the max. */
#define MB_FN static inline
typedef double mb_real;
typedef double mb_color;
static inline double mb_max(double y, double x) { return fmax(x, y); }
#include "multibounce/multibounce.inc"

multibounce_model multibounce_model_jimenez2016(void)
{
    /* GTAOMultiBounce in the talk's shader code: a = 2.0404 * albedo - 0.3324 etc. */
    multibounce_model m = {.degree = 1,
                           .a = {-0.3324, 2.0404, 0.0},
                           .b = {0.6417, -4.7951, 0.0},
                           .c = {0.6903, 2.7552, 0.0}};
    return m;
}

/* sum_k coef[k] rho^k by Horner's rule (degree 0 .. MULTIBOUNCE_MAX_DEGREE = 2). */
static double polynomial(const double *coef, int degree, double rho)
{
    return degree == 0 ? coef[0] : degree == 1 ? mb_rho_linear(coef[0], coef[1], rho)
                                               : mb_rho_quadratic(coef[0], coef[1], coef[2], rho);
}

multibounce_cubic multibounce_cubic_at(const multibounce_model *model, double albedo)
{
    multibounce_cubic c = {polynomial(model->a, model->degree, albedo), polynomial(model->b, model->degree, albedo),
                           polynomial(model->c, model->degree, albedo)};
    return c;
}

double multibounce_cubic_eval(const multibounce_cubic *cubic, double visibility)
{
    return mb_cubic(cubic->a, cubic->b, cubic->c, visibility);
}

void multibounce_cubic_basis(double visibility, double basis[3])
{
    double x = visibility;
    basis[0] = x * x * x;
    basis[1] = x * x;
    basis[2] = x;
}

int multibounce_model_parameter_count(int degree) { return 3 * (degree + 1); }

void multibounce_model_to_vector(const multibounce_model *model, double *params)
{
    int n = model->degree + 1;
    for (int k = 0; k < n; ++k) {
        params[k] = model->a[k];
        params[n + k] = model->b[k];
        params[2 * n + k] = model->c[k];
    }
}

multibounce_model multibounce_model_from_vector(int degree, const double *params)
{
    multibounce_model m = {.degree = degree};
    int n = degree + 1;
    for (int k = 0; k < n; ++k) {
        m.a[k] = params[k];
        m.b[k] = params[n + k];
        m.c[k] = params[2 * n + k];
    }
    return m;
}

void multibounce_model_gradient(int degree, double visibility, double albedo, double *gradient)
{
    double basis[3];
    multibounce_cubic_basis(visibility, basis);
    int n = degree + 1;
    double power = 1.0;
    for (int k = 0; k < n; ++k, power *= albedo)
        for (int term = 0; term < 3; ++term)
            gradient[term * n + k] = basis[term] * power;
}

multibounce_model multibounce_model_anchored(const double p[MULTIBOUNCE_ANCHORED_PARAMETERS])
{
    /* V (1 - V)(P + Q V) = P V + (Q - P) V^2 - Q V^3 with P = p1 rho + p2 rho^2, Q likewise. */
    const double p1 = p[0], q1 = p[1], p2 = p[2], q2 = p[3];
    multibounce_model m = {.degree = 2,
                           .a = {0.0, -q1, -q2},
                           .b = {0.0, q1 - p1, q2 - p2},
                           .c = {1.0, p1, p2}};
    return m;
}

double multibounce_constrained_g(const double s[MULTIBOUNCE_CONSTRAINED_PARAMETERS], double visibility,
                                 double albedo)
{
    const double x = visibility, r = albedo;
    return (1.0 - x) * ((1.0 - r) * s[0] * s[0] + r * s[1] * s[1]) + x * ((1.0 - r) * s[2] * s[2] + r * s[3] * s[3]);
}

double multibounce_constrained_eval(const double s[MULTIBOUNCE_CONSTRAINED_PARAMETERS], double visibility,
                                    double albedo)
{
    const double x = visibility;
    return x + x * (1.0 - x) * multibounce_constrained_g(s, x, albedo);
}

multibounce_model multibounce_model_constrained(const double s[MULTIBOUNCE_CONSTRAINED_PARAMETERS])
{
    /* x (1 - x)(P + (R - P) x) = P x + (R - 2P) x^2 + (P - R) x^3, P = P0 + (P1 - P0) rho, R likewise. */
    const double p0 = s[0] * s[0], p1 = s[1] * s[1], r0 = s[2] * s[2], r1 = s[3] * s[3];
    multibounce_model m = {.degree = 1,
                           .a = {p0 - r0, (p1 - p0) - (r1 - r0)},
                           .b = {r0 - 2.0 * p0, (r1 - r0) - 2.0 * (p1 - p0)},
                           .c = {1.0 + p0, p1 - p0}};
    return m;
}

double gtao_multibounce(const multibounce_model *model, double visibility, double albedo)
{
    multibounce_cubic c = multibounce_cubic_at(model, albedo);
    return mb_multibounce(c.a, c.b, c.c, visibility);
}
