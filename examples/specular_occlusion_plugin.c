/* An example gtlab specular-occlusion plug-in (core/plugin_abi.h): Lagarde
 * and de Rousiers 2014 ("Moving Frostbite to PBR", listing 26),
 *   V_s = saturate((n.v + ao)^(2^(-16 alpha - 1)) - 1 + ao),  alpha = roughness^2,
 * evaluated as specular_occlusion/specular_occlusion.inc evaluates so_lagarde in C
 * (double, the same order of operations and libm calls), so gtlab scores it
 * exactly as its own "lagarde" variant
 * (techniques/shader/tests/test_gpu_so_function_score.c).
 * beta is unused: Lagarde's form has no bent normal. Build it as a shared library:
 *   cc -std=c11 -O2 -ffp-contract=off -shared -fPIC -I<gtlab> specular_occlusion_plugin.c -o libso.so -lm */
#include <math.h>

#include "core/plugin_abi.h"

int gtlab_plugin_abi(void) { return GTLAB_PLUGIN_ABI; }

static double saturate(double x) { return fmin(1.0, fmax(0.0, x)); }

static double lagarde(double n_dot_v, double ao, double alpha)
{
    return saturate(pow(fmax(n_dot_v + ao, 0.0), exp2(-16.0 * alpha - 1.0)) - 1.0 + ao);
}

void gtlab_specular_occlusion_v1(const float *ao, const float *beta, const float *roughness, const float *n_dot_v,
                                 float *out, size_t count)
{
    (void)beta;
    for (size_t i = 0; i < count; ++i) {
        double r = roughness[i];
        out[i] = (float)lagarde(n_dot_v[i], ao[i], r * r);
    }
}
