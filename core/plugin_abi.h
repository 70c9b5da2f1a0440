/* gtlab's C plug-in ABI (issue 15, item 5): approximations written in C, or
 * anything with a C ABI, scored by gtlab beside its own variants. A plug-in
 * is a shared library (dlopen'ed RTLD_NOW | RTLD_LOCAL) that includes only
 * this header and exports, with C linkage:
 *
 *   int gtlab_plugin_abi(void);   returns GTLAB_PLUGIN_ABI, the version it was built for
 *
 * and the entry points of the quantities it approximates, each named with
 * the version of its signature (a changed signature gets a new name; gtlab
 * keeps loading the old ones):
 *
 *   gtlab_multibounce_v1   GTAOMultiBounce's quantity (techniques/multibounce/multibounce.h):
 *                          V'_d from the visibility V_d and one colour
 *                          channel's albedo rho, for `count` samples
 *   gtlab_specular_occlusion_v1
 *                          specular occlusion V_s (specular_occlusion/specular_occlusion.h)
 *                          from the cosine-weighted AO, the angle beta
 *                          (radians) between the bent normal and the
 *                          reflection vector, the perceptual roughness
 *                          (alpha = roughness^2) and n.v, for `count` samples
 *
 * Every entry point has one shape: k float arrays in (the inputs of the
 * quantity's function contract, gpu/function_shader.h, in its order), one
 * out, and the count: gtlab_plugin_fn2 and gtlab_plugin_fn4 below, which the
 * loader (plugins/plugin_loader.h) calls for any quantity.
 *
 * An entry point must be pure: the same inputs give the same outputs, on
 * any thread, and it may be called from several threads at once on disjoint
 * arrays. examples/multibounce_plugin.c and examples/specular_occlusion_plugin.c
 * are examples. Only this header's C
 * types cross the boundary. */
#ifndef GTLAB_CORE_PLUGIN_ABI_H
#define GTLAB_CORE_PLUGIN_ABI_H

#include <stddef.h>

#define GTLAB_PLUGIN_ABI 1

#define GTLAB_PLUGIN_ABI_SYMBOL "gtlab_plugin_abi"
typedef int (*gtlab_plugin_abi_fn)(void);

/* The entry points' shapes by their number of inputs: out[i] = f(in0[i], ...), i < count. */
typedef void (*gtlab_plugin_fn2)(const float *in0, const float *in1, float *out, size_t count);
typedef void (*gtlab_plugin_fn4)(const float *in0, const float *in1, const float *in2, const float *in3, float *out,
                                 size_t count);
enum { GTLAB_PLUGIN_MAX_INPUTS = 4 };

#define GTLAB_MULTIBOUNCE_V1_SYMBOL "gtlab_multibounce_v1"
/* out[i] = V'_d(visibility[i], albedo[i]), i < count. */
typedef void (*gtlab_multibounce_v1_fn)(const float *visibility, const float *albedo, float *out, size_t count);

#define GTLAB_SPECULAR_OCCLUSION_V1_SYMBOL "gtlab_specular_occlusion_v1"
/* out[i] = V_s(ao[i], beta[i], roughness[i], n_dot_v[i]), i < count. */
typedef void (*gtlab_specular_occlusion_v1_fn)(const float *ao, const float *beta, const float *roughness,
                                               const float *n_dot_v, float *out, size_t count);

/* Every entry point this gtlab knows (a plug-in must export one). */
#define GTLAB_PLUGIN_ENTRY_POINTS {GTLAB_MULTIBOUNCE_V1_SYMBOL, GTLAB_SPECULAR_OCCLUSION_V1_SYMBOL}

#endif
