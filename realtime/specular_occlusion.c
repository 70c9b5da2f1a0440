/* Cone/cone specular occlusion and its baselines: GTSO talk (Jimenez et al.
 * 2016), slides "Calculating Aperture from Ambient Occlusion" to "Final
 * Specular Visibility Calculation"; see the header for the formulas and the
 * transcription's corrections. */
#include "realtime/specular_occlusion.h"

#include <math.h>

#include "core/ggx.h"
#include "core/phong.h"
#include "core/spherical_caps.h"
#include "core/vec3.h" /* M_PI */

static double clamp01(double x) { return fmin(1.0, fmax(0.0, x)); }

double so_visibility_cos_aperture(double ao, so_ao_weighting weighting)
{
    ao = clamp01(ao);
    return weighting == SO_AO_UNIFORM ? 1.0 - ao : sqrt(1.0 - ao);
}

double so_phong_exponent(double alpha) { return phong_exponent(alpha); }

const char *so_aperture_name(so_aperture_mapping m)
{
    static const char *const names[SO_APERTURE_COUNT] = {"drobot",     "uludag",          "phong-u",
                                                         "exp2-alpha", "exp2-perceptual", "phong-u-reflected"};
    return (int)m >= 0 && m < SO_APERTURE_COUNT ? names[m] : "unknown";
}

int so_aperture_takes_u(so_aperture_mapping m)
{
    return m == SO_APERTURE_PHONG_U || m == SO_APERTURE_PHONG_U_REFLECTED;
}

double so_reflection_cos_aperture(so_aperture_mapping m, double roughness, double u)
{
    double alpha = ggx_alpha_phong_cone(roughness), p = so_phong_exponent(alpha);
    switch (m) {
    case SO_APERTURE_DROBOT: return cos(fmin(M_PI, 2.0 * sqrt(2.0 / (p + 2.0))));
    case SO_APERTURE_ULUDAG: return pow(0.244, 1.0 / (p + 1.0));
    case SO_APERTURE_PHONG_U: return pow(u, 1.0 / (p + 2.0));
    case SO_APERTURE_EXP2_ALPHA: return exp2(-3.32193 * alpha * alpha);
    case SO_APERTURE_EXP2_PERCEPTUAL: return exp2(-3.32193 * roughness * roughness);
    case SO_APERTURE_PHONG_U_REFLECTED: return cos(fmin(M_PI, 2.0 * acos(pow(u, 1.0 / (p + 2.0)))));
    default: return 1.0;
    }
}

static double smoothstep01(double x)
{
    x = clamp01(x);
    return x * x * (3.0 - 2.0 * x);
}

double so_cap_intersection_oat(double a1, double a2, double gamma)
{
    double small = fmin(a1, a2), diff = fabs(a1 - a2);
    double smaller_cap = spherical_cap_solid_angle(cos(small));
    if (gamma <= diff)
        return smaller_cap;
    if (gamma >= a1 + a2)
        return 0.0;
    return smaller_cap * smoothstep01(1.0 - (gamma - diff) / (a1 + a2 - diff));
}

double so_cone_cone(double cos_av, double cos_as, double beta, int exact)
{
    double av = acos(fmax(-1.0, fmin(1.0, cos_av))), as = acos(fmax(-1.0, fmin(1.0, cos_as)));
    double cap = spherical_cap_solid_angle(cos_as);
    if (cap <= 0.0) /* a mirror: the reflection direction is in the cone or not */
        return beta <= av ? 1.0 : 0.0;
    double inter = exact ? spherical_cap_intersection(av, as, beta) : so_cap_intersection_oat(av, as, beta);
    return clamp01(inter / cap);
}

double so_cone_cone_above_horizon(double cos_av, double cos_as, double beta, double n_dot_v)
{
    double av = acos(fmax(-1.0, fmin(1.0, cos_av))), as = acos(fmax(-1.0, fmin(1.0, cos_as)));
    double theta_r = acos(fmax(-1.0, fmin(1.0, n_dot_v)));
    double above = spherical_cap_intersection(as, 0.5 * M_PI, theta_r);
    if (above <= 0.0) /* a mirror, or a cone wholly below the surface */
        return beta <= av ? 1.0 : 0.0;
    return clamp01(spherical_cap_intersection(av, as, beta) / above);
}

double so_lagarde(double n_dot_v, double ao, double alpha)
{
    return clamp01(pow(fmax(n_dot_v + ao, 0.0), exp2(-16.0 * alpha - 1.0)) - 1.0 + ao);
}
