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
 * step is derived from the talk's mathematics (README.md, "Decisions", has
 * the full list of differences). With s = sin(sigma),
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
#include "sphere_light/sphere_light.h"

#include "core/frame.h"
#include "core/optics/sphere_light_units.h"
#include "sphere_light/sphere_light_c.h"
#include "sphere_light/sphere_light.inc"

int sphere_rim_setup(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l, sphere_rim *rim)
{
    if (sl_r_inside_light(radius_tan, n_dot_l, n_dot_v, v_dot_l))
        return 1;
    *rim = sl_rim_setup(radius_tan, n_dot_l, n_dot_v, v_dot_l);
    return 0;
}

void sphere_rim_newton_step(const sphere_rim *rim, float *num, float *den)
{
    sphere_rim_step x1 = sl_rim_newton_step(*rim);
    *num = x1.num, *den = x1.den;
}

void sphere_rim_rotate(sphere_rim *rim, float num, float den)
{
    sphere_rim_step x1 = {num, den};
    *rim = sl_rim_rotate(*rim, x1);
}

float sphere_noh_squared(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l, int newton_steps)
{
    return sl_noh_squared(radius_tan, n_dot_l, n_dot_v, v_dot_l, newton_steps, false);
}

float sphere_noh_squared_karis(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l)
{
    return sl_noh_squared(radius_tan, n_dot_l, n_dot_v, v_dot_l, 0, false);
}

float sphere_noh_squared_decima(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l)
{
    return sl_noh_squared(radius_tan, n_dot_l, n_dot_v, v_dot_l, 1, false);
}

float sphere_noh_squared_guarded(float radius_tan, float n_dot_l, float n_dot_v, float v_dot_l)
{
    return sl_noh_squared(radius_tan, n_dot_l, n_dot_v, v_dot_l, 1, true);
}

vec3 karis_sphere_point(vec3 r, vec3 lc, float sin_sigma)
{
    vec3 centre_to_ray = v3_sub(v3_scale(r, v3_dot(lc, r)), lc);
    float len = v3_length(centre_to_ray);
    float t = len > 0.0f ? sl_saturate(sin_sigma / len) : 0.0f;
    return v3_normalize(v3_add(lc, v3_scale(centre_to_ray, t)));
}

float karis_sphere_normalization(float alpha, float sin_sigma)
{
    float widened = sl_saturate(alpha + 0.5f * sin_sigma);
    float ratio = alpha / widened;
    return ratio * ratio;
}

float karis_sphere_ggx(vec3 v, vec3 lc, float sin_sigma, float alpha)
{
    vec3 r = v3(-v.x, -v.y, v.z); /* reflect(-v, n) with n = +z */
    vec3 l = karis_sphere_point(r, lc, sin_sigma);
    return karis_sphere_normalization(alpha, sin_sigma) * (float)ggx_brdf(v, l, alpha) * sl_saturate(l.z);
}

decima_sphere_constants decima_sphere_published(void)
{
    decima_sphere_constants k = {0.25f, 0.25f, 3.0f, 0.001f, 0.001f};
    return k;
}

float decima_sphere_ggx(float n_dot_l, float n_dot_v, float v_dot_l, float l_dot_h, float radius_over_distance,
                        float alpha, float f0, const decima_sphere_constants *k, int newton_steps)
{
    return sl_decima_sphere_ggx(n_dot_l, n_dot_v, v_dot_l, l_dot_h, radius_over_distance, alpha, f0, *k, newton_steps);
}

float decima_sphere_ggx_local_radii(vec3 v, vec3 lc, float sin_sigma, float norm_radius, float alpha,
                                    const decima_sphere_constants *k, int newton_steps)
{
    float v_dot_l = v3_dot(v, lc);
    float l_dot_h = sqrtf(fmaxf(0.0f, 0.5f + 0.5f * v_dot_l)); /* h = (v + l)/|v + l| */
    return sl_decima_sphere_ggx_radii(lc.z, v.z, v_dot_l, l_dot_h, sin_sigma, norm_radius, alpha, 1.0f, *k,
                                      newton_steps);
}

float decima_sphere_ggx_local(vec3 v, vec3 lc, float sin_sigma, float alpha, const decima_sphere_constants *k,
                              int newton_steps)
{
    return decima_sphere_ggx_local_radii(v, lc, sin_sigma, sin_sigma, alpha, k, newton_steps);
}

float decima_sphere_ggx_horizon_local(vec3 v, vec3 lc, float sin_sigma, float alpha, const decima_sphere_constants *k,
                                      int newton_steps)
{
    float sin_sigma_sq = sin_sigma * sin_sigma;
    if (lc.z * lc.z > sin_sigma_sq) /* the whole cap above (or below) the horizon: the talk's */
        return decima_sphere_ggx_local(v, lc, sin_sigma, alpha, k, newton_steps);
    float form_factor = sphere_illuminance_frostbite(lc.z, sin_sigma) / ((float)M_PI * sin_sigma_sq);
    float lifted = fmaxf(lc.z, 1e-4f);
    float v_dot_l = v3_dot(v, lc);
    float l_dot_h = sqrtf(fmaxf(0.0f, 0.5f + 0.5f * v_dot_l));
    return decima_sphere_ggx(lifted, v.z, v_dot_l, l_dot_h, sin_sigma, alpha, 1.0f, k, newton_steps) / lifted *
           form_factor;
}

float sphere_illuminance_representative(float cos_theta, float sin_sigma)
{
    float sin_theta = sqrtf(fmaxf(0.0f, 1.0f - cos_theta * cos_theta));
    float cos_sigma = sqrtf(fmaxf(0.0f, 1.0f - sin_sigma * sin_sigma));
    /* cos(theta - sigma), or 1 once the cap contains n. */
    float cos_rep = cos_theta >= cos_sigma ? 1.0f : cos_theta * cos_sigma + sin_theta * sin_sigma;
    return (float)M_PI * sin_sigma * sin_sigma * sl_saturate(cos_rep);
}

/* The talks' specular with Schlick's Fresnel: Karis (k == NULL) or Decima
 * with the constants k (one Newton step). */
static float talk_specular(const void *user, vec3 v, vec3 lc, float sin_sigma, float roughness, float f0)
{
    const decima_sphere_constants *k = user;
    float alpha = (float)ggx_alpha(roughness);
    float l_dot_h = sqrtf(fmaxf(0.0f, 0.5f + 0.5f * v3_dot(v, lc)));
    return k ? decima_sphere_ggx(lc.z, v.z, v3_dot(v, lc), l_dot_h, sin_sigma, alpha, f0, k, 1)
             : karis_sphere_ggx(v, lc, sin_sigma, alpha) * fresnel_schlick(l_dot_h, f0);
}

/* One pixel of sphere_light_shade_specular. */
static float shade_point(vec3 p, vec3 n, float albedo, float roughness, vec3 eye, const sphere_light_source *light,
                         float f0, sphere_specular_fn specular, const void *user)
{
    frame f = frame_from_normal(v3_normalize(n));
    vec3 to_light = v3_sub(light->position, p);
    float d = v3_length(to_light), sin_sigma = light->radius / d;
    vec3 v = frame_to_local(&f, v3_normalize(v3_sub(eye, p))), lc = frame_to_local(&f, v3_scale(to_light, 1.0f / d));
    if (!(v.z > 0.0f))
        return 0.0f;
    float e_perp = (float)sphere_light_normal_illuminance(sin_sigma);
    float diffuse = albedo / (float)M_PI * sphere_illuminance_frostbite(lc.z, sin_sigma);
    return light->radiance * (diffuse + e_perp * specular(user, v, lc, sin_sigma, roughness, f0));
}

void sphere_light_shade_specular(const sphere_light_gbuffer *g, vec3 eye, const sphere_light_source *light, float f0,
                                 sphere_specular_fn specular, const void *user, float *out)
{
    for (size_t i = 0; i < g->count; ++i) {
        vec3 p = v3(g->position[0][i], g->position[1][i], g->position[2][i]);
        vec3 n = v3(g->normal[0][i], g->normal[1][i], g->normal[2][i]);
        out[i] = g->mask[i] != 0.0f
                     ? shade_point(p, n, g->albedo[i], g->roughness[i], eye, light, f0, specular, user)
                     : 0.0f;
    }
}

void sphere_light_shade(const sphere_light_gbuffer *g, vec3 eye, const sphere_light_source *light, float f0,
                        const decima_sphere_constants *k, float *out)
{
    sphere_light_shade_specular(g, eye, light, f0, talk_specular, k, out);
}
