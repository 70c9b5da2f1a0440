/* The gloss-to-aperture fit of the GTSO talk (slide "Calculating Aperture
 * from Gloss"): the reflection cone's aperture a_s = arccos(u^(1/(p+2)))
 * (Phong importance sampling, Walter et al. 2007 eq. 31) has one parameter
 * u, which the talk chose by comparing cone/cone specular-occlusion IMAGES
 * with the Monte Carlo reference by DSSIM (it found u = 0.01). DSSIM as a
 * function of u is piecewise and not smooth (SSIM windows, clamping), so
 * instead of a gradient fit: a scan of log10 u over [-12, -0.05] in steps of
 * 1/8 decade (which is also the curve reported), then golden-section search
 * between the scan minimum's neighbours to 1e-3 in log10 u. The objective is
 * the mean DSSIM over all cases (masked to surfaces).
 *
 * The cases are in memory: the screen pass's per-pixel inputs
 * (specular_occlusion/specular_occlusion_screen.h) and the reference V_s of the same
 * pixels. Building them from reference files is the caller's job
 * (specular_occlusion/specular_occlusion_inputs.h). */
#ifndef GTLAB_SPECULAR_OCCLUSION_APERTURE_FIT_H
#define GTLAB_SPECULAR_OCCLUSION_APERTURE_FIT_H

#include "core/error.h"
#include "specular_occlusion/specular_occlusion_screen.h"

typedef struct {
    so_pixel_inputs inputs;
    const float *reference; /* the reference V_s, one per pixel (not owned) */
    char name[128];         /* names the case in errors */
} aperture_case;

/* Frees the case's inputs. */
void aperture_case_free(aperture_case *c);

enum { APERTURE_CURVE_MAX = 128 };

/* Where the cone/cone model is scored apart along the scan (issue 26: is
 * the search driven by one kind of pixel?): grazing views, n.v below
 * APERTURE_GRAZING_NV, where the reflection cone dips below the surface's
 * horizon, which the reference never counts as occluded; occluded pixels,
 * cosine AO below APERTURE_OCCLUDED_AO (and not grazing); and open ones. */
typedef enum { APERTURE_GRAZING, APERTURE_OCCLUDED, APERTURE_OPEN, APERTURE_REGIONS } aperture_region;
#define APERTURE_GRAZING_NV 0.3
#define APERTURE_OCCLUDED_AO 0.8
const char *aperture_region_name(aperture_region r);

typedef struct {
    so_aperture_mapping mapping; /* the cone u parametrises */
    double u, log10_u, dssim;
    int at_range_edge;         /* the minimum lies within a scan step of the range's ends: the search ran off */
    double dssim_at_published; /* at the talk's u = 0.01, for comparison */
    int curve_count;
    double curve_u[APERTURE_CURVE_MAX], curve_dssim[APERTURE_CURVE_MAX]; /* sorted by u */
    /* RMSE of V_s per region at each scan point, pooled over the cases' pixels */
    double curve_region_rmse[APERTURE_REGIONS][APERTURE_CURVE_MAX];
    long region_pixels[APERTURE_REGIONS];
    double region_best_u[APERTURE_REGIONS]; /* the scan point of each region's lowest RMSE */
    int evaluations;
} aperture_fit;

/* The search for the u of `mapping` (one that so_aperture_takes_u: the
 * talk's SO_APERTURE_PHONG_U, or SO_APERTURE_PHONG_U_REFLECTED); `exact`:
 * exact cap intersection, else Oat's. Returns 0, or -1 with e (out of
 * memory, or a case SSIM cannot score). */
int aperture_fit_run(const aperture_case *cases, int count, so_aperture_mapping mapping, int exact, aperture_fit *out,
                     gt_error *e);

#endif
