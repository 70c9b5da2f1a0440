/* The engines' ambient combinations under an environment: see the header. */
#include "environment/env_approx.h"

#include <math.h>

#include "core/vec3.h" /* M_PI */

const char *env_irradiance_source_name(env_irradiance_source s) { return s == ENV_IRRADIANCE_SH9 ? "sh9" : "map"; }

const char *env_diffuse_kind_name(env_diffuse_kind k)
{
    static const char *names[ENV_DIFFUSE_KINDS] = {"unoccluded", "ao-n", "ao-bent", "multibounce-n",
                                                   "multibounce-bent"};
    return k >= 0 && k < ENV_DIFFUSE_KINDS ? names[k] : "?";
}

void env_approx_irradiance(const env_approx_lighting *l, env_irradiance_source s, const double n[3], double e[3])
{
    if (s == ENV_IRRADIANCE_SH9) {
        sh9_irradiance_clamped(l->sh, n, e);
        return;
    }
    float f[3];
    irradiance_map_lookup(l->map, n, f);
    e[0] = f[0], e[1] = f[1], e[2] = f[2];
}

void env_approx_unit_bent(const double bent[3], const double n[3], double out[3])
{
    double len = sqrt(bent[0] * bent[0] + bent[1] * bent[1] + bent[2] * bent[2]);
    for (int c = 0; c < 3; ++c)
        out[c] = len > 0.0 ? bent[c] / len : n[c];
}

static int uses_bent(env_diffuse_kind k) { return k == ENV_DIFFUSE_AO_BENT || k == ENV_DIFFUSE_MULTIBOUNCE_BENT; }

/* The occlusion factor of a kind for one channel's albedo. */
static double occlusion(const env_approx_lighting *l, env_diffuse_kind k, double ao, double albedo)
{
    if (k == ENV_DIFFUSE_UNOCCLUDED)
        return 1.0;
    if (k == ENV_DIFFUSE_AO_N || k == ENV_DIFFUSE_AO_BENT)
        return ao;
    return gtao_multibounce(l->multibounce, ao, albedo);
}

void env_approx_diffuse(const env_approx_lighting *l, env_irradiance_source s, env_diffuse_kind k,
                        const double n[3], const double bent[3], double ao, const double albedo[3], double out[3])
{
    double e[3];
    env_approx_irradiance(l, s, uses_bent(k) ? bent : n, e);
    for (int c = 0; c < 3; ++c)
        out[c] = e[c] / M_PI * occlusion(l, k, ao, albedo[c]);
}

void env_approx_specular(const env_approx_lighting *l, const double R[3], double n_dot_v, double roughness,
                         const double f0[3], double v_s, double out[3])
{
    split_sum_specular(l->prefiltered, l->dfg, R, n_dot_v, roughness, f0, out);
    for (int c = 0; c < 3; ++c)
        out[c] *= v_s;
}
