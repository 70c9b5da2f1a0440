/* Precision of 8-bit colour and the lower bound of an HDR frame's range
 * (Kaplanyan 2010, "CryENGINE 3", slides "Gamma vs linear space for color
 * textures" and "HDR on consoles: lower bound estimator").
 *
 * Gamma vs linear. An 8-bit code g/255 stores the linear value x = g^gamma
 * (gamma space) or x = g (linear space). One code step is dx = (dx/dg)/255
 * in the first and 1/255 in the second, so gamma space is finer where
 * dx/dg < 1, i.e. below the point where gamma g^(gamma-1) = 1:
 *     g* = gamma^(-1/(gamma-1)),   x* = gamma^(-gamma/(gamma-1)).
 * For the sRGB curve (IEC 61966-2-1, x = ((g + 0.055)/1.055)^2.4 above the
 * linear toe) the same condition dg/dx = 1 on g = 1.055 x^(1/2.4) - 0.055
 * gives x* = (1.055/2.4)^(2.4/1.4).
 *
 * The HDR lower bound. A display resolves about half an 8-bit step, so an HDR
 * value c whose tone-mapped output T(c) is below 0.5/255 = 1/510 is black;
 * c_min = T^-1(1/510) bounds the range an HDR buffer needs to hold. With l
 * the frame's average luminance:
 *   exponential  T(c) = 1 - exp(-c/l)               c_min = l ln(510/509)
 *   filmic (Hejl and Burgess-Dawson 2010, output already gamma-encoded):
 *     x = max(0, c/l - 0.004),
 *     T_display = x (6.2 x + 0.5) / (x (6.2 x + 1.7) + 0.06),
 *     T = T_display^2.2 (linear, as the slide writes it);
 *   c_min solves T = 1/510: with d = (1/510)^(1/2.2), x is the positive root
 *     of 6.2 (1 - d) x^2 + (0.5 - 1.7 d) x - 0.06 d = 0, and c_min = l (x + 0.004).
 * The slide prints the filmic denominator as x (6.2 (x + 1.7)) + 0.06; that
 * form is kept (filmic_transcribed) to show what it would give. */
#ifndef GTLAB_HDR_PRECISION_H
#define GTLAB_HDR_PRECISION_H

#define HDR_DISPLAY_THRESHOLD (1.0 / 510.0) /* 0.5 / 255 */

/* x* for a pure power curve x = g^gamma (gamma > 1). */
double gamma_equal_precision_point(double gamma);
/* x* for the sRGB curve. */
double srgb_equal_precision_point(void);
/* The sRGB encode g(x) (IEC 61966-2-1): core/optics/srgb.h's linear_to_srgb. */
double srgb_encode(double x);

double tonemap_exponential(double c, double l);
/* The filmic curve's display-encoded output, and as the slide prints it. */
double tonemap_filmic_display(double c, double l);
double tonemap_filmic_transcribed_display(double c, double l);

/* c_min by the closed forms above (threshold y on the linear output). */
double exponential_c_min(double l, double y);
double filmic_c_min(double l, double y);

/* c_min of any increasing T by bisection on [0, 16 l] (60 halvings): the
 * independent check of the closed forms. `linear` raises a display-encoded
 * T to 2.2 first. */
double tonemap_c_min_bisection(double (*t)(double c, double l), int linear, double l, double y);

#endif
