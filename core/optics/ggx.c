#include "core/optics/ggx.h"

#include <math.h>

double ggx_alpha(double roughness) { return roughness * roughness; }

double ggx_alpha_phong_cone(double roughness) { return fmax(ggx_alpha(roughness), 1e-4); }

double ggx_alpha_tabulated(double roughness) { return fmax(ggx_alpha(roughness), 1e-3); }

double ggx_ndf(double cos_m, double alpha)
{
    if (cos_m <= 0.0)
        return 0.0;
    double a2 = alpha * alpha, t = cos_m * cos_m * (a2 - 1.0) + 1.0;
    return a2 / (M_PI * t * t);
}

double ggx_smith_lambda(double cos_w, double alpha)
{
    double c2 = cos_w * cos_w, tan2 = (1.0 - c2) / c2;
    return 0.5 * (sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

double ggx_smith_g1(double cos_w, double alpha) { return 1.0 / (1.0 + ggx_smith_lambda(cos_w, alpha)); }

double ggx_smith_g2(double cos_v, double cos_l, double alpha)
{
    return 1.0 / (1.0 + ggx_smith_lambda(cos_v, alpha) + ggx_smith_lambda(cos_l, alpha));
}

/* Unit half vector of two unit directions, in double. */
static void half_vector(vec3 v, vec3 l, double h[3])
{
    double x = (double)v.x + l.x, y = (double)v.y + l.y, z = (double)v.z + l.z;
    double inv = 1.0 / sqrt(x * x + y * y + z * z);
    h[0] = x * inv, h[1] = y * inv, h[2] = z * inv;
}

double ggx_brdf(vec3 v, vec3 l, double alpha)
{
    if (v.z <= 0.0f || l.z <= 0.0f)
        return 0.0;
    double h[3];
    half_vector(v, l, h);
    return ggx_ndf(h[2], alpha) * ggx_smith_g2(v.z, l.z, alpha) / (4.0 * (double)v.z * l.z);
}

vec3 ggx_sample_visible_normal(vec3 v, double alpha, const float u[2])
{
    /* The view direction in the hemisphere configuration (alpha = 1). */
    double vh[3] = {alpha * v.x, alpha * v.y, v.z};
    double len = sqrt(vh[0] * vh[0] + vh[1] * vh[1] + vh[2] * vh[2]);
    vh[0] /= len, vh[1] /= len, vh[2] /= len;
    /* An orthonormal basis (t1, t2, vh). */
    double lensq = vh[0] * vh[0] + vh[1] * vh[1];
    double t1[3] = {1.0, 0.0, 0.0};
    if (lensq > 0.0) {
        double inv = 1.0 / sqrt(lensq);
        t1[0] = -vh[1] * inv, t1[1] = vh[0] * inv;
    }
    double t2[3] = {vh[1] * t1[2] - vh[2] * t1[1], vh[2] * t1[0] - vh[0] * t1[2], vh[0] * t1[1] - vh[1] * t1[0]};
    /* A point on the projected disc, warped onto the visible half. */
    double r = sqrt((double)u[0]), phi = 2.0 * M_PI * u[1];
    double p1 = r * cos(phi), p2 = r * sin(phi), s = 0.5 * (1.0 + vh[2]);
    p2 = (1.0 - s) * sqrt(fmax(0.0, 1.0 - p1 * p1)) + s * p2;
    double p3 = sqrt(fmax(0.0, 1.0 - p1 * p1 - p2 * p2));
    double nh[3];
    for (int i = 0; i < 3; ++i)
        nh[i] = p1 * t1[i] + p2 * t2[i] + p3 * vh[i];
    /* Back to the ellipsoid configuration. */
    double m[3] = {alpha * nh[0], alpha * nh[1], fmax(0.0, nh[2])};
    double inv = 1.0 / sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    return v3((float)(m[0] * inv), (float)(m[1] * inv), (float)(m[2] * inv));
}

/* D_v(m) with m in double. */
static double visible_normal_pdf(vec3 v, const double m[3], double alpha)
{
    double vm = (double)v.x * m[0] + (double)v.y * m[1] + (double)v.z * m[2];
    if (v.z <= 0.0f || vm <= 0.0)
        return 0.0;
    return ggx_smith_g1(v.z, alpha) * vm * ggx_ndf(m[2], alpha) / v.z;
}

double ggx_visible_normal_pdf(vec3 v, vec3 m, double alpha)
{
    const double md[3] = {m.x, m.y, m.z};
    return visible_normal_pdf(v, md, alpha);
}

vec3 ggx_reflect(vec3 v, vec3 m) { return v3_sub(v3_scale(m, 2.0f * v3_dot(v, m)), v); }

double ggx_reflection_pdf(vec3 v, vec3 l, double alpha)
{
    double h[3];
    half_vector(v, l, h);
    double vh = (double)v.x * h[0] + (double)v.y * h[1] + (double)v.z * h[2];
    return vh > 0.0 ? visible_normal_pdf(v, h, alpha) / (4.0 * vh) : 0.0;
}

double ggx_reflection_weight_brdf(vec3 v, vec3 l, double alpha)
{
    return l.z > 0.0f ? ggx_smith_g2(v.z, l.z, alpha) / ggx_smith_g1(v.z, alpha) : 0.0;
}

double ggx_reflection_weight_ndf(vec3 v, vec3 l, double alpha)
{
    return l.z > 0.0f ? 4.0 * (double)v.z * l.z / ggx_smith_g1(v.z, alpha) : 0.0;
}
