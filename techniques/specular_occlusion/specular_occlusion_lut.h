/* The cone/lobe specular-occlusion LUT of GTSO (Jimenez et al. 2016,
 * slides "Intersection with Accurate Reflection Lobes"):
 *
 *   V_s(a_v, beta, r) = \int_{cone(a_v)} L_r(w) dw / \int_{H(R)} L_r(w) dw
 *
 * the fraction of a reflection lobe L_r about the reflection vector R that
 * lies inside a visibility cone of half-angle a_v whose axis (the bent
 * normal) is beta away from R. A 3-D table needs a lobe symmetric about R, so
 * the lobe is taken where it is, at normal incidence (n = v = R, the
 * split-sum's own assumption):
 *   SO_LOBE_GGX    L = f_r(w, R) (R.w) = D(h) G2(R, w) / 4   (GTSO's definition)
 *   SO_LOBE_GGX_D  L = D(h) (R.w)                           (the talk's older one)
 *   SO_LOBE_PHONG  L = D_p(h) (R.w), D_p = (p+2)/(2 pi) (n.h)^p, p = 2/alpha^2 - 2
 * with h = normalize(w + R), alpha = r^2 (r perceptual, clamped to alpha >=
 * 1e-3), GGX D and G2 from core/optics/ggx.h.
 *
 * Integration: in polar coordinates (theta, phi) about R the cone cuts each
 * circle theta = const in an arc of length 2 acos((cos a_v - cos theta cos
 * beta) / (sin theta sin beta)) (clamped), so V_s is a 1-D integral over
 * theta in [0, pi/2], done by adaptive Gauss-Kronrod (core/sampling/quadrature.h)
 * split at the arc's kinks |a_v - beta|, a_v + beta and at the lobe's scale
 * 2 alpha 2^k, to an absolute tolerance of 1e-8 of the normaliser (tests
 * compare with an independent 2-D quadrature about the cone's axis).
 *
 * Table layout: value [k][j][i] at data[(k * N + j) * N + i]; axis i maps a_v
 * in [0, pi/2], j maps beta in [0, pi], k maps r in [0, 1], each grid point
 * at coordinate t = index / (N - 1) (a GPU texture with texel centres at
 * (index + 0.5) / N is sampled at t (N - 1) / N + 0.5 / N). The coordinate
 * of each axis depends on the parametrisation (so_lut_axes). */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_LUT_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_LUT_H

typedef enum { SO_LOBE_GGX, SO_LOBE_GGX_D, SO_LOBE_PHONG, SO_LOBE_COUNT } so_lobe;

typedef enum {
    SO_AXES_COSINES, /* t = (cos a_v, 0.5 cos beta + 0.5, r): the talk's arguments */
    SO_AXES_ANGLES,  /* t = (a_v / (pi/2), beta / pi, r) */
    SO_AXES_COUNT
} so_lut_axes;

const char *so_lobe_name(so_lobe lobe);
const char *so_lut_axes_name(so_lut_axes axes);
/* One paragraph describing the layout and axes, for file metadata. */
const char *so_lut_axes_description(so_lut_axes axes);

/* \int_{H(R)} L dw for a roughness (perceptual). */
double so_lobe_normaliser(so_lobe lobe, double roughness);
/* V_s(a_v, beta, r) by quadrature; `normaliser` from so_lobe_normaliser(lobe, r).
 * *error (may be NULL) receives the quadrature's error estimate of V_s. */
double so_cone_lobe(so_lobe lobe, double alpha_v, double beta, double roughness, double normaliser, double *error);
/* The lobe L at cos(angle from R) = c, for roughness r (the integrand above). */
double so_lobe_value(so_lobe lobe, double c, double roughness);

/* Axis coordinates <-> (a_v, beta, r). */
void so_lut_coordinates(so_lut_axes axes, double alpha_v, double beta, double roughness, double t[3]);
void so_lut_point(so_lut_axes axes, const double t[3], double *alpha_v, double *beta, double *roughness);

typedef struct {
    int size;
    so_lobe lobe;
    so_lut_axes axes;
    float *data; /* size^3 */
    double max_error_estimate; /* the largest quadrature error estimate of an entry */
    int bc4;                   /* 1: the entries as shipped, decoded from BC4 (so_lut_bc4) */
} so_lut;

/* Fills a table (OpenMP, `threads` workers; the result does not depend on
 * it). Returns 0, or -1 when out of memory. */
int so_lut_build(so_lut *lut, int size, so_lobe lobe, so_lut_axes axes, int threads);
void so_lut_free(so_lut *lut);
/* The table as the talk ships it (slide "Final Specular Visibility
 * Calculation": "32x32x32 BC4 ... (8-bit)"): each roughness slice, a 2-D
 * a_v x beta texture, BC4-compressed (specular_occlusion/bc4_codec.h) and decoded back;
 * dst gets the decoded entries and bc4 = 1. Returns 0, or -1 when out of
 * memory. */
int so_lut_bc4(const so_lut *src, so_lut *dst);
/* Trilinear interpolation at (a_v, beta, r), coordinates clamped to [0, 1]. */
double so_lut_lookup(const so_lut *lut, double alpha_v, double beta, double roughness);

/* Interpolation error of a table: |lookup - so_cone_lobe| at `count` points
 * uniformly random in the table's coordinate cube (fixed seed), max and RMS. */
void so_lut_interpolation_error(const so_lut *lut, int count, unsigned seed, int threads, double *max_error,
                                double *rms_error);

#endif
