/* GTSO's cone/cone specular occlusion, its analytic baselines and the
 * spherical-Gaussian form for an engine, as HLSL or GLSL functions:
 * core/optics/spherical_caps.inc, specular_occlusion/specular_occlusion.inc,
 * core/optics/spherical_gaussian.inc and specular_occlusion/specular_occlusion_sg.inc
 * themselves, the texts gtlab compiles as C, behind the dialect's
 * definitions for float. No formula is written for the
 * shaders alone. The functions (float in, float out):
 *   spherical_cap_solid_angle(cos_a), spherical_cap_intersection(a1, a2, gamma)
 *   so_visibility_cos_cosine(ao), so_reflection_cos_exp2(r)
 *   so_cap_intersection_oat(a1, a2, gamma)
 *   so_cone_cone(cos_av, cos_as, beta, exact)        (exact: int, 0 = Oat and Sander)
 *   so_cone_cone_above_horizon(cos_av, cos_as, beta, n_dot_v)
 *   so_lagarde(n_dot_v, ao, alpha)
 *   so_sg_occlusion(cos_av, cos_beta, n_dot_v, alpha)   (and its pieces, specular_occlusion/specular_occlusion_sg.h)
 * techniques/specular_occlusion/tests/test_gpu_specular_occlusion.c runs them on Vulkan against the C. */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SHADER_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SHADER_H

#include "realtime/shader_language.h"

/* The texts of the four .inc files, embedded by the build. */
extern const char spherical_caps_inc_text[];
extern const char specular_occlusion_inc_text[];
extern const char spherical_gaussian_inc_text[];
extern const char specular_occlusion_sg_inc_text[];

/* The shader source (malloc'd; NULL if out of memory): a header comment
 * naming `generator`, the dialect and the functions. */
char *specular_occlusion_shader_source(shader_language language, const char *generator);

/* shaders/template_specular_occlusion.glsl/.hlsl (malloc'd; NULL if out of
 * memory): the functions above and the per-sample contract's
 * float gtlab_specular_occlusion(float ao, float beta, float roughness, float n_dot_v)
 * as GTSO with the talk's choices, so_cone_cone(so_visibility_cos_cosine(ao),
 * so_reflection_cos_exp2(roughness^2), beta, 1): the same math as gtlab's C
 * variant cone-exact:exp2-alpha.
 * techniques/shader/tests/test_gpu_so_function_score.c checks the files
 * equal this text. */
char *specular_occlusion_template_source(shader_language language);

#endif
