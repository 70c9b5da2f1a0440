/* The sRGB transfer functions (IEC 61966-2-1): display-encoded values in
 * [0, 1] to linear light and back, the linear toe below 0.04045 (encoded)
 * or 0.0031308 (linear), the 2.4 power above. The one sRGB encode and decode
 * of gtlab's studies, LUTs and real-time code. */
#ifndef GTLAB_CORE_OPTICS_SRGB_H
#define GTLAB_CORE_OPTICS_SRGB_H

double srgb_to_linear(double v);
double linear_to_srgb(double v);

#endif
