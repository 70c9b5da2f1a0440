/* The illuminance of a sphere: see sphere_illuminance.h. */
#include "realtime/sphere_illuminance.h"

#include "core/vec3.h" /* M_PI */

float sphere_illuminance_frostbite(float cos_theta, float sin_sigma)
{
    float sin_sigma_sq = sin_sigma * sin_sigma;
    /* Whole cap above the horizon (or below it): a point light's cosine law. */
    if (cos_theta * cos_theta > sin_sigma_sq)
        return (float)M_PI * sin_sigma_sq * fminf(fmaxf(cos_theta, 0.0f), 1.0f);
    float sin_theta = sqrtf(fmaxf(0.0f, 1.0f - cos_theta * cos_theta));
    float x = sqrtf(1.0f / sin_sigma_sq - 1.0f); /* cot(sigma) */
    float y = -x * (cos_theta / sin_theta);
    float sin_theta_sqrt_y = sin_theta * sqrtf(fmaxf(0.0f, 1.0f - y * y));
    float e = (cos_theta * acosf(y) - x * sin_theta_sqrt_y) * sin_sigma_sq + atanf(sin_theta_sqrt_y / x);
    return fmaxf(e, 0.0f);
}
