/* Dithered quantisation as INSIDE does it (Gjoel, "Low Complexity, High
 * Fidelity: INSIDE", GDC 2016, seed 002), with the statistics that decide
 * between the dither distributions (Christou 2008, "Optimal Dither and Noise
 * Shaping in Image Processing", ch. 2; Lipshitz, Wannamaker and Vanderkooy
 * 1992, "Quantization and Dither: A Theoretical Survey").
 *
 * Units: a signal s in LSB (one quantisation step = 1). Two quantisers:
 *   DITHER_FLOOR: q = floor(s + d), the talk's convention ("q = quantize(s +
 *                 rnd)" with rnd on [0, 1[ RPDF or [-0.5, 1.5[ TPDF);
 *   DITHER_ROUND: q = round-half-even(s + d), what a GPU does writing UNORM
 *                 (D3D11.3 functional spec, FLOAT -> UNORM conversion:
 *                 round to nearest) and R11G11B10 float (Vulkan spec, "Unsigned 11-Bit
 *                 Floating-Point Numbers": rounded to the closest value).
 * A floor quantiser is unbiased with d of mean 1/2, a rounding one with d of
 * mean 0: dither_offset() gives the shift that turns a [0, 1[-convention
 * dither into the other. The talk's shader `outcol.rgb += tex/255.0` written
 * to an 8-bit target is a floor-convention dither fed to a rounding
 * quantiser: bias +1/2 LSB (the study measures it).
 *
 * Error e = q - s. With nonsubtractive dither the first two moments of e are
 * independent of s iff the dither's characteristic function and its first
 * two derivatives vanish at nonzero integers (Wannamaker 1992): RPDF of 1 LSB
 * width satisfies the first only, so E[e] = 0 but
 *     Var[e | s] = f (1 - f),   f = frac(s)            (RPDF, 1 LSB)
 * while TPDF of 2 LSB width (sum of two independent 1-LSB uniforms)
 * satisfies both:
 *     Var[e | s] = 1/12 + 1/6 = 1/4 LSB^2 for every s  (TPDF, 2 LSB).
 *
 * The talk's two ways to make TPDF:
 *   1. "(rand(seed0) + rand(seed1)) / 2": as written, a triangle of 1 LSB
 *      width, [0, 1[, variance 1/24: NOT the 2-LSB triangle; its error
 *      variance still depends on s (dither_tpdf_average_as_written). The
 *      2-LSB form is u0 + u1 - 1/2 on [-0.5, 1.5[ (dither_tpdf_sum).
 *   2. Reshape one uniform (Forsyth, shadertoy 4t2SDh), the talk's remap_tri:
 *          o = 2v - 1;  v = max(-1, o / sqrt(|o|));  return v - sign(o) + 0.5
 *      i.e. sign(o) sqrt(|o|) - sign(o) + 1/2: a measure-preserving map of
 *      the uniform onto the triangle on [-0.5, 1.5[, not monotone (v < 1/2
 *      goes to ]0.5, 1.5], v > 1/2 to ]-0.5, 0.5]) (dither_remap_triangular). At v = 1/2, o = 0
 *      and o / sqrt(|o|) is 0/0: GLSL/HLSL max(-1, NaN) is unspecified; C's
 *      fmax returns -1, giving -0.5, the limit from above (1.5 from below:
 *      the inverse CDF jumps there); this function returns -0.5. An 8-bit
 *      texture never holds exactly 1/2 (k/255), a float uniform may. */
#ifndef GTLAB_DITHER_DITHER_H
#define GTLAB_DITHER_DITHER_H

typedef enum { DITHER_FLOOR = 0, DITHER_ROUND } dither_quantiser;

typedef enum {
    DITHER_NONE = 0,           /* d = 1/2 (floor) / 0 (round): plain rounding */
    DITHER_RPDF,               /* u on [0, 1[ */
    DITHER_TPDF_SUM,           /* u0 + u1 - 1/2 on [-0.5, 1.5[ */
    DITHER_TPDF_AVERAGE,       /* (u0 + u1) / 2, the talk's way 1 as written */
    DITHER_TPDF_REMAP,         /* remap_tri(u0), the talk's way 2 */
    DITHER_KIND_COUNT
} dither_kind;

const char *dither_kind_name(dither_kind kind);

/* The talk's remap_tri (Forsyth): uniform v on [0, 1[ -> triangle on [-0.5, 1.5[. */
double dither_remap_triangular(double v);

/* A dither value (floor convention, LSB) of the kind from uniforms u0, u1 in [0, 1[. */
double dither_value(dither_kind kind, double u0, double u1);

/* The shift added to a floor-convention dither for the given quantiser:
 * 0 for DITHER_FLOOR, -1/2 for DITHER_ROUND. */
double dither_offset(dither_quantiser quantiser);

/* q = floor(s + d) or round-half-even(s + d), in LSB (not clamped). */
double dither_quantise_lsb(double s_plus_d, dither_quantiser quantiser);

/* UNORM with `bits` bits: x in [0, 1] -> k / (2^bits - 1), round to nearest
 * even and clamp, after adding `dither_lsb` LSB (round convention). */
double dither_unorm(double x, int bits, double dither_lsb);

/* Unsigned small float of R11G11B10 (5 exponent bits, bias 15, `mantissa_bits`
 * = 6 for R and G, 5 for B; no sign, no infinity in the clamp here):
 * negatives -> 0, rounded to the closest representable value with ties to
 * even, saturated at the largest finite value (2 - 2^-m) 2^15. */
double dither_small_float(double x, int mantissa_bits);

/* The spacing of small floats at x (its local LSB): 2^(max(e, -14) - m) for
 * x in [2^e, 2^(e+1)). */
double dither_small_float_ulp(double x, int mantissa_bits);

#endif
