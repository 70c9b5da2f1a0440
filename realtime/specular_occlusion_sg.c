/* Spherical-Gaussian specular occlusion (Unity HDRP); see the header for
 * the lobes and the product integral. */
#include "realtime/specular_occlusion_sg.h"

#include <math.h>

#include "core/spherical_gaussian.h"

double so_sg_lobe_sharpness(double alpha, double n_dot_v) { return 0.5 / fmax(alpha * alpha * n_dot_v, 0.001); }

double so_sg_cone_sharpness(double cos_av) { return 1.0 / fmax(1.0 - cos_av, 0.001); }

/* L = |lambda_1 p_1 + lambda_2 p_2|. */
static double product_sharpness(double l1, double l2, double cos_angle)
{
    return sqrt(fmax(0.0, l1 * l1 + l2 * l2 + 2.0 * l1 * l2 * cos_angle));
}

double so_sg_inner_product(double sharpness_1, double sharpness_2, double cos_angle)
{
    double l = product_sharpness(sharpness_1, sharpness_2, cos_angle);
    return exp(l - sharpness_1 - sharpness_2) * sg_sphere_integral(l, 1.0);
}

double so_sg_occlusion(double cos_av, double cos_beta, double n_dot_v, double alpha)
{
    double lw = so_sg_lobe_sharpness(alpha, n_dot_v), lv = so_sg_cone_sharpness(cos_av);
    double lu = SO_SG_HEMISPHERE_SHARPNESS;
    double l1 = product_sharpness(lw, lv, cos_beta), l2 = product_sharpness(lw, lu, n_dot_v);
    /* <D_w, V> / <D_w, H> with the exponentials combined: no underflow */
    double v = exp(l1 - l2 + lu - lv) * sg_sphere_integral(l1, 1.0) / sg_sphere_integral(l2, 1.0);
    return fmin(1.0, fmax(0.0, v));
}
