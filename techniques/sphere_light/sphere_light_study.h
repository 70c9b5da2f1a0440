/* GGX sphere lights (the `sphere-light` stage of `gtlab all`; Decima,
 * SIGGRAPH 2017; Karis 2013): the accuracy of GetNoHSquared against brute
 * force, the refit of Decima's constants to Monte Carlo references, error
 * maps of Karis, Decima and Decima refit over (n.v, angular size) and
 * roughness, scene renders of a glossy floor against the path-traced
 * reference, the shadows none of them models, and the cost of the Newton
 * step. The parts are also functions of their own for `gtlab check
 * sphere-noh`, `gtlab fit sphere-light` and `gtlab bench sphere-light`.
 *
 * Writes under <output>/sphere_light: sphere_noh{,_map,_by_nv}.csv,
 * fit_profile.csv, errors_*.csv, scene_*.exr and the scenes' previews and
 * heatmaps (PNG), and the LTC table it fits under <output>/luts/ltc_ggx.{exr,
 * h,hlsl,glsl} (ltc/ltc_ggx_writers.h). The fit's own files
 * (fits/sphere_light.json, .h, .hlsl, .glsl) are the caller's to write from
 * the results. */
#ifndef GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_STUDY_H
#define GTLAB_SPHERE_LIGHT_SPHERE_LIGHT_STUDY_H

#include <stdint.h>
#include <stdio.h>

#include "ltc/ltc_ggx.h"
#include "sphere_light/sphere_light_reference.h"
#include "sphere_light/sphere_light_fit_outputs.h"
#include "project/study_context.h"

/* The folder below the output folder. */
#define SPHERE_LIGHT_DIR "sphere_light"

/* ---- GetNoHSquared against the brute-force maximum of (N.H)^2 ---- */

/* A grid over n.v, the light's elevation and azimuth and its angular size
 * (tan sigma log-spaced over [1e-3, 1]); rim_steps brute-force angles on the
 * light's rim, refined by golden-section search. */
typedef struct {
    int nv_steps, theta_steps, phi_steps, size_steps;
    int rim_steps;
} sphere_noh_sweep;

/* Karis's point (0 Newton steps), 1 and 2 steps, 1 step guarded (taken
 * only where f''(0) < 0). */
enum { NOH_KARIS, NOH_STEP1, NOH_STEP2, NOH_GUARDED, NOH_METHODS };

/* One method's shortfall of (N.H)^2 below the maximum, over the
 * configurations with R outside the light. "Worse"/"better" compare with
 * the baseline: the previous number of steps, or Karis for the guarded
 * step (none for Karis itself: has_baseline 0). */
typedef struct {
    const char *method, *baseline;
    int has_baseline;
    double mean, p99, worst;
    double share_worse, share_better;
} sphere_noh_row;

typedef struct {
    long configurations, r_inside; /* R inside the light: all exact (1) */
    sphere_noh_row rows[NOH_METHODS];
} sphere_noh_stats;

/* Runs the sweep and writes DIR/sphere_noh.csv (every configuration),
 * DIR/sphere_noh_map.csv (over n.v and the light's elevation: the mean gain
 * of one step over Karis and the share of worse configurations) and
 * DIR/sphere_noh_by_nv.csv (mean shortfalls against n.v). */
int sphere_noh_study(const sphere_noh_sweep *sweep, const char *dir, sphere_noh_stats *out, gt_error *e);

/* ---- The refit of Decima's radius reduction and normalisation ---- */

/* Configurations drawn from a realistic distribution (roughness 0.05-1,
 * the sun's size to 30 deg, the light mostly near the mirror direction),
 * their Monte Carlo references, the fit (sphere_light/sphere_light_fit.h) and
 * the errors before and after on held-out configurations. Writes nothing
 * (the settings, the outcome and its files: sphere_light/sphere_light_fit_outputs.h). */
int sphere_fit_study(const sphere_fit_settings *s, sphere_fit_outcome *out, gt_error *e);

/* The held-out configurations of that study (s->test of them after the
 * s->train training ones, with their references): the same samples
 * sphere_fit_study measures, into a malloc'd array. */
int sphere_fit_held_out_samples(const sphere_fit_settings *s, sphere_light_sample **out, gt_error *e);

/* Configuration i of that distribution under a seed. */
sphere_light_config sphere_light_realistic_config(uint32_t seed, uint32_t i);
/* A configuration with its reference (`samples` MIS samples), as radiance
 * per unit normal illuminance. */
sphere_light_sample sphere_light_reference_sample(const sphere_light_config *c, uint32_t samples, uint32_t seed);

/* ---- Error maps against the parameter-space reference ---- */

/* Each cell: mean |ln((approx + 0.01)/(reference + 0.01))| over
 * SPHERE_MAP_OFFSETS light positions at 0 to 2 (alpha + sigma) from the
 * mirror direction. x over [SPHERE_MAP_X_LO, 1], sin(sigma) log-spaced over
 * [SPHERE_MAP_SIN_LO, SPHERE_MAP_SIN_HI]. */
#define SPHERE_MAP_OFFSETS 8
#define SPHERE_MAP_X_LO 0.05
#define SPHERE_MAP_X_HI 1.0
#define SPHERE_MAP_SIN_LO 0.00465
#define SPHERE_MAP_SIN_HI 0.5
enum { SPHERE_MAPS = 4 };

typedef struct {
    const char *name, *title, *xlabel; /* file stem (DIR/<name>.csv), title, x axis */
    int x_is_roughness;                /* x: roughness (else n.v) */
    double fixed;                      /* the other of roughness / n.v */
    double karis, decima, refit;       /* means over the map */
    double ltc;                        /* the LTC sphere light (ltc/ltc_sphere.h) */
} sphere_map_row;

/* ---- Scene renders ---- */

enum { SPHERE_SCENES = 2, SPHERE_SCENE_APPROX = 4 };
/* File stems of the approximations: scene_<scene>_<stem>.png. */
extern const char *const sphere_scene_approx_files[SPHERE_SCENE_APPROX];

/* Floor material of the comparison: grey dielectric, glossy. */
#define SPHERE_FLOOR_ROUGHNESS 0.25f
#define SPHERE_FLOOR_ALBEDO 0.5f
#define SPHERE_F0_DIELECTRIC 0.04f

typedef struct {
    const char *name, *title;
    double karis, decima, refit; /* DSSIM against the reference */
    double karis_flip, decima_flip, refit_flip; /* mean FLIP, the reference the reference (metrics/flip.h) */
    double ltc, ltc_flip;        /* the LTC sphere light: DSSIM, mean FLIP */
    double noise_floor;          /* DSSIM of the reference's even against odd samples */
    int width, height;
} sphere_scene_row;

/* The sphere-on-plane reference with shadows against without. */
typedef struct {
    double dssim;           /* shadowed vs unshadowed */
    double share_darkened;  /* of the visible pixels, losing more than a tenth */
} sphere_shadow_result;

/* Renders the sun and large-light floor scenes, compares Karis, Decima,
 * Decima with `refit` and the LTC sphere light with the table `ltc` per
 * pixel from the reference's G-buffer (the exact Lambert part in all), and
 * the shadowed sphere-on-plane. Writes
 * DIR/scene_<name>.exr, the previews scene_<name>_{reference,karis,...}.png,
 * heatmaps scene_<name>_<approx>_error.png, FLIP maps
 * scene_<name>_<approx>_flip.png and scene_shadows_*.png. */
int sphere_scenes_study(const study_context *ctx, const char *dir, const decima_sphere_constants *refit,
                        const ltc_table *ltc, sphere_scene_row rows[SPHERE_SCENES], sphere_shadow_result *shadows,
                        gt_error *e);

/* ---- The cost of the Newton step ---- */

/* x86-64 instructions of the two functions a shader would hard-code,
 * counted from the disassembly of the running binary (objdump), and time
 * per call over `count` random configurations (one thread). */
typedef struct {
    int instructions_karis, instructions_decima; /* -1 if objdump is unavailable */
    int calls_karis, calls_decima;               /* call instructions inside them (0: straight code) */
    double ns_karis, ns_decima;                  /* best of the passes; NaN: out of memory */
    double ns_karis_full, ns_decima_full, ns_ltc; /* whole specular per pixel: karis_sphere_ggx,
                                                     decima_sphere_ggx_local, ltc_sphere_ggx (16^2 table); NaN: not run */
    long count;                                  /* configurations per pass */
    double share_early_out;                      /* R inside the light: both return 1 at once */
} sphere_cost;

void sphere_cost_study(long count, int repeats, sphere_cost *out);
/* The cost as `gtlab bench sphere-light` prints it: instructions, ns per
 * call and per pixel, beside the talk's +87%. */
void sphere_cost_print(FILE *out, const sphere_cost *cost, long count, int repeats);

/* ---- Near the terminator (issue 26, item 8) ---- */

/* The talk: "N.L is not adjusted ... zero intensity when the centre of the
 * area light is on the horizon". Configurations of the realistic
 * distribution's roughness, size and n.v with the light's centre in the band
 * where the cap straddles the horizon (elevation uniform in [-sigma,
 * sigma]), and for comparison just above it ([sigma, 3 sigma]), azimuth on
 * the reflection's side (within 90 degrees of the mirror azimuth). Errors
 * are the fit's residual ln((model + 0.01)/(reference + 0.01)): the talk's
 * Decima (published constants, one step) and the mended form
 * (decima_sphere_ggx_horizon_local). Means over the configurations, each
 * with the standard error of that mean. */
typedef struct {
    int configurations;   /* per band */
    uint32_t samples;     /* MIS samples per reference */
    double share_centre_below; /* of the straddling band: centre below the horizon, where the talk gives 0 */
    double talk_signed, talk_signed_se;     /* straddling band: mean residual (negative: too dark) */
    double talk_abs, talk_abs_se, fixed_abs, fixed_abs_se; /* straddling band: mean |residual| */
    double gain, gain_se;                   /* talk's |residual| minus the mended one's, paired */
    double above_abs, above_abs_se;         /* the talk's mean |residual| just above the band */
} sphere_terminator_result;

int sphere_terminator_study(int configurations, uint32_t samples, sphere_terminator_result *out);

/* ---- The sun regime (issue 26, item 9) ---- */

/* The talk shows "the sun's reflection with and without the N.H
 * maximization": a disc of the sun's size (sin sigma = 0.00465) at grazing
 * views (n.v uniform in [0.02, 0.3]), its centre 1 to 4 angular radii from
 * the mirror direction (R outside the disc: the early-out, exact, is not
 * counted), roughness uniform in [0.05, 0.3] (water, wet or polished
 * surfaces: a visible sun glint). Compared: Karis's point (0 Newton steps)
 * and the talk's one step, as the shortfall of (N.H)^2 below the rim's
 * brute-force maximum and as Decima's radiance residual (published
 * constants) against the Monte Carlo reference. Means with standard errors
 * over the configurations; gains paired (Karis's minus the step's). */
typedef struct {
    int configurations;
    uint32_t samples;
    double shortfall_karis, shortfall_karis_se, shortfall_step, shortfall_step_se;
    double shortfall_gain, shortfall_gain_se;
    double abs_karis, abs_karis_se, abs_step, abs_step_se; /* mean |residual| */
    double gain, gain_se;
} sphere_sun_result;

int sphere_sun_study(int configurations, uint32_t samples, sphere_sun_result *out);

/* ---- The normalisation's units (issue 26, item 7) ---- */

/* The appendix's normalisation a2 (l.h + eps) / (a2 (l.h + eps) + 0.25 r
 * (3 alpha + r)) takes r = light_radius, a length, beside the
 * dimensionless alpha. Readings of r: sin(sigma) = R / d (gtlab's; Karis's
 * sourceRadius / distance), tan(sigma), and the radius as a length R =
 * d sin(sigma) with the light 0.25 to 4 scene units away (log-uniform), so
 * the result depends on the scene's unit. Each scored with the published
 * constants and refitted (the same fit, its own training set) on the
 * realistic distribution; means of |residual| on held-out configurations
 * with their standard errors. And the normalisation itself: gtlab's
 * reading against none at all (norm_scale = 0), paired. */
enum { SPHERE_READING_SIN, SPHERE_READING_TAN, SPHERE_READING_LENGTH, SPHERE_READINGS };
typedef struct {
    const char *name, *meaning;
    sphere_light_errors published, refit; /* held out */
    double value[SPHERE_FIT_PARAMS], stderr_[SPHERE_FIT_PARAMS]; /* the refit */
} sphere_reading_row;

typedef struct {
    int train, test;
    uint32_t samples;
    sphere_reading_row rows[SPHERE_READINGS];
    sphere_light_errors none;  /* no normalisation (norm_scale = 0), gtlab's reading, held out */
    double gain, gain_se;      /* |residual| without minus with the published normalisation, paired */
} sphere_units_result;

int sphere_units_study(int train, int test, uint32_t samples, int threads, sphere_units_result *out, gt_error *e);

/* ---- LTC sphere lights (issue 27, item 2) ---- */

/* The GGX LTC table fitted by gtlab (ltc/ltc_fit.h) and the sphere as
 * an equal-area N-gon (ltc/ltc_sphere.h), scored on the refit's
 * held-out configurations beside Karis and Decima (published, refit):
 * the residual ln((ltc + 0.01)/(reference + 0.01)), and the paired
 * difference of |residual| (other minus LTC, positive: the LTC is closer)
 * with its standard error over the configurations. The N-gon's own error:
 * sphere_ltc_ngon_error of the shipped LTC_SPHERE_SIDES over the same
 * configurations, mean and worst. */
typedef struct {
    int table_size;
    double fit_seconds, mean_fit_error, max_fit_error; /* the fit's total-variation error per texel */
    sphere_light_errors held_out;
    double paired[SPHERE_FIT_MODELS], paired_se[SPHERE_FIT_MODELS]; /* vs held_out rows of sphere_fit_outcome */
    double ngon_mean, ngon_max;
} sphere_ltc_result;


/* The residual of one sample under the LTC sphere light with table t. */
double sphere_ltc_residual(const ltc_table *t, const sphere_light_sample *s);

/* |ln((ngon + 0.01)/(exact + 0.01))| of the LTC sphere light at s with a
 * `sides`-gon, the exact disk being the LTC_MAX_SIDES-gon (both radiance per
 * unit normal illuminance, as the residual). */
double sphere_ltc_ngon_error(const ltc_table *t, const sphere_light_sample *s, int sides);

/* Scores the table on the held-out samples (count of them) against the
 * outcome's three models. */
void sphere_ltc_score(const ltc_table *t, const sphere_light_sample *test, int count, const sphere_fit_outcome *fit,
                      sphere_ltc_result *out);

/* ---- The whole stage ---- */

typedef struct {
    sphere_noh_sweep sweep;
    sphere_noh_stats noh;
    sphere_fit_settings fit_settings;
    sphere_fit_outcome fit;
    int map_size;          /* cells per side */
    uint32_t map_samples;  /* MIS samples per cell and offset */
    sphere_map_row maps[SPHERE_MAPS];
    sphere_scene_row scenes[SPHERE_SCENES];
    sphere_shadow_result shadows;
    sphere_cost cost;
    sphere_terminator_result terminator;
    sphere_units_result units;
    sphere_sun_result sun;
    sphere_ltc_result ltc;
} sphere_light_result;

int sphere_light_study(const study_context *ctx, sphere_light_result *out, gt_error *e);

#endif
