/* Schlick's approximation of the Fresnel reflectance (Schlick 1994,
 * "An Inexpensive BRDF Model for Physically-based Rendering", eq. 15):
 * F = F0 + (1 - F0) (1 - cos)^5, with cos the cosine between the light (or
 * view) direction and the microfacet normal. */
#ifndef GTLAB_CORE_OPTICS_FRESNEL_H
#define GTLAB_CORE_OPTICS_FRESNEL_H

static inline float fresnel_schlick(float cos_theta, float f0)
{
    float m = 1.0f - cos_theta, m2 = m * m;
    return f0 + (1.0f - f0) * (m2 * m2 * m);
}

#endif
