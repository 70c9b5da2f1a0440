/* The combination images of the Decima height fog (Kojima Productions,
 * "Height fog", SIGGRAPH 2017 Advances, slide "Height fog: Analytic model";
 * issue 16 item 4): builtin:terrain under the atmosphere of
 * atmosphere/atmosphere_model.h, per weather (sunny t = 0, dense fog t = 1) and
 * sun elevation, rendered
 *
 *  (i) as the reference: per pixel the radiance the atmosphere scatters
 *      towards the camera along the view ray (atmosphere_view_radiance:
 *      single scattering with the sun at its true azimuth and the exact
 *      phases at the pixel's theta_sv, plus the solved orders >= 2), over
 *      the whole ray for a pixel that misses the terrain (the sky, or the
 *      planet's black ground beyond the terrain's edge) and over the segment
 *      camera -> surface for a terrain pixel (the terrain is black: surfaces
 *      absorb, as in the fog study's references; the terrain neither shadows
 *      the sun nor hides the sky: it only ends view rays);
 * (ii) as the talk's model: L_background = sum_i p_i(theta_sv)
 *      L_inscatter^i(theta_s, theta_v, y_camera, t) from the LUTs for a pixel
 *      that misses the terrain; HeightFog()'s in-scatter for a terrain pixel,
 *      with the atmosphere's own coefficients at the ground (Rayleigh RGB,
 *      Mie scattering and absorption at the weather's blend), one scale
 *      height H (below), the sun colour L_sun(theta_s, y_camera, t) and the
 *      ambient colour L_sky(theta_s, y_camera, t) from the LUTs (the talk's
 *      L = L_background alpha + (L_sun + L_amb)(1 - alpha) with a black
 *      background behind the surface). Models: the talk's published
 *      HeightFog() and the corrected one with the sun and the sky attenuated
 *      (height_fog/height_fog.h, HEIGHT_FOG_ATTENUATE_SKY).
 *
 * Scene units are metres, the scene's y = 0 is the planet's surface
 * (radius R_b), and the scene is placed tangent to the sphere below the
 * camera: a ray from the camera at altitude y_c along unit direction w has
 * r = R_b + y_c, mu = w_y; along it the atmosphere's altitudes follow the
 * sphere (the flat terrain and the sphere part by d^2 / 2 R_b, 5 m at the
 * terrain's 8 km). The sun's direction is the fog study's
 * (height_fog_weather: elevation e, 35 degrees of azimuth from +Z towards
 * +X), theta_s = 90 deg - e, nu = dot(w, sun).
 *
 * The scale height: the talk's fog has one H, the atmosphere two species
 * with 8 km (Rayleigh) and 1.2 or 0.6 km (Mie). H is fitted so that the
 * fog's vertical optical depth from the ground to the camera equals the
 * atmosphere's (green): beta_t(0) H (1 - exp(-y_c / H)) = \int_0^{y_c}
 * beta_t(y) dy, the column the camera looks down through (bisection on log H).
 *
 * The fisheye: an equidistant fisheye from the ground (y = 0) looking at
 * the zenith, 180 degrees: pixel (i, j) of an N x N image at u = 2 (i + 1/2)
 * / N - 1, v = 1 - 2 (j + 1/2) / N, rho = sqrt(u^2 + v^2) <= 1 sees zenith
 * angle theta = rho 90 deg at azimuth atan2(v, u), direction (sin theta u /
 * rho, cos theta, -sin theta v / rho): image right is +X, image up -Z. All of
 * it is sky: the reference's full rays against L_background of the LUTs at
 * y = 0. This isolates the LUT's sky error, including the theta_sv the talk
 * keeps only through the phases; scored again with finer in-scatter
 * tables (request.fine: by default 4x theta_s and 2x theta_v, the two axes
 * item 5 found to dominate), whatever error remains there is not the
 * tables' resolution.
 *
 * Scores per case: RMSE over RGB (terrain pixels, sky pixels, the whole
 * image; the fisheye's circle) and DSSIM (metrics/ssim.h) of the green
 * channel with both images divided by the reference's largest green value
 * (SSIM's dynamic range L = 1), RMSE relative to the reference's RMS, and
 * the median over pixels of |model - reference| / reference (green).
 * No sun disc in either image. Files (in the directory given):
 * aerial_<weather>_sunNN.exr and fisheye_<weather>_sunNN.exr (channels
 * aerial_reference.*, aerial_model.* (published), aerial_model_corrected.*,
 * mask.A: terrain, resp. inside the circle), .png (reference | published
 * model, one exposure: the reference's mean green at 0.18) and
 * _error.png (heatmap of |model - reference| / reference, green, 0 to 0.5). */
#ifndef GTLAB_HEIGHT_FOG_AERIAL_PERSPECTIVE_STUDY_H
#define GTLAB_HEIGHT_FOG_AERIAL_PERSPECTIVE_STUDY_H

#include "core/error.h"
#include "atmosphere/atmosphere_luts.h"
#include "height_fog/height_fog.h"
#include "project/study_context.h"

enum { AERIAL_SUNS = 3, AERIAL_CASES = 2 * AERIAL_SUNS, AERIAL_MODELS = 2 };
typedef enum { AERIAL_MODEL_PUBLISHED, AERIAL_MODEL_SKY_ATTENUATED } aerial_model;

typedef struct {
    int width, height;      /* the terrain view */
    int fisheye;            /* the fisheye's side */
    int sun_count;          /* 1..AERIAL_SUNS */
    double sun_elevations[AERIAL_SUNS];
    double tolerance;       /* the reference's quadrature, relative to each integral's scale */
    atmosphere_method method; /* its transmittances: ADAPTIVE (the grid) or REFERENCE (quadrature) */
    atmosphere_lut_sizes sizes; /* the LUTs of the model; their t axes need at least 2 points (t = 0, 1) */
    atmosphere_lut_sizes fine;  /* finer LUTs for the fisheye's *_fine scores (their blends among the above) */
} aerial_perspective_request;

typedef struct {
    char weather[16];
    double sun_elevation_deg;
    double fog_scale_height;   /* the fitted H [m] */
    int terrain_pixels, sky_pixels, fisheye_pixels;
    double reference_mean_terrain, reference_mean_sky, reference_mean_fisheye; /* green */
    double model_mean_terrain[AERIAL_MODELS], model_mean_sky, model_mean_fisheye;  /* green */
    double rmse_terrain[AERIAL_MODELS], rmse_sky, rmse_view[AERIAL_MODELS];    /* RGB */
    double relative_rmse_view[AERIAL_MODELS]; /* rmse_view / the reference's RMS */
    double dssim_view[AERIAL_MODELS];
    double median_relative_view[AERIAL_MODELS]; /* median over pixels of |model - reference| / reference, green */
    double rmse_fisheye, relative_rmse_fisheye, dssim_fisheye, median_relative_fisheye;
    double rmse_fisheye_fine, relative_rmse_fisheye_fine, dssim_fisheye_fine, median_relative_fisheye_fine;
    double reference_error;    /* the quadrature's largest estimate, relative to its scale */
} aerial_case;

typedef struct {
    aerial_perspective_request request;
    int case_count;
    aerial_case cases[AERIAL_CASES];
    double seconds;            /* the whole study, wall */
} aerial_perspective_result;

/* The request of `gtlab all` at a quality: the view's and fisheye's size and
 * the reference's tolerance and transmittances (ADAPTIVE or REFERENCE) are the
 * quality table's (height_fog aerial_*, fisheye_size and reference_* rows of
 * techniques/quality_table.txt); suns 5, 20 and 60 degrees, the talk's LUT
 * sizes, fine (32, 128, 8, 2). */
aerial_perspective_request aerial_perspective_default_request(study_quality quality);

/* The study: writes its files into dir (which exists). 0, or -1 with e. */
int aerial_perspective_study(const study_context *ctx, const char *dir, const aerial_perspective_request *rq,
                             aerial_perspective_result *out, gt_error *e);

/* A case's file name: "<kind>_<weather>_sunNN<suffix>", kind "aerial" or
 * "fisheye", suffix ".exr", ".png" or "_error.png". */
void aerial_file_name(const aerial_case *c, const char *kind, const char *suffix, char *out, size_t size);

/* The HeightFog parameters standing in for the atmosphere at blend t seen
 * from altitude camera_y (above: coefficients at the ground, fitted H, LUT
 * sun and sky colours at theta_s, camera_y), with the sun along sun_dir. */
void aerial_fog_param(const atmosphere_luts *luts, double t, double camera_y, vec3 sun_dir, height_fog_param *p);
/* The fitted H of the description above. */
double aerial_fog_scale_height(const atmosphere_model *m, double t, double camera_y);

#endif
