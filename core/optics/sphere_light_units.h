/* The unit of sphere-light radiance shared by the Monte Carlo reference
 * (techniques/sphere_light/sphere_light_reference.h) and the real-time approximations
 * (sphere_light/sphere_light.h): the normal illuminance of a sphere of unit
 * radiance, E_perp / L_e = pi sin^2(sigma), sin(sigma) = R / d. Specular
 * values are reflected radiance per unit of it. */
#ifndef GTLAB_CORE_OPTICS_SPHERE_LIGHT_UNITS_H
#define GTLAB_CORE_OPTICS_SPHERE_LIGHT_UNITS_H

#include "core/vec3.h" /* M_PI */

static inline double sphere_light_normal_illuminance(double sin_sigma) { return M_PI * sin_sigma * sin_sigma; }

#endif
