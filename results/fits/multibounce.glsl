// GTAO multi-bounce, refitted by gtlab 0.1.0:
//   gtlab all --quality preview
// Same form as GTAOMultiBounce (Jimenez et al. 2016), new coefficients. Generated file.
// The formula is techniques/multibounce/multibounce.inc, the very text gtlab compiles as C, behind the
// definitions below.

#define MB_FN
#define mb_real float
#define mb_color vec3
#define mb_max max

/* GTAOMultiBounce (Jimenez et al. 2016, "Shader Code";
 * techniques/multibounce/multibounce.h has the formula and the reading of the
 * talk's coefficients), written once, in the common subset of C, HLSL and GLSL:
 *     V'_d = max(V_d, ((a V_d + b) V_d + c) V_d),
 * a, b, c polynomials in the albedo rho of degree 1 or 2.
 * techniques/multibounce/multibounce.c compiles this file as C in double (its
 * dialect is at its top); the build embeds the very same text in the C header
 * and the HLSL/GLSL functions gtlab writes
 * (techniques/multibounce/multibounce_shader.c: their dialects, float and
 * float3/vec3), so the formula exists nowhere else.
 *
 * The dialect defines:
 *   MB_FN              qualifiers of a function (C: static inline)
 *   mb_real            a coefficient and the visibility (C: double; the generated code: float)
 *   mb_color           the albedo and V'_d (C: double; shaders: float3/vec3)
 *   mb_max(y, x)       the larger of a colour y and the visibility x (C: fmax(x, y)) */

/* A coefficient linear in the albedo: k0 + k1 rho. */
MB_FN mb_color mb_rho_linear(mb_real k0, mb_real k1, mb_color rho)
{
    return rho * k1 + k0;
}

/* A coefficient quadratic in the albedo, by Horner's rule: k0 + rho (k1 + rho k2). */
MB_FN mb_color mb_rho_quadratic(mb_real k0, mb_real k1, mb_real k2, mb_color rho)
{
    return mb_rho_linear(k1, k2, rho) * rho + k0;
}

/* The cubic ((a x + b) x + c) x without the max: what the fits model. */
MB_FN mb_color mb_cubic(mb_color a, mb_color b, mb_color c, mb_real x)
{
    return ((a * x + b) * x + c) * x;
}

/* GTAOMultiBounce: max(x, cubic(x)). The max keeps V'_d >= V_d, which the
 * physics guarantees (a bounce only adds light) and a fitted cubic need not. */
MB_FN mb_color mb_multibounce(mb_color a, mb_color b, mb_color c, mb_real x)
{
    return mb_max(mb_cubic(a, b, c, x), x);
}

// a, b, c linear in the albedo (the talk's form); weighted RMSE 0.0327 on the data.
vec3 GTAOMultiBounce(float visibility, vec3 albedo)
{
    vec3 a = mb_rho_linear(-0.408535167f, 2.35962356f, albedo);
    vec3 b = mb_rho_linear(0.754530377f, -5.28282176f, albedo);
    vec3 c = mb_rho_linear(0.650220594f, 2.92940149f, albedo);
    return mb_multibounce(a, b, c, visibility);
}

// a, b, c quadratic in the albedo; weighted RMSE 0.0308 on the data.
vec3 GTAOMultiBounceQuadratic(float visibility, vec3 albedo)
{
    vec3 a = mb_rho_quadratic(0.116908795f, -0.577663668f, 2.93377434f, albedo);
    vec3 b = mb_rho_quadratic(-0.200708922f, 0.0570664531f, -5.33350172f, albedo);
    vec3 c = mb_rho_quadratic(1.08467847f, 0.500736434f, 2.42576028f, albedo);
    return mb_multibounce(a, b, c, visibility);
}

// anchored: V_d + V_d (1 - V_d) (albedo (p1 + q1 V_d) + albedo^2 (p2 + q2 V_d)), exact at albedo 0 and V_d = 0, 1; weighted RMSE 0.0309 on the data. Preferred by the leave-one-scene-out test.
vec3 GTAOMultiBounceAnchored(float visibility, vec3 albedo)
{
    vec3 a = mb_rho_quadratic(0.0f, 0.064675288f, 2.2986303f, albedo);
    vec3 b = mb_rho_quadratic(0.0f, -0.977670176f, -4.33928974f, albedo);
    vec3 c = mb_rho_quadratic(1.0f, 0.912994888f, 2.04065944f, albedo);
    return mb_multibounce(a, b, c, visibility);
}
