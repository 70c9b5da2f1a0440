/* Linearly transformed cosines (LTC) for gtlab's GGX BRDF: the table a
 * shader looks up, its layout and the distribution it describes.
 *
 * Heitz, Dupuy, Hill & Neubelt 2016, "Real-Time Polygonal-Light Shading
 * with Linearly Transformed Cosines" (SIGGRAPH), their linearly transformed
 * distributions: a distribution D on the sphere is the clamped cosine
 * D_o(w_o) = max(0, w_o.z) / pi seen through a 3x3 matrix M. With
 * w_o = M^-1 w / |M^-1 w|, the Jacobian of that change of variables gives
 *
 *   D(w) = D_o(w_o) |det M^-1| / |M^-1 w|^3
 *
 * so D integrates to 1 over the sphere for any invertible M, and the
 * integral of D over a polygon P equals that of D_o over the polygon
 * M^-1 P, which is Lambert's form factor (ltc/ltc_sphere.h).
 * The BRDF times the cosine is approximated per (n.v, roughness) as
 *
 *   f_r(v, l) (n.l) ~ E D(l),   E = \int_H f_r(v, l)(n.l) dl
 *
 * the magnitude E being the directional albedo (the DFG table's E,
 * luts/dfg_lut.h) and D fitted to f_r (n.l) / E (ltc/ltc_fit.h).
 * gtlab's BRDF: core/optics/ggx.h (GGX D, height-correlated Smith G2, no Fresnel).
 *
 * Frame: n = +z, the view v = (sin theta_v, 0, cos theta_v) in the xz
 * plane; isotropic GGX is symmetric about that plane, so (as in Heitz's
 * table) M^-1 has four free coefficients after dividing by its (2,2) entry
 * (a common scale of M^-1 does not change D):
 *
 *   M^-1 = [[a, 0, b], [0, c, 0], [d, 0, 1]]
 *
 * Fresnel as Heitz's shipped code: with Schlick's F, the lobe's magnitude
 * becomes F0 E + (1 - F0) F_E, F_E = \int_H f_r Fc (n.l) dl = the DFG
 * table's B (Fc = (1 - v.h)^5), i.e. F0 A + B.
 *
 * Axes, texel centres (as luts/dfg_lut.h, so the GPU samples at uv
 * directly): texel (i, j) of an N x N table is data[(j N + i) * LTC_CHANNELS
 * + c]; column i at u = (i + 0.5) / N with u = sqrt(1 - n.v) (Heitz's axis:
 * it spreads the texels towards grazing views where the lobe changes
 * fastest), row j at perceptual roughness r = (j + 0.5) / N. The fit uses
 * alpha = ggx_alpha_tabulated(r) (alpha >= 1e-3: below that the lobe is a
 * mirror to any table). The lookup is luts/table_lookup.inc's bilinear,
 * clamp-to-edge fetch, one channel at a time. */
#ifndef GTLAB_LTC_LTC_GGX_H
#define GTLAB_LTC_LTC_GGX_H

enum { LTC_A, LTC_B, LTC_C, LTC_D, LTC_MAGNITUDE, LTC_FRESNEL, LTC_CHANNELS };

#define LTC_MIN_SIZE 4
#define LTC_MAX_SIZE 256

/* One paragraph describing the layout and axes, for file metadata. */
const char *ltc_ggx_description(void);

/* The axes at texel centres: n.v = 1 - u^2 of column i, r of row j. */
double ltc_n_dot_v_of_column(int i, int size);
double ltc_roughness_of_row(int j, int size);

/* D(w) of the transformed cosine with M^-1 = [[a, 0, b], [0, c, 0], [d, 0,
 * 1]] (m = {a, b, c, d}) at the direction w (need not be unit: D is taken
 * per unit solid angle of w / |w|). */
double ltc_density(const double m[4], const double w[3]);

/* M^-1 w, with m as above. */
void ltc_apply_inverse(const double m[4], const double w[3], double out[3]);

typedef struct {
    int size;
    float *data;      /* size * size * LTC_CHANNELS, layout above */
    float *error;     /* size * size: the fit's error per texel (ltc/ltc_fit.h) */
    double max_error; /* the largest of them */
    double mean_error;
} ltc_table;

/* Allocates a zeroed table; 0, or -1 (out of memory or size outside
 * LTC_MIN_SIZE..LTC_MAX_SIZE; table left empty). */
int ltc_table_alloc(ltc_table *t, int size);
void ltc_table_free(ltc_table *t);

/* Bilinear, clamp-to-edge lookup of every channel at (n.v, r), in float,
 * as a GPU samples the texture (luts/table_lookup.inc at uv = (sqrt(1 - n.v), r)). */
void ltc_table_sample(const ltc_table *t, float n_dot_v, float roughness, float out[LTC_CHANNELS]);

#endif
