/* Cone/cone specular occlusion (GTSO, Jimenez et al. 2016, "Practical
 * Realtime Strategies for Accurate Indirect Occlusion", SIGGRAPH course,
 * slides "First V_s Attempt" to "Final Specular Visibility Calculation"),
 * and the baselines the talk compares it with.
 *
 *   visibility cone: axis = bent normal, aperture from the AO
 *     uniform AO: V = 1 - cos a_v      ->  cos a_v = 1 - V
 *     cosine AO:  V = 1 - cos^2 a_v    ->  cos a_v = sqrt(1 - V)
 *   reflection cone: axis = reflection vector, aperture a_s from roughness
 *     (every published mapping, below)
 *   V_s = Omega(a_v, a_s, beta) / (2 pi (1 - cos a_s)),  beta = angle between
 *     the bent normal and the reflection vector, Omega the cap intersection,
 *     exact (core/optics/spherical_caps.h) or Oat and Sander 2007's smoothstep.
 *
 * Roughness: `roughness` is perceptual (glTF), alpha = roughness^2 (GGX). A
 * Phong exponent p is tied to alpha by Walter et al. 2007's Beckmann-Phong
 * correspondence alpha^2 = 2 / (p + 2), GGX alpha standing in for Beckmann's
 * (the talk's "r = sqrt(2 / (p + 2))" is this alpha).
 *
 * Corrections to the transcription of the talk: none needed in these
 * formulas (each derived and tested: see tests/realtime); the intersection's
 * third argument written "0.5 cos(beta) + 0.5" is a LUT texture coordinate,
 * not an angle (specular_occlusion/specular_occlusion_lut.c), and Uludag's mapping is
 * arccos, as the talk's own note says. */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_H

typedef enum { SO_AO_COSINE, SO_AO_UNIFORM } so_ao_weighting;

/* cos a_v of the visibility cone from an AO value in [0, 1]. */
double so_visibility_cos_aperture(double ao, so_ao_weighting weighting);

/* The two pieces of GTSO's apertures shared with the shaders
 * (specular_occlusion/specular_occlusion.inc): cos a_v = sqrt(1 - saturate(ao)) of a
 * cosine AO, and cos a_s = 2^(-3.32193 r^2). */
double so_visibility_cos_cosine(double ao);
double so_reflection_cos_exp2(double r);

/* Phong exponent from alpha: p = 2 / alpha^2 - 2 (core/optics/phong.h). */
double so_phong_exponent(double alpha);

typedef enum {
    SO_APERTURE_DROBOT,          /* a_s = 2 sqrt(2 / (p + 2)) = 2 alpha (Drobot 2014) */
    SO_APERTURE_ULUDAG,          /* a_s = arccos(0.244^(1 / (p + 1))) (Uludag 2014) */
    SO_APERTURE_PHONG_U,         /* a_s = arccos(u^(1 / (p + 2))) = arccos(u^(alpha^2 / 2)) (the talk; u given) */
    SO_APERTURE_EXP2_ALPHA,      /* cos a_s = 2^(-3.32193 r^2), r = alpha (the talk's u = 0.01, r as it defines r) */
    SO_APERTURE_EXP2_PERCEPTUAL, /* cos a_s = 2^(-3.32193 r^2), r = perceptual roughness (engines' other reading) */
    SO_APERTURE_PHONG_U_REFLECTED, /* a_s = 2 arccos(u^(1 / (p + 2))): the same u, as a cone of reflected
                                      directions (see below; u given) */
    SO_APERTURE_COUNT
} so_aperture_mapping;

/* Walter et al.'s eq. 31 samples the microfacet normal m: a fraction u of
 * the Phong lobe's (cosine-weighted) normals lies outside the cone
 * cos theta_m = u^(1 / (p + 2)) about the normal. The talk takes theta_m as
 * the reflection cone's aperture; but the light direction is the mirror of
 * the view about m, which turns 2 theta_m away from the reflection vector
 * when m turns theta_m away from the normal (exactly so at normal incidence:
 * the half-vector's Jacobian). The cone of reflected directions holding the
 * same share 1 - u of the lobe is then about 2 theta_m wide, as Drobot's
 * a_s = 2 sqrt(2 / (p + 2)) = 2 alpha is. SO_APERTURE_PHONG_U_REFLECTED is
 * that cone; SO_APERTURE_PHONG_U the talk's (README.md, "The
 * gloss-to-aperture search ran off its range"). */
int so_aperture_takes_u(so_aperture_mapping m);
const char *so_aperture_name(so_aperture_mapping m);
/* cos a_s for a perceptual roughness (u: the Phong-importance parameter,
 * used by the mappings so_aperture_takes_u). a_s is clamped to [0, pi]. */
double so_reflection_cos_aperture(so_aperture_mapping m, double roughness, double u);

/* Oat and Sander 2007 ("Ambient Aperture Lighting", listing 1): the
 * intersection of caps of angular radii a1, a2 with axes gamma apart, as the
 * smaller cap's solid angle times smoothstep(0, 1, 1 - (gamma - |a1 - a2|) /
 * (a1 + a2 - |a1 - a2|)) in the partial-overlap range. */
double so_cap_intersection_oat(double a1, double a2, double gamma);

/* Cone/cone V_s for cos a_v, cos a_s and beta (radians). */
double so_cone_cone(double cos_av, double cos_as, double beta, int exact);

/* Not the talk's: cone/cone V_s normalised by the part of the reflection
 * cone above the surface, Omega(a_v, a_s, beta) / Omega(a_s, pi/2, theta_r),
 * theta_r = angle(R, n) = acos(n.v) (R mirrors v about n), exact caps. The
 * reference never counts directions below the surface as occluded (they are
 * not in its lobe); the talk's ratio divides by the whole cone and so
 * darkens open surfaces wherever the cone reaches below the horizon (issue
 * 26, README.md). On an open surface (a_v = pi/2 about n) it is 1. */
double so_cone_cone_above_horizon(double cos_av, double cos_as, double beta, double n_dot_v);

/* Lagarde and de Rousiers 2014, "Moving Frostbite to PBR", listing 26:
 * saturate((n.v + ao)^(2^(-16 alpha - 1)) - 1 + ao), with alpha = roughness^2
 * (Frostbite's "roughness" is GGX alpha). */
double so_lagarde(double n_dot_v, double ao, double alpha);

#endif
