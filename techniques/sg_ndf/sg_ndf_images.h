/* The specular images of the spherical-Gaussian NDF fit (issue 18 item 4):
 * an orthographic unit sphere filling a size x size image, seen along -z
 * (view v = +z), under core/optics/sky_environment.h's analytic sky (world up +Y).
 * At the pixel's normal n, with the anisotropy's tangent t = Y x n
 * (horizontal; normalised) and b = n x t, the pixel's value is the
 * NDF-weighted environment
 *
 *   I(n) = int_{m.n > 0} D(m) (m.n) L_sky(r(m)) [r.n > 0] dm,
 *   r(m) = 2 (v.m) m - v,
 *
 * the part of a microfacet reflection that depends on D alone (no Fresnel,
 * no masking, no Jacobian: those multiply both images alike and would only
 * blur the comparison). For the true NDF, m ~ D(m)(m.n)
 * (anisotropic_ndf_sample), so each sample weighs L_sky(r) [r.n > 0]. For
 * an SG sum S, the same integral with S for D, m drawn from the lobe
 * mixture with weights proportional to each lobe's sphere integral I_j:
 * each sample weighs (sum_j I_j) (m.n)_+ L_sky(r) [r.n > 0]. Both are Monte
 * Carlo over Owen-scrambled Sobol' points (core/sampling/sobol.h) from a fixed seed,
 * per pixel mean and standard error; pixels compute independently, so the
 * bits do not depend on the thread count. Background pixels are 0. */
#ifndef GTLAB_SG_NDF_IMAGES_H
#define GTLAB_SG_NDF_IMAGES_H

#include <stdint.h>

#include "core/optics/anisotropic_ndf.h"
#include "core/error.h"
#include "core/optics/spherical_gaussian.h"

enum { SG_IMAGE_MAX_LOBES = 16 };

typedef struct {
    int size;     /* pixels per side, >= 16 */
    int samples;  /* per pixel, even, >= 2 */
    uint32_t seed;
    int threads;  /* >= 1 */
} sg_image_options;

/* Per-pixel planes (size^2 floats each; NULL to skip): mean, its standard
 * error, and the means of the even- and odd-index samples (two independent
 * halves, for the noise floor of a DSSIM). */
typedef struct {
    float *mean, *stderr_, *half_even, *half_odd;
} sg_image_planes;

/* The sphere's mask: 1 on the sphere, 0 elsewhere. */
void sg_image_mask(int size, float *mask);

/* The true NDF's image (ndf != NULL) or the SG sum's (lobes, count). */
int sg_image_render(const anisotropic_ndf *ndf, const spherical_gaussian *lobes, int count,
                    const sg_image_options *o, const sg_image_planes *out, gt_error *e);

#endif
