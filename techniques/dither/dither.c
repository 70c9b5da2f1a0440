/* Dithered quantisation: see dither.h for the definitions and sources. */
#include "dither/dither.h"

#include <math.h>

const char *dither_kind_name(dither_kind kind)
{
    static const char *const names[DITHER_KIND_COUNT] = {"none", "rpdf", "tpdf-sum", "tpdf-average", "tpdf-remap"};
    return kind >= 0 && kind < DITHER_KIND_COUNT ? names[kind] : "?";
}

double dither_remap_triangular(double v)
{
    double orig = v * 2.0 - 1.0;
    if (orig == 0.0) /* the talk's o / sqrt(|o|) is 0/0: C's fmax(-1, NaN) = -1, sign(0) = 0 */
        return -0.5;
    double sign = orig > 0.0 ? 1.0 : -1.0;
    double r = fmax(-1.0, orig / sqrt(fabs(orig)));
    return r - sign + 0.5;
}

double dither_value(dither_kind kind, double u0, double u1)
{
    switch (kind) {
    case DITHER_RPDF: return u0;
    case DITHER_TPDF_SUM: return u0 + u1 - 0.5;
    case DITHER_TPDF_AVERAGE: return 0.5 * (u0 + u1);
    case DITHER_TPDF_REMAP: return dither_remap_triangular(u0);
    default: return 0.5;
    }
}

double dither_offset(dither_quantiser quantiser) { return quantiser == DITHER_ROUND ? -0.5 : 0.0; }

double dither_quantise_lsb(double s_plus_d, dither_quantiser quantiser)
{
    return quantiser == DITHER_ROUND ? nearbyint(s_plus_d) : floor(s_plus_d);
}

double dither_unorm(double x, int bits, double dither_lsb)
{
    double levels = ldexp(1.0, bits) - 1.0;
    double k = nearbyint(x * levels + dither_lsb);
    return fmin(fmax(k, 0.0), levels) / levels;
}

double dither_small_float_ulp(double x, int mantissa_bits)
{
    int e = 0;
    (void)frexp(x > 0.0 ? x : 0.0, &e); /* x = f 2^e, f in [1/2, 1): binade 2^(e-1) */
    int binade = x > 0.0 ? e - 1 : -14;
    return ldexp(1.0, (binade < -14 ? -14 : binade) - mantissa_bits);
}

double dither_small_float(double x, int mantissa_bits)
{
    double largest = ldexp(2.0 - ldexp(1.0, -mantissa_bits), 15);
    if (!(x > 0.0))
        return 0.0;
    double ulp = dither_small_float_ulp(x, mantissa_bits);
    return fmin(nearbyint(x / ulp) * ulp, largest);
}
