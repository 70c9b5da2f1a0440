/* The height fog study (issue 16 items 2, 4, 6): the Decima talk's analytic
 * HeightFog() (height_fog/height_fog.h), published and corrected, against the
 * references of `gtlab render fog` (techniques/height_fog/height_fog_integrator.h) on the
 * built-in terrain, per weather (sunny, dense) and sun elevation, and the
 * regime table of single rays against the quadrature.
 *
 * Per case (weather, sun elevation), over the terrain pixels:
 *   - the multiple-scattering reference fog.L (the truth: the sun attenuated
 *     and shadowed, the sky attenuated and blocked by the terrain, light
 *     scattered any number of times) with its standard errors;
 *   - the single-scattering quadrature under the published model's
 *     assumptions (sun unattenuated, no shadows): the published model must
 *     equal it wherever its clamp is inactive; its largest relative departure
 *     is the figure of the talk's "exact solution ... under single
 *     scattering" claim;
 *   - RMSE and DSSIM of fog.L of the published model, the corrected model
 *     with the sun unattenuated (the clamp fixed) and with the sun
 *     attenuated, each against the multiple-scattering reference, and the
 *     RMSE of their transmittance against the closed form.
 * The analytic models see what a shader sees: the camera's and the
 * surface's altitudes, the distance and dot(sun, view). */
#ifndef GTLAB_HEIGHT_FOG_STUDY_H
#define GTLAB_HEIGHT_FOG_STUDY_H

#include <stdio.h>

#include "core/error.h"
#include "core/image.h"
#include "height_fog/aerial_perspective_study.h"
#include "project/study_context.h"

#define HEIGHT_FOG_DIR "height_fog"
enum { HEIGHT_FOG_SUNS = 3, HEIGHT_FOG_CASES = 2 * HEIGHT_FOG_SUNS, HEIGHT_FOG_MODELS = 4, HEIGHT_FOG_REGIMES = 8 };
typedef enum {
    HEIGHT_FOG_MODEL_PUBLISHED,
    HEIGHT_FOG_MODEL_CLAMP_FIXED,
    HEIGHT_FOG_MODEL_SUN_ATTENUATED,
    HEIGHT_FOG_MODEL_SKY_ATTENUATED /* and the ambient through the fog above (height_fog.h) */
} height_fog_model;

typedef struct {
    int width, height, spp;
    double sun_elevations[HEIGHT_FOG_SUNS];
    aerial_perspective_request aerial; /* the combination images (height_fog/aerial_perspective_study.h) */
} height_fog_request;

typedef struct {
    char weather[16];
    double sun_elevation_deg;
    int pixels;
    double reference_mean_l, reference_mean_stderr; /* green channel, over the terrain */
    double reference_noise_rms; /* RMS over RGB and pixels of fog.L's stderr: the floor under every RMSE */
    double single_mean_l;                           /* the quadrature, published assumptions */
    double published_max_rel_single;                /* max |published - single| / single (green) */
    double rmse_l[HEIGHT_FOG_MODELS];               /* vs the multiple-scattering reference, RGB */
    double dssim_l[HEIGHT_FOG_MODELS];              /* green channel */
    double rmse_t[HEIGHT_FOG_MODELS];               /* vs the closed form, RGB */
    double reference_rays_per_second;
} height_fog_case;

/* One regime of single rays: the published and the corrected model against
 * the quadrature (sun unattenuated for the published, attenuated for the
 * corrected), largest relative error of T's optical depth and of L. */
typedef struct {
    char regime[64];
    double published_depth_error, published_l_error;
    double corrected_depth_error, corrected_l_error;
} height_fog_regime;

/* What the analytic models cost in C, one thread: ns per pixel of each
 * model one pixel at a time, and of the published one batched over rows
 * (height_fog_published_batch, vectorised), as a CPU port runs it. */
typedef struct {
    double ns_per_pixel[HEIGHT_FOG_MODELS];
    double published_batch_ns_per_pixel;
} height_fog_timing;

typedef struct {
    height_fog_request request;
    height_fog_case cases[HEIGHT_FOG_CASES];
    height_fog_regime regimes[HEIGHT_FOG_REGIMES];
    height_fog_timing analytic_cost;
    aerial_perspective_result aerial;
} height_fog_result;

/* The request of `gtlab all` at a quality: the reference renders' size and
 * samples per pixel are the quality table's (height_fog rows of
 * techniques/quality_table.txt); suns at 5, 20 and 60 degrees; the aerial
 * part's aerial_perspective_default_request. */
height_fog_request height_fog_default_request(study_quality quality);
int height_fog_study(const study_context *ctx, const height_fog_request *rq, height_fog_result *out, gt_error *e);
/* The regime table alone (no rendering). */
void height_fog_regimes(height_fog_regime regimes[HEIGHT_FOG_REGIMES]);
/* The analytic models' cost over n pixels (the bench). */
void height_fog_time_models(int n, height_fog_timing *cost);

/* `gtlab approx height-fog`: model m's fog.L.R/G/B and fog.T.R/G/B for the
 * surfaces of `gbuffer` (P.X/Y/Z and mask.A, e.g. a `render fog` or
 * `render gbuffer` file; its camera from the header), in weather at the sun
 * elevation, added to out (initialised here, same size). `what` names the
 * file in errors. */
int height_fog_approx_image(const image *gbuffer, const char *what, const char *weather, double sun_elevation_deg,
                            height_fog_model m, image *out, gt_error *e);
/* `gtlab bench fog`: the reference's rays per second (multiple scattering,
 * dense fog, the terrain at 128x96) and the models' ns per pixel. */
int height_fog_bench(int threads, double *rays_per_second, height_fog_timing *cost, gt_error *e);
/* The bench's lines. */
void height_fog_bench_print(FILE *f, double rays_per_second, const height_fog_timing *cost);

#endif
