/* GTAO multi-bounce: single-bounce visibility V_d to multi-bounce V'_d.
 * Jimenez, Wu, Pesce, Jarabo, "Practical Realtime Strategies for Accurate
 * Indirect Occlusion", SIGGRAPH 2016 (seeds/001_*.txt), slides "Fitting for
 * a Fixed Albedo" to "Shader Code":
 *
 *     V'_d = max(V_d, ((a V_d + b) V_d + c) V_d),
 *     a = a1 rho + a0,  b = b1 rho + b0,  c = c1 rho + c0.
 *
 * Here the coefficients a, b, c may be polynomials of any degree up to
 * MULTIBOUNCE_MAX_DEGREE in the albedo rho (degree 1 is the talk's model;
 * degree 0 is one albedo's cubic), so the fitters, the tests and the
 * real-time code all evaluate this one formula. Its text is
 * multibounce/multibounce.inc, compiled here in double and embedded in the C
 * header and HLSL/GLSL that multibounce/multibounce_shader.h writes. Correction to the talk's
 * text: its slide writes "a = a0 + a1 rho" beside a Mathematica listing
 * {a, {x0 -> 2.0404, x1 -> -0.332404}}, which read that way would make
 * 2.0404 the constant term; the shader code (a = 2.0404 * albedo - 0.3324)
 * takes it as the slope. The shader is right: only then is
 * a + b + c = 0.0005 rho + 0.9996 ~ 1, i.e. V'_d(1) = 1 (an unoccluded
 * point sees the white dome whatever its albedo); read the other way
 * V'_d(1) would be ~rho. The tests check this. */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_H

enum { MULTIBOUNCE_MAX_DEGREE = 2, MULTIBOUNCE_MAX_PARAMETERS = 3 * (MULTIBOUNCE_MAX_DEGREE + 1) };

/* The cubic of one albedo: V'_d = ((a x + b) x + c) x. */
typedef struct {
    double a, b, c;
} multibounce_cubic;

/* The joint model: a = sum_k a[k] rho^k, k = 0 .. degree (likewise b, c). */
typedef struct {
    int degree; /* 0 .. MULTIBOUNCE_MAX_DEGREE */
    double a[MULTIBOUNCE_MAX_DEGREE + 1], b[MULTIBOUNCE_MAX_DEGREE + 1], c[MULTIBOUNCE_MAX_DEGREE + 1];
} multibounce_model;

/* The talk's published coefficients (shader code slide): a comparison, never
 * an output of gtlab. */
multibounce_model multibounce_model_jimenez2016(void);

/* The cubic of `model` at albedo rho. */
multibounce_cubic multibounce_cubic_at(const multibounce_model *model, double albedo);

/* ((a x + b) x + c) x, without the max: what the fit models. */
double multibounce_cubic_eval(const multibounce_cubic *cubic, double visibility);

/* d V'_d / d(a, b, c) = (x^3, x^2, x): the cubic is linear in its
 * coefficients, and a joint model's parameter a[k] has derivative
 * rho^k x^3 (multibounce_model_gradient). */
void multibounce_cubic_basis(double visibility, double basis[3]);

/* Parameters of a model as one vector (a[0..d], b[0..d], c[0..d]), the
 * order of the fits, and back. Returns the parameter count 3 (d + 1). */
int multibounce_model_parameter_count(int degree);
void multibounce_model_to_vector(const multibounce_model *model, double *params);
multibounce_model multibounce_model_from_vector(int degree, const double *params);

/* d (cubic without max) / d params at (visibility, albedo), in the vector order above. */
void multibounce_model_gradient(int degree, double visibility, double albedo, double *gradient);

/* The anchored form (gtlab's, not the talk's): the cubic written as
 *     V'_d = V_d + V_d (1 - V_d) (rho (p1 + q1 V_d) + rho^2 (p2 + q2 V_d)),
 * i.e. a = -(q1 rho + q2 rho^2), b = (q1 - p1) rho + (q2 - p2) rho^2,
 * c = 1 + p1 rho + p2 rho^2. It holds by construction what the physics
 * fixes and the talk's coefficients only approach: V'_d = V_d at rho = 0
 * (no bounce light), V'_d(0) = 0 and V'_d(1) = 1 (an unoccluded point sees
 * the dome) at every albedo. p = {p1, q1, p2, q2}. */
enum { MULTIBOUNCE_ANCHORED_PARAMETERS = 4 };
multibounce_model multibounce_model_anchored(const double p[MULTIBOUNCE_ANCHORED_PARAMETERS]);

/* The constrained form (gtlab's; issue 25, item 4): the talk's model (a, b,
 * c linear in rho) restricted to the cubics with V'_d(1) = 1 and
 * V'_d >= V_d for every V_d and rho in [0, 1], so that the shader's
 * max(V_d, .) never binds. Every such cubic is
 *     V'_d = V_d + V_d (1 - V_d) g(V_d, rho),
 * g bilinear in (V_d, rho) with non-negative values at the four corners of
 * the unit square (a bilinear g is >= 0 on the square iff it is at the
 * corners), and conversely. Written with the corner values as squares,
 *     g = (1-x)(1-rho) s00^2 + (1-x) rho s01^2 + x (1-rho) s10^2 + x rho s11^2,
 * the constraints hold for any s by construction: x (1 - x) g >= 0, and the
 * term vanishes at x = 1 (exactly, in floating point too). With P(rho) =
 * g(0, rho), R(rho) = g(1, rho): a = P - R, b = R - 2P, c = 1 + P.
 * s = {s00, s01, s10, s11}. */
enum { MULTIBOUNCE_CONSTRAINED_PARAMETERS = 4 };
/* g(x, rho) of the form above. */
double multibounce_constrained_g(const double s[MULTIBOUNCE_CONSTRAINED_PARAMETERS], double visibility,
                                 double albedo);
/* V'_d = x + x (1 - x) g(x, rho): the form in which the constraints are exact. */
double multibounce_constrained_eval(const double s[MULTIBOUNCE_CONSTRAINED_PARAMETERS], double visibility,
                                    double albedo);
/* The same cubic as a degree-1 model (a, b, c linear in rho; equal to the
 * form above up to rounding). */
multibounce_model multibounce_model_constrained(const double s[MULTIBOUNCE_CONSTRAINED_PARAMETERS]);

/* GTAOMultiBounce(visibility, albedo) of the talk with any coefficients:
 * max(x, cubic(x)). The max keeps V'_d >= V_d, which the physics guarantees
 * (a bounce only adds light) and a fitted cubic need not. */
double gtao_multibounce(const multibounce_model *model, double visibility, double albedo);

#endif
