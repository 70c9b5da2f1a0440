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
    /* On the disc's rim, rounding can make z2 <= 0; keep z > 0 (a change on a
     * set of measure zero) so no sample lies on the horizon itself. */
    float z2 = 1.0f - x * x - y * y;
    return v3(x, y, sqrtf(z2 > 0x1p-24f ? z2 : 0x1p-24f));
}

vec3 sample_uniform_hemisphere(const float u[2])
{
    float z = 1.0f - u[0]; /* in (0, 1]: never on the horizon */
    float r = sqrtf(1.0f - z * z);
    float phi = 2.0f * (float)M_PI * u[1];
    return v3(r * cosf(phi), r * sinf(phi), z);
}
