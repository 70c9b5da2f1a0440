/* The gloss-to-aperture fit of the GTSO talk (slide "Calculating Aperture
 * from Gloss"): the reflection cone's aperture a_s = arccos(u^(1/(p+2)))
 * (Phong importance sampling, Walter et al. 2007 eq. 31) has one parameter
 * u, which the talk chose by comparing cone/cone specular-occlusion IMAGES
 * with the Monte Carlo reference by DSSIM (it found u = 0.01). DSSIM as a
 * function of u is piecewise and not smooth (SSIM windows, clamping), so
 * instead of a gradient fit: a scan of log10 u over [-12, -0.05] in steps of
 * 1/8 decade (which is also the curve reported), then golden-section search
 * between the scan minimum's neighbours to 1e-3 in log10 u. The objective is
 * the mean DSSIM over all reference images (masked to surfaces). */
#ifndef GTLAB_CLI_FIT_APERTURE_H
#define GTLAB_CLI_FIT_APERTURE_H

#include "cli/specular_occlusion_approx.h"

typedef struct {
    so_pixel_inputs inputs;
    const float *reference; /* the reference V_s channel (owned by its image) */
    char name[128];
} aperture_case;

enum { APERTURE_CURVE_MAX = 128 };

typedef struct {
    double u, log10_u, dssim;
    double dssim_at_published; /* at the talk's u = 0.01, for comparison */
    int curve_count;
    double curve_u[APERTURE_CURVE_MAX], curve_dssim[APERTURE_CURVE_MAX]; /* sorted by u */
    int evaluations;
} aperture_fit;

/* A case from a specular-occlusion reference (its G-buffer, its roughness
 * setting, `channel` = specocc.V or specocc_d.V) and an AO reference of the
 * same view. */
int aperture_case_init(aperture_case *c, const image *reference, const char *what_reference, const image *ao,
                       const char *what_ao, const char *channel, gt_error *e);
void aperture_case_free(aperture_case *c);

/* The search; `exact`: exact cap intersection, else Oat's. */
int aperture_fit_run(const aperture_case *cases, int count, int exact, aperture_fit *out, gt_error *e);

#include <cjson/cJSON.h>
/* The fit as JSON (u, DSSIM, DSSIM at the talk's u, the curve), and the curve as a PNG plot. */
cJSON *aperture_fit_json(const aperture_fit *fit, const char *channel, int exact);
int aperture_fit_plot(const aperture_fit *fit, const char *path, const char *title, gt_error *e);

#endif
