/* The illuminance of a uniform sphere on a surface, for any technique that
 * lights or occludes with a sphere: the GGX sphere lights' diffuse part
 * (sphere_light/sphere_light.h), the exact sphere AO decal (ao_decals.h).
 * Moved out of the sphere lights' real-time code so a shared folder needs
 * no technique (issue 43). */
#ifndef GTLAB_REALTIME_SPHERE_ILLUMINANCE_H
#define GTLAB_REALTIME_SPHERE_ILLUMINANCE_H

/* Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", listing 7
 * (illuminanceSphereOrDisk): E / L_e for unit radiance, exact for a sphere,
 * including the part of the cap below the horizon. cos_theta = n.lc (lc the
 * direction to the centre), sin_sigma the sine of the angular radius. */
float sphere_illuminance_frostbite(float cos_theta, float sin_sigma);

#endif
