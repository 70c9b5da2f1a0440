/* The normalised Phong microfacet distribution of Walter et al. 2007
 * ("Microfacet Models for Refraction through Rough Surfaces", eq. 30) and its
 * correspondence with Beckmann/GGX roughness (same paper, section 5.2):
 *
 *   D_p(m) = (p + 2) / (2 pi) (n.m)^p,    p = 2 / alpha^2 - 2
 *
 * The GTSO talk's Phong comparisons and its gloss-to-aperture mapping use
 * this p (its "r = sqrt(2 / (p + 2))" is alpha). */
#ifndef GTLAB_CORE_OPTICS_PHONG_H
#define GTLAB_CORE_OPTICS_PHONG_H

/* p for a GGX/Beckmann alpha, alpha clamped to >= 1e-4. */
double phong_exponent(double alpha);

/* D_p(m) given cos theta_m = n.m; 0 for n.m <= 0. */
double phong_ndf(double cos_m, double p);

#endif
