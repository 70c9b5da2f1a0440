#include "core/sampling/cone_sampling.h"

#include <math.h>

#include "core/frame.h"

double cone_one_minus_cos(double sin_sigma)
{
    double s2 = sin_sigma * sin_sigma;
    return s2 / (1.0 + sqrt(fmax(0.0, 1.0 - s2)));
}

double cone_solid_angle(double sin_sigma) { return 2.0 * M_PI * cone_one_minus_cos(sin_sigma); }

vec3 cone_sample_uniform(vec3 axis, double sin_sigma, const float u[2])
{
    /* 1 - cos(theta) uniform in [0, 1 - cos(sigma)): equal solid angles. */
    double t = u[0] * cone_one_minus_cos(sin_sigma);
    double cos_theta = 1.0 - t, sin_theta = sqrt(fmax(0.0, t * (2.0 - t)));
    double phi = 2.0 * M_PI * u[1];
    frame f = frame_from_normal(axis);
    vec3 local = v3((float)(sin_theta * cos(phi)), (float)(sin_theta * sin(phi)), (float)cos_theta);
    return v3_normalize(frame_to_world(&f, local));
}

/* a / |a| in double: a float "unit" vector is unit only to ~6e-8, which
 * would move the edge of a sun-sized cap by 0.5%. */
static void unit_double(vec3 a, double out[3])
{
    double x = a.x, y = a.y, z = a.z, inv = 1.0 / sqrt(x * x + y * y + z * z);
    out[0] = x * inv, out[1] = y * inv, out[2] = z * inv;
}

int cone_contains(vec3 axis, double sin_sigma, vec3 d)
{
    double a[3], b[3];
    unit_double(axis, a);
    unit_double(d, b);
    double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
    return dx * dx + dy * dy + dz * dz <= 2.0 * cone_one_minus_cos(sin_sigma);
}
