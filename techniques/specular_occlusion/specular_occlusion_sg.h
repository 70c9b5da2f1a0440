/* Specular occlusion from a bent-normal visibility cone by spherical
 * Gaussians: Unity HDRP's current GetSpecularOcclusionFromBentAO
 * (com.unity.render-pipelines.core, ShaderLibrary/CommonLighting.hlsl), the
 * successor of its cone/cone form (specular_occlusion/specular_occlusion.h). Every
 * lobe is an SG G(v; p, lambda) = exp(lambda (v.p - 1)) of amplitude 1
 * (core/optics/spherical_gaussian.h), and
 *
 *   V_s = saturate( <D_w, V> / <D_w, H> ),   <A, B> = int_S2 A B dv,
 *
 *   D_w  the GGX lobe warped to an SG about the reflection vector R (Wang
 *        et al. 2009, "All-Frequency Rendering of Dynamic, Spatially-Varying
 *        Reflectance", section 4: the NDF as an SG of sharpness 2 / alpha^2
 *        about n, warped by the half-vector Jacobian 1 / (4 |h.v|), h = n):
 *          lambda_w = 0.5 / max(alpha^2 n.v, 0.001);
 *   V    the visibility cone (axis b, the bent normal; cos a_v from the AO)
 *        as an SG whose value at the cone's edge is 1/e:
 *          lambda_v = 1 / max(1 - cos a_v, 0.001)
 *        (HDRP's comment derives lambda = -ln Y / (1 - cos a_v) "for Y = 0.1",
 *        which would be 2.303 / (1 - cos a_v); its code has 1: Y = 1/e, as here);
 *   H    the upper hemisphere as an SG about n of sharpness lambda_u = 0.8.
 *
 * The product of two SGs is an SG (axis and sharpness of lambda_1 p_1 +
 * lambda_2 p_2, L = |lambda_1 p_1 + lambda_2 p_2|), so
 *
 *   <G_1, G_2> = exp(L - lambda_1 - lambda_2) 2 pi / L (1 - exp(-2 L))
 *
 * and with L_1 = |lambda_w R + lambda_v b|, L_2 = |lambda_w R + lambda_u n|
 * (R.b = cos beta, R.n = n.v):
 *
 *   V_s = saturate( exp(L_1 - L_2 + lambda_u - lambda_v) I(L_1) / I(L_2) ),
 *   I(L) = 2 pi / L (1 - exp(-2 L))  (sg_sphere_integral(L, 1)).
 *
 * alpha is GGX alpha (HDRP's "roughness" argument, = perceptual roughness^2).
 * Its error against the exact cone-lobe ratio is measured in
 * techniques/specular_occlusion/tests/test_specular_occlusion_sg.c and stated in
 * techniques/specular_occlusion/README.md. */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SG_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SG_H

#define SO_SG_HEMISPHERE_SHARPNESS 0.8 /* lambda_u */

/* lambda_w of the warped GGX lobe. */
double so_sg_lobe_sharpness(double alpha, double n_dot_v);

/* lambda_v of the visibility cone of half-angle acos(cos_av). */
double so_sg_cone_sharpness(double cos_av);

/* <G_1, G_2> of two unit-amplitude SGs whose axes make cos_angle. */
double so_sg_inner_product(double sharpness_1, double sharpness_2, double cos_angle);

/* V_s for the visibility cone's cos a_v, cos beta (bent normal against the
 * reflection vector), n.v and alpha. */
double so_sg_occlusion(double cos_av, double cos_beta, double n_dot_v, double alpha);

#endif
