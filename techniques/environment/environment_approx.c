/* The engines' ambient combinations under an environment: see the header. */
#include "environment/environment_approx.h"

#include <math.h>

#include "core/vec3.h" /* M_PI */

const char *environment_irradiance_source_name(environment_irradiance_source s) { return s == ENVIRONMENT_IRRADIANCE_SH9 ? "sh9" : "map"; }

const char *environment_diffuse_kind_name(environment_diffuse_kind k)
{
    static const char *names[ENVIRONMENT_DIFFUSE_KINDS] = {"unoccluded", "ao-n", "ao-bent", "multibounce-n",
                                                   "multibounce-bent"};
    return k >= 0 && k < ENVIRONMENT_DIFFUSE_KINDS ? names[k] : "?";
}

void environment_irradiance(const environment_lighting *l, environment_irradiance_source s, const double n[3], double e[3])
{
    if (s == ENVIRONMENT_IRRADIANCE_SH9) {
        sh9_irradiance_clamped(l->sh, n, e);
        return;
    }
    float f[3];
    irradiance_map_lookup(l->map, n, f);
    e[0] = f[0], e[1] = f[1], e[2] = f[2];
}

void environment_unit_bent(const double bent[3], const double n[3], double out[3])
{
    double len = sqrt(bent[0] * bent[0] + bent[1] * bent[1] + bent[2] * bent[2]);
    for (int c = 0; c < 3; ++c)
        out[c] = len > 0.0 ? bent[c] / len : n[c];
}

static int uses_bent(environment_diffuse_kind k) { return k == ENVIRONMENT_DIFFUSE_AO_BENT || k == ENVIRONMENT_DIFFUSE_MULTIBOUNCE_BENT; }

/* The occlusion factor of a kind for one channel's albedo. */
static double occlusion(const environment_lighting *l, environment_diffuse_kind k, double ao, double albedo)
{
    if (k == ENVIRONMENT_DIFFUSE_UNOCCLUDED)
        return 1.0;
    if (k == ENVIRONMENT_DIFFUSE_AO_N || k == ENVIRONMENT_DIFFUSE_AO_BENT)
        return ao;
    return gtao_multibounce(l->multibounce, ao, albedo);
}

void environment_diffuse(const environment_lighting *l, environment_irradiance_source s, environment_diffuse_kind k,
                        const double n[3], const double bent[3], double ao, const double albedo[3], double out[3])
{
    double e[3];
    environment_irradiance(l, s, uses_bent(k) ? bent : n, e);
    for (int c = 0; c < 3; ++c)
        out[c] = e[c] / M_PI * occlusion(l, k, ao, albedo[c]);
}

void environment_specular(const environment_lighting *l, const double R[3], double n_dot_v, double roughness,
                         const double f0[3], double v_s, double out[3])
{
    split_sum_specular(l->prefiltered, l->dfg, R, n_dot_v, roughness, f0, out);
    for (int c = 0; c < 3; ++c)
        out[c] *= v_s;
}
