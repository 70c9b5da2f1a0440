/* INSIDE's AO decals on the decal scenes (scene/builtin_scene_ao_decals.h:
 * a pill, a crate on the floor, a crate in a corner, overlapping spheres and
 * boxes with a sphere sunk into the floor) against gtlab's cosine AO
 * reference of the same occluders as real geometry, which counts their
 * union exactly. Receivers: the floor (and the corner's walls), at the
 * scene's own camera.
 *
 * Decals per scene, each occluder's occlusion a_i, multiplied as the talk's
 * blend does (Src: Zero, Dst: SrcColor): V = V_walls prod (1 - a_i), with
 * V_walls = 1 - the walls' exact form factor in the corner (the AO an engine
 * already has there) and 1 elsewhere:
 *   exact         the exact sphere (horizon-clipped) and box forms;
 *   engine        Quilez's sphere (no horizon clip) and the exact box: the
 *                 talk's box code is not published, Quilez 2014 (which it cites) is exact;
 *   point, talk's sign / light's sign
 *                 the published point decal in each occluder's unit space scaled
 *                 by AO_DECAL_POINT_RADIUS (the "full transform": the pill's decal
 *                 is its ellipsoid, stretched);
 *   walls only    (corner) no decal on the crate.
 * Each row: RMSE, worst error, DSSIM and the share of pixels beyond 4
 * standard errors of the reference, over all receivers and by region:
 *   overlap  two or more occluders (the corner's walls count) each occlude > 0.02;
 *   clipped  otherwise, the one that does is a sphere straddling the pixel's tangent plane;
 *   single   the rest.
 * The DSSIM map of every row goes to <out>/ao_decals/dssim_<scene>_<row>.png
 * (inferno, 0 to AO_DECAL_DSSIM_MAP_MAX; black outside the receivers). */
#ifndef GTLAB_AO_DECALS_AO_DECALS_SCENES_H
#define GTLAB_AO_DECALS_AO_DECALS_SCENES_H

#include <stddef.h>

#include "ao_decals/ao_decals.h"
#include "core/image.h"
#include "scene/builtin_scene_ao_decals.h"
#include "project/study_context.h"

#define AO_DECAL_POINT_RADIUS 3.0f /* the point decal's size in occluder radii (half extents) */
#define AO_DECAL_DSSIM_MAP_MAX 0.05f
#define AO_DECAL_SIGNIFICANT 0.02 /* an occluder counts towards a region above this occlusion */

enum { AO_DECAL_SCENE_ROWS_MAX = 32, AO_DECAL_REGIONS = 3, AO_DECAL_SCENE_VIEWS_MAX = 8 };
typedef enum { AO_REGION_SINGLE, AO_REGION_OVERLAP, AO_REGION_CLIPPED } ao_decal_region;

typedef struct {
    const char *scene, *decal;
    size_t pixels;
    double rmse, bias, worst, dssim, outlier_share; /* bias: mean decal - reference (< 0: over-occludes) */
    size_t region_pixels[AO_DECAL_REGIONS];
    double region_rmse[AO_DECAL_REGIONS]; /* NaN where the region is empty */
} ao_decal_scene_row;

/* One rendered scene's receivers, kept for the refit (ao_decals_fit.h). */
typedef struct {
    const ao_decal_scene *scene;
    image img;
    size_t count;            /* receiver pixels */
    size_t *pixel;           /* their image index */
    vec3 *p, *n;
    float *v, *stderr_, *walls; /* the reference's V_d and s.e.; V_walls */
    float *sample_counts;       /* the reference's samples at each receiver (a pixel stops at its noise budget) */
    unsigned char *region;
    float *receiver_mask;    /* per image pixel */
    ao_decal_volume volumes[AO_DECAL_SCENE_MAX_OCCLUDERS];
} ao_decal_scene_view;

typedef struct {
    int row_count;
    ao_decal_scene_row rows[AO_DECAL_SCENE_ROWS_MAX];
    int view_count;
    ao_decal_scene_view views[AO_DECAL_SCENE_VIEWS_MAX];
} ao_decals_scenes_result;

/* Renders every decal scene at size^2 pixels, at most spp samples a pixel, stopping at the
 * standard error noise_budget (0: every pixel takes spp; seed), scores the decals and writes the
 * DSSIM maps. Keeps the views (free with ao_decals_scenes_free). */
int ao_decals_scenes_study(const study_context *ctx, int size, int spp, double noise_budget, unsigned seed,
                           ao_decals_scenes_result *out, gt_error *e);

/* Scores one decal (visibility(view, i) for receiver i) on a view: appends a row, writes its DSSIM map
 * when figures is non-NULL. */
typedef double (*ao_decal_visibility_fn)(const ao_decal_scene_view *view, size_t i, const void *user);
int ao_decals_scenes_score(ao_decals_scenes_result *r, const ao_decal_scene_view *view, const char *decal,
                           const char *key, ao_decal_visibility_fn visibility, const void *user,
                           const char *figures, gt_error *e);

void ao_decals_scenes_free(ao_decals_scenes_result *r);

#endif
