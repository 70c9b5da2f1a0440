#include "core/hemisphere_sampling.h"

void sample_concentric_disc(const float u[2], float *x, float *y)
{
    float a = 2.0f * u[0] - 1.0f, b = 2.0f * u[1] - 1.0f;
    if (a == 0.0f && b == 0.0f) {
        *x = *y = 0.0f;
        return;
    }
    float r, phi;
    if (fabsf(a) > fabsf(b)) {
        r = a;
        phi = (float)(M_PI / 4) * (b / a);
    } else {
        r = b;
        phi = (float)(M_PI / 2) - (float)(M_PI / 4) * (a / b);
    }
    *x = r * cosf(phi);
    *y = r * sinf(phi);
}

vec3 sample_cosine_hemisphere(const float u[2])
{
    float x, y;
    sample_concentric_disc(u, &x, &y);
    float z2 = 1.0f - x * x - y * y;
    return v3(x, y, sqrtf(z2 > 0.0f ? z2 : 0.0f));
}

vec3 sample_uniform_hemisphere(const float u[2])
{
    float z = u[0];
    float r = sqrtf(1.0f - z * z); /* z < 1 */
    float phi = 2.0f * (float)M_PI * u[1];
    return v3(r * cosf(phi), r * sinf(phi), z);
}
