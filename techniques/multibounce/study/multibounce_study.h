/* The GTAO multi-bounce refit (Jimenez et al. 2016, "Multiple Bounces" to
 * "Shader Code"; issue 3), the `multibounce` stage of `gtlab all`.
 *
 * References: V'_d = L / rho of a Lambertian surface of albedo rho under a
 * white dome of radiance 1, every surface of albedo rho, 4 bounces, and the
 * single-bounce V_d of the same paths, for the built-in scenes (the plane
 * is left out: V_d = V'_d = 1) at seven grey albedos in one pass per scene.
 * Fit: `gtlab fit multibounce` on them (multibounce/multibounce_fit.h): per
 * albedo V'_d = ((a V_d + b) V_d + c) V_d, jointly a, b, c linear in rho,
 * the alternatives, leave-one-scene-out and the jackknife over scenes.
 * Validation: per scene and albedo, V'_d of the odd-index samples against
 * V_d alone, the talk's model, ours and ours fitted without the scene, each
 * fed V_d of the even-index samples (metrics/reference_halves.h), with the
 * noise floors (the even half of V'_d against the odd half). Performance: a
 * short multi-bounce benchmark (multibounce_throughput.h).
 *
 * Writes <output>/multibounce/<scene>.exr and .camera.json (and the
 * height-field multi-bounce reference at the same camera, multibounce/heightfield/<scene>.exr), the fit's
 * <output>/fits/multibounce.{json,h,hlsl,glsl}, and the plot data
 * <output>/figures/multibounce_{scatter,curves,coefficients}.dat. */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_STUDY_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_STUDY_H

#include <stdint.h>

#include "multibounce/multibounce_fit.h"
#include "multibounce/multibounce_fit_constrained.h"
#include "multibounce/multibounce_integrator.h"
#include "project/study_context.h"

#define MULTIBOUNCE_STUDY_DIR "multibounce" /* the references, below the output folder */
/* The height-field references at the same cameras, below the output folder
 * (a folder of their own: MULTIBOUNCE_STUDY_DIR holds multi-bounce references only) */
#define MULTIBOUNCE_HEIGHTFIELD_DIR MULTIBOUNCE_STUDY_DIR "/heightfield"
#define MULTIBOUNCE_FIT_FILE "fits/multibounce.json"
/* Plot data below <output>/figures (formats: multibounce_plot_data.c). */
#define MULTIBOUNCE_SCATTER_DATA "multibounce_scatter.dat"
#define MULTIBOUNCE_CURVES_DATA "multibounce_curves.dat"
#define MULTIBOUNCE_COEFFICIENTS_DATA "multibounce_coefficients.dat"

enum {
    MULTIBOUNCE_STUDY_SCENES = 5,
    MULTIBOUNCE_STUDY_ALBEDOS = 7,
    MULTIBOUNCE_COEFFICIENTS = 6, /* a0 a1 b0 b1 c0 c1 of the joint linear model */
    MULTIBOUNCE_STUDY_NAME = 64
};

/* One scene's render. */
typedef struct {
    char scene[MULTIBOUNCE_STUDY_NAME]; /* built-in scene name */
    double seconds;
    uint64_t paths, rays;
    double mean_spp;   /* paths / covered pixels: where the noise budget stopped them */
    double noise_rmse; /* sqrt of the mean over albedos of V'_d's mean squared standard error (mask) */
} multibounce_render_row;

/* One coefficient of the joint linear model against the talk's. */
typedef struct {
    char name[8];                     /* "a0", "a1", ... (multibounce_fit_parameter_name) */
    int rho_power;                    /* the coefficient multiplies rho^rho_power */
    double ours, standard_error;      /* Ceres' covariance, pixels taken as independent */
    double jackknife_se;              /* over scenes */
    double talk;
    double talk_minus_ours_jackknife; /* (talk - ours) / jackknife_se */
} multibounce_coefficient_row;

/* One albedo: its own cubic, and the RMSE (with the max) of each model on its samples. */
typedef struct {
    double albedo;
    double a, se_a, b, se_b, c, se_c; /* the albedo's own cubic and standard errors */
    double talk_a, talk_b, talk_c;    /* the talk's cubic at this albedo */
    double rmse_own, rmse_joint, rmse_talk;
    double fraction_talk_below;       /* weighted fraction where the talk's cubic < V_d - MBFIT_BELOW_MARGIN */
} multibounce_albedo_row;

/* One held-out scene: the models fitted without it, scored on it (with the
 * max). The last row of a table is the mean over the scenes (is_mean). */
typedef struct {
    char scene[MBFIT_NAME_MAX];       /* the data's scene ("builtin:NAME"), or "mean" */
    int is_mean;
    double rmse_linear, rmse_quadratic, rmse_anchored; /* NAN: not determined by the data */
    double rmse_talk;
    uint64_t samples;                 /* of the scene; all samples in the mean row */
} multibounce_heldout_row;

/* One scene and albedo: the reference (odd samples) against each
 * approximation fed V_d of the even samples, and the noise floors. */
typedef struct {
    char scene[MULTIBOUNCE_STUDY_NAME]; /* built-in scene name, or "mean" */
    double albedo;
    double noise_floor_dssim, noise_floor_rmse; /* even half of V'_d against the odd half */
    double dssim_v_d, dssim_talk, dssim_ours, dssim_ours_held_out;
    double rmse_v_d, rmse_talk, rmse_ours, rmse_ours_held_out;
} multibounce_validation_row;

/* The joint fit on all the data (weighted; errors with the shader's max unless said). */
typedef struct {
    const char *file;              /* MULTIBOUNCE_FIT_FILE, relative to the output folder */
    uint64_t samples;
    int scenes, albedos;
    double rmse_ours, max_error_ours, rmse_talk, max_error_talk;
    double rmse_talk_without_max, fraction_talk_cubic_below_v_d;
    int heldout_scenes;            /* scenes held out in turn */
    double heldout_mean_rmse_linear, heldout_mean_rmse_quadratic, heldout_mean_rmse_anchored,
        heldout_mean_rmse_talk;
    const char *chosen;            /* multibounce_joint_names[]: lowest held-out mean */
    char worst_scene[MBFIT_NAME_MAX]; /* the talk's worst sample */
    double worst_albedo, worst_v_d, worst_v_prime_d;
} multibounce_fit_summary;

/* What the findings are made of. */
typedef struct {
    int farthest_pixels, farthest_scenes; /* index into coefficients: largest |talk - ours| / (s.e. | jackknife s.e.) */
    double farthest_pixels_sigmas, farthest_scenes_sigmas;
    int talk_better_heldout;              /* held-out scenes where the talk's RMSE is lower than ours (linear) */
    double talk_shortfall_lowest_albedo;  /* multibounce_max_shortfall of the talk's cubic */
    double talk_shortfall_zero;           /* ... at albedo 0 */
    double ours_worst_shortfall, ours_worst_shortfall_albedo; /* ours, over the study's albedos */
    double ours_shortfall_zero;
    double two_step_gap;                  /* max |joint linear - the talk's two-step lines| over the coefficients */
} multibounce_findings;

/* A short `gtlab bench multibounce` and the joint fit's own time. */
typedef struct {
    const char *scene;
    int width, height, spp, albedos, channels, threads;
    double paths_per_s_1_thread, rays_per_s_1_thread, raw_intersect1_rays_per_s_1_thread;
    double loop_to_raw_ratio;            /* rays_per_s_1_thread / raw_intersect1_rays_per_s_1_thread */
    double paths_per_s_threads;
    double one_pass_seconds, separate_renders_seconds, one_pass_speedup;
    uint64_t fit_samples;
    int fit_block;
    double joint_fit_solve_seconds;
} multibounce_performance;

/* The shader's clamp max(V_d, cubic) (issue 25, item 4): where it binds,
 * and the cubic refitted so that it never needs it (f >= V_d and f(1) = 1
 * by construction: multibounce/multibounce_fit_constrained.h) against the
 * unconstrained refit, leave one scene out. */
enum { MULTIBOUNCE_CLAMP_GRID = 1000 }; /* the (V_d, rho) grid: V_d = i/N, i = 1..N; rho = j/N, j = 0..N */

typedef struct {
    char scene[MBFIT_NAME_MAX];
    double rmse_unconstrained, rmse_constrained; /* fitted without the scene, scored on it */
} multibounce_clamp_heldout_row;

typedef struct {
    /* where the cubic falls below V_d, so that the max binds */
    double domain_fraction_talk, domain_fraction_ours;    /* of the grid over (0, 1] x [0, 1] */
    double domain_fraction_talk_rho0;                     /* of the grid's row rho = 0 */
    double pixel_fraction_talk, pixel_fraction_ours;      /* weighted samples, below by > MBFIT_BELOW_MARGIN */
    /* the constrained refit on all the data */
    double corner[MULTIBOUNCE_CONSTRAINED_PARAMETERS];    /* g at (V_d, rho) = (0,0), (0,1), (1,0), (1,1) */
    double coefficients[MULTIBOUNCE_COEFFICIENTS];        /* the same cubic as a0 a1 b0 b1 c0 c1 */
    double rmse_constrained, rmse_unconstrained;          /* the latter with the max */
    int heldout_count;
    multibounce_clamp_heldout_row heldout[MULTIBOUNCE_STUDY_SCENES];
    double heldout_mean_difference, heldout_difference_se; /* constrained - unconstrained, over the scenes */
} multibounce_clamp;

/* The bounce count (issue 25, item 3): the published a, b, c were fitted
 * to 4-bounce references; the same scenes, camera and samples rendered at
 * 1, 2, 4 and unlimited inter-reflections (Russian roulette,
 * multibounce_integrator.h: unbiased but for paths cut after
 * 1024 bounces), the joint linear refit of each, and how far the talk's
 * curve is from each refit. */
enum { MULTIBOUNCE_BOUNCE_COUNTS = 4 };
#define MULTIBOUNCE_DISTANCE_ALBEDO_MIN 0.1 /* the distance's albedo range: the talk's, 0.1 to 0.9 */
#define MULTIBOUNCE_DISTANCE_ALBEDO_MAX 0.9

typedef struct {
    char bounces[8];                               /* "1", "2", "4", "inf" */
    double coefficients[MULTIBOUNCE_COEFFICIENTS]; /* joint linear refit: a0 a1 b0 b1 c0 c1 */
    double jackknife_se[MULTIBOUNCE_COEFFICIENTS]; /* over scenes */
    double rmse_refit, rmse_talk, rmse_v_d;        /* on these references' samples (models with the max) */
    double mean_gain;                              /* weighted mean of V'_d - V_d: the light the bounces add */
    /* RMS over the grid V_d = i/100, rho = 0.1 .. 0.9 (step 0.01) of the
     * talk's curve minus the refit's (both with the max), and its jackknife s.e. */
    double talk_distance, talk_distance_se;
    double render_seconds;                         /* of the extra renders (0 for the study's own 4) */
} multibounce_bounce_row;

typedef struct {
    multibounce_bounce_row rows[MULTIBOUNCE_BOUNCE_COUNTS];
    int closest;                                   /* the row whose refit the talk's curve is closest to */
    /* distance at 4 bounces minus the least distance at the other counts,
     * with its jackknife standard error: <= 0 when 4 bounces match best */
    double four_minus_best_other, four_minus_best_other_se;
    int best_other;                                /* the row of that least distance */
    int path_limit;                                /* bounces after which "inf" cuts a path */
} multibounce_bounce_study;

/* "Agnostic to the source of AO" (issue 25, item 5): the talk's f applied
 * to GTAO's V_d (presets low to ultra, one frame, unbounded radius, run on
 * each reference's own G-buffer) and to the reference V_d (even-sample
 * half), both scored against the reference V'_d (odd half) over every scene
 * and albedo (each weighted equally). GTAO's share of the final squared
 * error is 1 - MSE(f(reference V_d)) / MSE(f(GTAO V_d)). */
enum { MULTIBOUNCE_GTAO_PRESETS = 4 };

typedef struct {
    char preset[16];
    double rmse_gtao_input;      /* f(GTAO V_d) against V'_d */
    double rmse_reference_input; /* f(reference V_d) against V'_d */
    double rmse_gtao_v_d;        /* GTAO's V_d against the reference V_d (even half) */
    double gtao_share, gtao_share_se;   /* jackknife over scenes */
    double difference, difference_se;   /* rmse_gtao_input - rmse_reference_input; jackknife */
} multibounce_gtao_row;

/* "Agnostic to the source of the AO as long as it is ground truth": the
 * talk's f fed two ground-truth V_d, the 3-D reference's and the
 * height-field multi-bounce reference's (raytracer/
 * heightfield_multibounce_integrator.h: the world screen-space and
 * line-sweep AO see, rendered at the same camera with the same albedos,
 * bounces and samples), each the even-sample half. What f claims is the
 * light the bounces add, so each source is scored on its own change,
 * f(V_d) - V_d, against the truth's V'_d - V_d of its own world (odd half):
 * RMS over every scene and albedo (each weighted equally). */
typedef struct {
    int spp;                             /* of the height-field reference */
    double gain_rmse_3d, gain_rmse_hf;   /* RMS of (f(V_d) - V_d) - (V'_d - V_d) of the source's own truth */
    double difference, difference_se;    /* gain_rmse_hf - gain_rmse_3d; jackknife over scenes */
    double rmse_hf_v_d;                  /* the height field's V_d against the 3-D one (even half) */
    double rmse_total_3d, rmse_total_hf; /* f(V_d) against its own world's V'_d */
} multibounce_agnostic;

typedef struct {
    multibounce_gtao_row rows[MULTIBOUNCE_GTAO_PRESETS];
    multibounce_agnostic agnostic;
} multibounce_gtao_study;

/* The model's premise, "neighbouring albedos ~ the albedo of the current
 * point" (issue 25, item 1): per-object-albedo references (--albedo scene,
 * 4 bounces, the study's cameras and samples) of scenes whose floor and
 * objects differ in albedo, against the study's uniform references at each
 * pixel's own albedo (same paths, so V_d is the same to the bit): the
 * premise's error alone, the talk's f on both, and a correction a shader can
 * afford, rho_eff = rho + w (mean rho over a screen neighbourhood - rho),
 * w fitted (closed-form least squares) and held out by scene. */
enum { MULTIBOUNCE_CONTRAST_SCENES = 3, MULTIBOUNCE_CONTRASTS = 4 };

typedef struct {
    char scene[MULTIBOUNCE_STUDY_NAME];
    double floor_albedo, object_albedo;
    double premise_rms_object, premise_rms_floor; /* RMS of V'_d(contrast) - V'_d(uniform, own albedo) */
    double rmse_contrast, rmse_uniform;  /* f(V_d, own albedo) against V'_d of the contrast / uniform scene */
    double rmse_corrected_held_out;      /* f(V_d, rho_eff), w fitted without the scene */
} multibounce_contrast_row;

typedef struct {
    int count;
    multibounce_contrast_row rows[MULTIBOUNCE_CONTRAST_SCENES * MULTIBOUNCE_CONTRASTS];
    int radius_px;                       /* the neighbourhood: (2 r + 1)^2 pixels */
    double weight;                       /* w fitted on every scene */
    double weight_held_out[MULTIBOUNCE_CONTRAST_SCENES];
    /* means over the rows, and the jackknife over scenes */
    double mean_rmse_contrast, mean_rmse_uniform, mean_rmse_corrected;
    double premise_cost, premise_cost_se;       /* mean rmse_contrast - rmse_uniform */
    double correction_gain, correction_gain_se; /* mean rmse_corrected_held_out - rmse_contrast */
} multibounce_contrast_study;

/* Colour (issue 25, item 2): per-object coloured albedo references
 * (--albedo scene, 4 bounces), the talk's f per channel, f(V_d, rho_c),
 * against multibounce.R/G/B; DSSIM per channel and of the luminance (Rec.
 * 709 weights) of rho_c V'_c, the shaded result, with the noise floors;
 * beside it f with one grey albedo (the luminance of rho) in every channel. */
enum { MULTIBOUNCE_COLOUR_SCENES = 3 };
#define MULTIBOUNCE_LUMINANCE_R 0.2126 /* Rec. 709 / sRGB luminance weights */
#define MULTIBOUNCE_LUMINANCE_G 0.7152
#define MULTIBOUNCE_LUMINANCE_B 0.0722

typedef struct {
    char scene[MULTIBOUNCE_STUDY_NAME];
    double dssim_channel[3], noise_floor_dssim_channel[3];         /* R, G, B of V'_c */
    double dssim_luminance, noise_floor_dssim_luminance;          /* of sum_c w_c rho_c V'_c */
    double dssim_luminance_grey;                                  /* f with the luminance of rho in every channel */
    double rmse_luminance, rmse_luminance_grey;
} multibounce_colour_row;

typedef struct {
    multibounce_colour_row rows[MULTIBOUNCE_COLOUR_SCENES];
    double mean_dssim_luminance, mean_dssim_luminance_se; /* over the scenes (s.d. / sqrt(scenes)) */
    double mean_noise_floor_dssim_luminance, mean_dssim_luminance_grey;
} multibounce_colour_study;

typedef struct {
    /* the references */
    int bounces, spp, width, height; /* spp: the most a pixel takes */
    int substudy_spp;                /* every pixel's paths in the sub-studies' references (no budget) */
    double noise_budget;             /* the standard error a pixel stops at (quantity 0); 0: none */
    double total_seconds, total_paths, total_rays;
    double mean_spp;                 /* over the scenes' covered pixels */
    double noise_rmse;               /* sqrt of the mean of the scenes' noise_rmse^2: the held-out figures' */
    multibounce_render_row renders[MULTIBOUNCE_STUDY_SCENES];
    float albedo_values[MULTIBOUNCE_STUDY_ALBEDOS];
    /* the fit */
    multibounce_fit_summary fit;
    multibounce_coefficient_row coefficients[MULTIBOUNCE_COEFFICIENTS];
    int albedo_count;
    multibounce_albedo_row albedos[MBFIT_MAX_ALBEDOS];
    int heldout_rows;                    /* held-out scenes + the mean row */
    multibounce_heldout_row heldout[MBFIT_MAX_SCENES + 1];
    multibounce_findings findings;
    /* validation: scene-major, then albedo */
    int validation_count;
    multibounce_validation_row validation[MULTIBOUNCE_STUDY_SCENES * MULTIBOUNCE_STUDY_ALBEDOS];
    multibounce_validation_row validation_mean; /* over the rows, scene "mean" */
    multibounce_performance performance;
    multibounce_clamp clamp;
    multibounce_bounce_study bounce_counts;
    multibounce_gtao_study gtao_input;
    multibounce_contrast_study contrast;
    multibounce_colour_study colour;
} multibounce_study_result;

int multibounce_study(const study_context *ctx, multibounce_study_result *out, gt_error *e);

/* A multi-bounce reference's noise in RMSE^2 units: the mean over the
 * plan's V'_d channels (every albedo, each weighted equally as the fit
 * weighs them) of their mean squared standard error over the covered
 * pixels (metrics/noise_corrected.h, noise_mean_variance); *covered, when
 * not NULL, gets the covered pixel count. -1 with e when a channel has no
 * standard error. */
int multibounce_reference_noise_variance(const image *ref, const multibounce_plan *plan, double *variance,
                                         size_t *covered, gt_error *e);

/* The fit's rows and findings from an analysis of `d` (multibounce_analyse):
 * fit, coefficients, albedos, heldout and findings of out; the rest untouched. */
void multibounce_study_fit_rows(const multibounce_data *d, const multibounce_analysis *a,
                                multibounce_study_result *out);

/* model(V_d, rho) = gtao_multibounce at the n pixels with mask != 0, 0 in the background. */
void multibounce_apply_model(const multibounce_model *m, const float *visibility, const float *mask, size_t n,
                             float albedo, float *out);

#endif
