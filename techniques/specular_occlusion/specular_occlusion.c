/* Cone/cone specular occlusion and its baselines: GTSO talk (Jimenez et al.
 * 2016), slides "Calculating Aperture from Ambient Occlusion" to "Final
 * Specular Visibility Calculation"; see the header for the formulas and the
 * transcription's corrections. */
#include "specular_occlusion/specular_occlusion.h"

#include "core/optics/ggx.h"
#include "core/optics/phong.h"
#include "core/optics/shared_math_c.h"
#include "core/optics/spherical_caps.h"

/* The cone/cone forms, the apertures and Lagarde's, the text the shaders
 * embed too. */
#include "specular_occlusion/specular_occlusion.inc"

double so_visibility_cos_aperture(double ao, so_ao_weighting weighting)
{
    return weighting == SO_AO_UNIFORM ? 1.0 - so_clamp01(ao) : so_visibility_cos_cosine(ao);
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
    case SO_APERTURE_EXP2_ALPHA: return so_reflection_cos_exp2(alpha);
    case SO_APERTURE_EXP2_PERCEPTUAL: return so_reflection_cos_exp2(roughness);
    case SO_APERTURE_PHONG_U_REFLECTED: return cos(fmin(M_PI, 2.0 * acos(pow(u, 1.0 / (p + 2.0)))));
    default: return 1.0;
    }
}
