/* An example gtlab plug-in (core/plugin_abi.h): GTAOMultiBounce with the
 * talk's coefficients (Jimenez et al. 2016, "Shader Code"), evaluated as
 * techniques/multibounce/multibounce.inc evaluates it in C (double, the same order of
 * operations), so gtlab scores it exactly as its own built-in function
 * (tests/plugins/test_plugin_loader.c). Build it as a shared library:
 *   cc -std=c11 -O2 -ffp-contract=off -shared -fPIC -I<gtlab> multibounce_plugin.c -o libmultibounce.so */
#include "core/plugin_abi.h"

int gtlab_plugin_abi(void) { return GTLAB_PLUGIN_ABI; }

/* k0 + k1 rho. */
static double linear(double k0, double k1, double rho) { return rho * k1 + k0; }

/* max(V_d, ((a V_d + b) V_d + c) V_d) with a, b, c linear in rho. */
static double multibounce(double x, double rho)
{
    double a = linear(-0.3324, 2.0404, rho), b = linear(0.6417, -4.7951, rho), c = linear(0.6903, 2.7552, rho);
    double cubic = ((a * x + b) * x + c) * x;
    return cubic > x ? cubic : x;
}

void gtlab_multibounce_v1(const float *visibility, const float *albedo, float *out, size_t count)
{
    for (size_t i = 0; i < count; ++i)
        out[i] = (float)multibounce(visibility[i], albedo[i]);
}
