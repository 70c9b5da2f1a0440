/* GGX and Lambert sphere lights, real-time approximations.
 *
 * - Karis 2013, "Real Shading in Unreal Engine 4" (SIGGRAPH course notes),
 *   "Sphere lights": the representative point and its normalisation.
 * - de Carpentier & Ishiyama, "Decima Engine: Advances in Lighting and AA",
 *   SIGGRAPH 2017 (seeds 000 and 003), "GGX spherical area light", slides
 *   "Bend L to maximise N.H" to "With N.H maximization", and the appendix
 *   "Spherical Area Lighting" (EvaluateSphericalAreaGGX).
 *
 * Correction. Both transcriptions of GetNoHSquared are garbled; this Newton
 * step is derived from the talk's mathematics (docs/decisions.md, "Sphere
 * lights", has the full list of differences). With s = sin(sigma),
 * c = cos(sigma), L(phi) = c lc + s (cos(phi) T + sin(phi) B):
 *   N.(L + V) = no_c + cos(phi) no_t + sin(phi) no_b
 *   1 + V.L   = vo_c + cos(phi) vo_t + sin(phi) vo_b
 *   f(phi)    = (N.H)^2 = (N.(L + V))^2 / (2 (1 + V.L)).
 * With x = tan(phi/2), cos(phi) = (1 - x^2)/(1 + x^2), sin(phi) = 2x/(1 + x^2):
 *   f(x) = n(x)^2 / (2 (1 + x^2) d(x)),
 *   n(x) = n0 + 2 no_b x + (2 no_c - n0) x^2,  n0 = no_c + no_t
 *   d(x) = d0 + 2 vo_b x + (2 vo_c - d0) x^2,  d0 = vo_c + vo_t.
 * Newton from x = 0: x1 = -f'(0)/f''(0) = -g'/(g'' + g'^2) with g = ln f.
 * With p = no_b d0, q = n0 d0, s' = vo_b n0 and both multiplied by q^2/8:
 *   num = -q^2 g'/8          = q (s'/4 - p/2)
 *   den = q^2 (g'' + g'^2)/8 = p^2 + s'(s' - 2p) + n0 (no_c d0^2 - q (d0 + vo_c)/2),
 * which is the talk's xNum and xDenom once its (vo_c - 1) = c V.lc is
 * written out. Tests check x1 against finite differences of f computed with
 * vectors, and (N.H)^2 against the rotated light vector. */
#include "realtime/sphere_light.h"

#include <float.h>
#include <math.h>

#include "core/fresnel.h"
#include "core/ggx.h"

/* A shader's max and saturate are one instruction each; C's fmaxf/fminf
 * are library calls (their NaN rules), which would distort the cost
 * measured by `gtlab bench sphere-light`. */
static inline float max_float(float a, float b) { return a > b ? a : b; }
static inline float saturate(float x) { return x < 0.0f ? 0.0f : x > 1.0f ? 1.0f : x; }

/* The steps are always inlined into the two forms a shader would write
 * (sphere_noh_squared_karis, _decima), so each is one straight function
 * whose instructions can be counted, as in the talk's comparison. */
#define RIM_INLINE static inline __attribute__((always_inline))

RIM_INLINE int rim_setup(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l, sphere_rim *rim)
{
    float radius_cos = 1.0f / sqrtf(1.0f + radius_tan * radius_tan);
    /* R = 2 (N.V) N - V, so R.lc = 2 (N.lc)(N.V) - V.lc. */
    float r_dot_l = 2.0f * n_dot_l * n_dot_v - v_dot_l;
    if (r_dot_l >= radius_cos)
        return 1;
    /* s / |R - (R.lc) lc| scales R - (R.lc) lc to s T. The clamp only keeps
     * R = -lc (T undefined: the light's centre is then below the horizon)
     * from giving NaN. */
    float s_over_len_t = radius_cos * radius_tan / sqrtf(max_float(1.0f - r_dot_l * r_dot_l, FLT_MIN));
    rim->no_t = s_over_len_t * (n_dot_v - r_dot_l * n_dot_l);                  /* N.R = N.V */
    rim->vo_t = s_over_len_t * (2.0f * n_dot_v * n_dot_v - 1.0f - r_dot_l * v_dot_l); /* V.R = 2 (N.V)^2 - 1 */
    /* |det(N, lc, V)| = sqrt of the Gram determinant; B = T x lc up to sign
     * has N.B = |det| / |R - (R.lc) lc| and V.B = 2 (N.V) N.B. */
    float triple = sqrtf(saturate(1.0f - n_dot_l * n_dot_l - n_dot_v * n_dot_v - v_dot_l * v_dot_l +
                                  2.0f * n_dot_l * n_dot_v * v_dot_l));
    rim->no_b = s_over_len_t * triple;
    rim->vo_b = s_over_len_t * (2.0f * triple * n_dot_v);
    rim->no_c = n_dot_l * radius_cos + n_dot_v;
    rim->vo_c = v_dot_l * radius_cos + 1.0f;
    return 0;
}

RIM_INLINE void rim_newton_step(const sphere_rim *rim, float *num, float *den)
{
    float n0 = rim->no_c + rim->no_t, d0 = rim->vo_c + rim->vo_t;
    float p = rim->no_b * d0, q = n0 * d0, s = rim->vo_b * n0;
    *num = q * (-0.5f * p + 0.25f * s);
    *den = p * p + s * (s - 2.0f * p) + n0 * (rim->no_c * d0 * d0 + q * (-0.5f * (d0 + rim->vo_c)));
}

RIM_INLINE void rim_rotate(sphere_rim *rim, float num, float den)
{
    /* cos(phi) = (1 - x^2)/(1 + x^2), sin(phi) = 2x/(1 + x^2), x = num/den,
     * without dividing by den (which may be 0). */
    float len2 = num * num + den * den;
    if (!(len2 > 0.0f))
        return; /* 0/0: no direction to move (a shader would produce NaN) */
    float two_x = 2.0f * num / len2;
    float sin_phi = two_x * den, cos_phi = 1.0f - two_x * num;
    float no_t = rim->no_t, vo_t = rim->vo_t;
    rim->no_t = cos_phi * no_t + sin_phi * rim->no_b;
    rim->vo_t = cos_phi * vo_t + sin_phi * rim->vo_b;
    rim->no_b = cos_phi * rim->no_b - sin_phi * no_t;
    rim->vo_b = cos_phi * rim->vo_b - sin_phi * vo_t;
}

RIM_INLINE float rim_noh_squared(const sphere_rim *rim)
{
    float no_h = rim->no_c + rim->no_t;             /* N.(L + V) */
    float h_dot_h = 2.0f * (rim->vo_c + rim->vo_t); /* |L + V|^2 */
    return max_float(0.0f, no_h * no_h / h_dot_h);
}

int sphere_rim_setup(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l, sphere_rim *rim)
{
    return rim_setup(radius_tan, n_dot_l, n_dot_v, v_dot_l, rim);
}

void sphere_rim_newton_step(const sphere_rim *rim, float *num, float *den) { rim_newton_step(rim, num, den); }

void sphere_rim_rotate(sphere_rim *rim, float num, float den) { rim_rotate(rim, num, den); }

float sphere_noh_squared(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l, int newton_steps)
{
    sphere_rim rim;
    if (rim_setup(radius_tan, n_dot_l, n_dot_v, v_dot_l, &rim))
        return 1.0f;
    for (int i = 0; i < newton_steps; ++i) {
        float num, den;
        rim_newton_step(&rim, &num, &den);
        rim_rotate(&rim, num, den);
    }
    return rim_noh_squared(&rim);
}

float sphere_noh_squared_karis(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l)
{
    sphere_rim rim;
    if (rim_setup(radius_tan, n_dot_l, n_dot_v, v_dot_l, &rim))
        return 1.0f;
    return rim_noh_squared(&rim);
}

float sphere_noh_squared_decima(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l)
{
    sphere_rim rim;
    if (rim_setup(radius_tan, n_dot_l, n_dot_v, v_dot_l, &rim))
        return 1.0f;
    float num, den;
    rim_newton_step(&rim, &num, &den);
    rim_rotate(&rim, num, den);
    return rim_noh_squared(&rim);
}

float sphere_noh_squared_guarded(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l)
{
    sphere_rim rim;
    if (rim_setup(radius_tan, n_dot_l, n_dot_v, v_dot_l, &rim))
        return 1.0f;
    float num, den;
    rim_newton_step(&rim, &num, &den);
    if (den < 0.0f) /* den = (q^2/8) f''(0)/f(0) */
        rim_rotate(&rim, num, den);
    return rim_noh_squared(&rim);
}

vec3 karis_sphere_point(vec3 r, vec3 lc, float sin_sigma)
{
    vec3 centre_to_ray = v3_sub(v3_scale(r, v3_dot(lc, r)), lc);
    float len = v3_length(centre_to_ray);
    float t = len > 0.0f ? saturate(sin_sigma / len) : 0.0f;
    return v3_normalize(v3_add(lc, v3_scale(centre_to_ray, t)));
}

float karis_sphere_normalization(float alpha, float sin_sigma)
{
    float widened = saturate(alpha + 0.5f * sin_sigma);
    float ratio = alpha / widened;
    return ratio * ratio;
}

float karis_sphere_ggx(vec3 v, vec3 lc, float sin_sigma, float alpha)
{
    vec3 r = v3(-v.x, -v.y, v.z); /* reflect(-v, n) with n = +z */
    vec3 l = karis_sphere_point(r, lc, sin_sigma);
    return karis_sphere_normalization(alpha, sin_sigma) * (float)ggx_brdf(v, l, alpha) * saturate(l.z);
}

decima_sphere_constants decima_sphere_published(void)
{
    decima_sphere_constants k = {0.25f, 0.25f, 3.0f, 0.001f, 0.001f};
    return k;
}

/* GGX D as a function of (N.H)^2 (the appendix's GetGGXFromNDotHSquared). */
static float ggx_from_noh_squared(float noh2, float alpha)
{
    float a2 = alpha * alpha, t = noh2 * (a2 - 1.0f) + 1.0f;
    return a2 / ((float)M_PI * t * t);
}

float decima_sphere_ggx(float n_dot_l, float n_dot_v, float v_dot_l, float l_dot_h, float radius_over_distance,
                        float alpha, float f0, const decima_sphere_constants *k, int newton_steps)
{
    if (n_dot_l <= 0.0f || n_dot_v <= 0.0f)
        return 0.0f;
    /* "light radius is made smaller for rougher materials" */
    float radius_tan = fmaxf(k->min_radius_tan, radius_over_distance - k->radius_reduction * alpha);
    float noh2 = sphere_noh_squared(radius_tan, n_dot_l, n_dot_v, v_dot_l, newton_steps);
    float density = ggx_from_noh_squared(noh2, alpha);
    /* visibility = G2 / (4 n.l n.v) */
    float visibility = (float)(ggx_smith_g2(n_dot_v, n_dot_l, alpha) / (4.0 * (double)n_dot_l * n_dot_v));
    float brdf = density * visibility * fresnel_schlick(l_dot_h, f0);
    float a2_ldoth = alpha * alpha * (l_dot_h + k->norm_eps);
    float normalization =
        a2_ldoth / (a2_ldoth + k->norm_scale * radius_over_distance * (k->norm_alpha * alpha + radius_over_distance));
    return normalization * brdf * saturate(n_dot_l);
}

float decima_sphere_ggx_local(vec3 v, vec3 lc, float sin_sigma, float alpha, const decima_sphere_constants *k,
                              int newton_steps)
{
    float v_dot_l = v3_dot(v, lc);
    float l_dot_h = sqrtf(fmaxf(0.0f, 0.5f + 0.5f * v_dot_l)); /* h = (v + l)/|v + l| */
    return decima_sphere_ggx(lc.z, v.z, v_dot_l, l_dot_h, sin_sigma, alpha, 1.0f, k, newton_steps);
}

float sphere_illuminance_frostbite(float cos_theta, float sin_sigma)
{
    float sin_sigma_sq = sin_sigma * sin_sigma;
    /* Whole cap above the horizon (or below it): a point light's cosine law. */
    if (cos_theta * cos_theta > sin_sigma_sq)
        return (float)M_PI * sin_sigma_sq * saturate(cos_theta);
    float sin_theta = sqrtf(fmaxf(0.0f, 1.0f - cos_theta * cos_theta));
    float x = sqrtf(1.0f / sin_sigma_sq - 1.0f); /* cot(sigma) */
    float y = -x * (cos_theta / sin_theta);
    float sin_theta_sqrt_y = sin_theta * sqrtf(fmaxf(0.0f, 1.0f - y * y));
    float e = (cos_theta * acosf(y) - x * sin_theta_sqrt_y) * sin_sigma_sq + atanf(sin_theta_sqrt_y / x);
    return fmaxf(e, 0.0f);
}

float sphere_illuminance_representative(float cos_theta, float sin_sigma)
{
    float sin_theta = sqrtf(fmaxf(0.0f, 1.0f - cos_theta * cos_theta));
    float cos_sigma = sqrtf(fmaxf(0.0f, 1.0f - sin_sigma * sin_sigma));
    /* cos(theta - sigma), or 1 once the cap contains n. */
    float cos_rep = cos_theta >= cos_sigma ? 1.0f : cos_theta * cos_sigma + sin_theta * sin_sigma;
    return (float)M_PI * sin_sigma * sin_sigma * saturate(cos_rep);
}
