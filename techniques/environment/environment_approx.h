/* The ambient terms engines compute under an environment, per pixel, from
 * the G-buffer and an AO / bent-normal buffer (issue 28, item 2):
 *
 * diffuse (Lambert, albedo rho per channel), outgoing radiance per unit
 * albedo (L_o / rho, as the environment references store it):
 *   unoccluded        E(n) / pi
 *   ao-n              E(n) / pi AO                    (AO x the pre-convolved probe)
 *   ao-bent           E(b) / pi AO                    (b the unit bent normal)
 *   multibounce-n     E(n) / pi G(AO, rho)            (G: the GTAO multi-bounce function,
 *   multibounce-bent  E(b) / pi G(AO, rho)             techniques/multibounce/multibounce.h, per channel)
 * with E the irradiance from 9 SH coefficients (environment/sh_irradiance.h) or the
 * exact irradiance map (environment/irradiance_map.h);
 *
 * specular (GGX, F0 per channel), the split sum times a specular occlusion
 *   P(R, r) (F0 A(n.v, r) + B(n.v, r)) V_s
 * (environment/prefiltered_radiance.h, luts/dfg_lut.h), V_s = 1 unoccluded or one
 * variant of specular_occlusion/specular_occlusion_screen.h (AO as V_s, Lagarde,
 * cone/cone, the GTSO cone/lobe LUT).
 *
 * The talk's claim (Jimenez et al. 2016, seed 001): AO x a pre-convolved
 * probe "will still be accurate for the case of a white dome, but not for
 * any other scenario": under a constant environment E(b) = E(n) = pi L and
 * ao-n is L AO, exactly the white-dome AO shading; elsewhere E(n) AO is
 * \int L cos times \int V cos / pi, not \int V L cos. */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_APPROX_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_APPROX_H

#include "luts/dfg_lut.h"
#include "environment/irradiance_map.h"
#include "environment/prefiltered_radiance.h"
#include "environment/sh_irradiance.h"
#include "multibounce/multibounce.h"

typedef enum { ENVIRONMENT_IRRADIANCE_SH9, ENVIRONMENT_IRRADIANCE_MAP, ENVIRONMENT_IRRADIANCE_SOURCES } environment_irradiance_source;

typedef enum {
    ENVIRONMENT_DIFFUSE_UNOCCLUDED,
    ENVIRONMENT_DIFFUSE_AO_N,
    ENVIRONMENT_DIFFUSE_AO_BENT,
    ENVIRONMENT_DIFFUSE_MULTIBOUNCE_N,
    ENVIRONMENT_DIFFUSE_MULTIBOUNCE_BENT,
    ENVIRONMENT_DIFFUSE_KINDS
} environment_diffuse_kind;

const char *environment_irradiance_source_name(environment_irradiance_source s); /* "sh9", "map" */
const char *environment_diffuse_kind_name(environment_diffuse_kind k);           /* "unoccluded", "ao-n", ... */

/* What the approximations read (not owned; a member may be NULL when no
 * approximation that needs it is asked for). */
typedef struct {
    const sh9_rgb *sh;
    const irradiance_map *map;
    const prefiltered_radiance *prefiltered;
    const dfg_lut *dfg;
    const multibounce_model *multibounce;
} environment_lighting;

/* E(n) from the chosen source (SH clamped at 0, as engines do). */
void environment_irradiance(const environment_lighting *l, environment_irradiance_source s, const double n[3], double e[3]);

/* The unit bent normal from a buffer's bent vector (any length; n where it is zero). */
void environment_unit_bent(const double bent[3], const double n[3], double out[3]);

/* Diffuse outgoing radiance per unit albedo of one kind; `bent` unit
 * (environment_unit_bent); the albedo matters to the multi-bounce kinds only. */
void environment_diffuse(const environment_lighting *l, environment_irradiance_source s, environment_diffuse_kind k,
                        const double n[3], const double bent[3], double ao, const double albedo[3], double out[3]);

/* Specular outgoing radiance: split sum times v_s. */
void environment_specular(const environment_lighting *l, const double R[3], double n_dot_v, double roughness,
                         const double f0[3], double v_s, double out[3]);

#endif
