/* INSIDE's analytic AO decals against gtlab's cosine AO reference (issue 17
 * item 1, partial): builtin:sphere-on-plane (sphere of radius 1 at (0, 1.5,
 * 0)) seen from two cameras, floor pixels only (the sphere is the only
 * occluder; V_d = 1 - a). Variants: the exact sphere form (horizon-clipped;
 * here the whole sphere is above every floor point's horizon), Quilez's
 * sphere, the published point decal at radius 3 with the talk's sign (pos =
 * p - centre) and with the light's sign (pos = centre - p), and the point
 * decal refitted by Ceres (radius, falloff exponent, wrap, intensity) on
 * view A and scored on view B (held out: other floor points of the same
 * configuration, not another configuration). Per row: RMSE and worst error
 * of V_d, DSSIM over the floor, and the share of floor pixels beyond 4 of the
 * reference's standard errors. Then the decal scenes (ao_decals_scenes.h)
 * at the same size and spp. */
#ifndef GTLAB_AO_DECALS_AO_DECALS_STUDY_H
#define GTLAB_AO_DECALS_AO_DECALS_STUDY_H

#include "ao_decals/ao_decals_fit.h"
#include "ao_decals/ao_decals_scenes.h"
#include "project/study_context.h"

#define AO_DECALS_DIR "ao_decals"

enum { AO_DECAL_VARIANTS = 6, AO_DECAL_VIEWS = 2 };
/* The held-out comparison: the published decal (light's sign), the refit with k held at 2, the free refit. */
enum { AO_DECAL_PUBLISHED, AO_DECAL_REFIT_K2, AO_DECAL_REFIT_FREE, AO_DECAL_COMPARED };

typedef struct {
    int size, spp;
    unsigned seed;
    int scene_size; /* the decal scenes' image side; 0: size */
    double noise_budget; /* the standard error a reference pixel stops at (spp the most); 0: every pixel takes spp */
} ao_decals_request;

typedef struct {
    const char *variant;
    double rmse[AO_DECAL_VIEWS], worst[AO_DECAL_VIEWS], dssim[AO_DECAL_VIEWS], outlier_share[AO_DECAL_VIEWS];
} ao_decal_row;

typedef struct {
    ao_decals_request request;
    ao_decal_row rows[AO_DECAL_VARIANTS];
    ao_decal_fit_result fit, fit_k2; /* on view A and pill-on-plane; k free, k held at 2 */
    ao_decal_fit_result fit_sphere, fit_pill; /* k free, on each of them alone */
    /* RMSE over the fitted samples and over the held-out configurations' receivers (box-on-plane,
     * box-in-corner, overlap-on-plane), per AO_DECAL_PUBLISHED .. AO_DECAL_REFIT_FREE */
    double fitted_rmse[AO_DECAL_COMPARED], held_out_rmse[AO_DECAL_COMPARED];
    size_t fitted_count, held_out_count;
    /* each held-out scene's own RMSE, [model][scene], for the gap's paired interval */
    double held_out_scene_rmse[AO_DECAL_COMPARED][AO_DECAL_SCENE_VIEWS_MAX];
    int held_out_scenes;
    double held_out_noise_rmse; /* the held-out references' noise: sqrt(mean stderr^2) over their receivers */
    size_t floor_pixels[AO_DECAL_VIEWS];
    /* the largest |Quilez - exact| visibility over each view's floor pixels (the two closed forms, no reference) */
    double quilez_exact_worst[AO_DECAL_VIEWS];
    ao_decals_scenes_result scenes; /* the pill, crate, corner and overlap scenes (views freed) */
} ao_decals_result;

/* The request of `gtlab all` at a quality: the views' size, the references'
 * samples per pixel and the decal scenes' size are the quality table's
 * (ao_decals rows of techniques/quality_table.txt); seed 3. */
ao_decals_request ao_decals_default_request(study_quality quality);

int ao_decals_study(const study_context *ctx, const ao_decals_request *rq, ao_decals_result *out, gt_error *e);

#endif
