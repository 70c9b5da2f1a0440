/* Specular occlusion (the `specular-occlusion` stage of `gtlab all`): how
 * close each real-time specular-occlusion variant of the GTSO talk (Jimenez
 * et al. 2016) and its baselines come to the Monte Carlo V_s.
 *
 * References: V_s = \int V f_r cos / \int f_r cos (GGX, alpha = r^2, no
 * Fresnel, view from the camera), VNDF-sampled under the analytic sky, of
 * every built-in scene at perceptual roughness 0.25, 0.5 and 0.8, with the
 * D-only and Phong definitions and the split integrals from the same samples
 * (specular_occlusion/specular_occlusion_integrator.h); an AO reference of the same
 * view gives the exact AO and bent normal, GTAO (high preset, one frame, no
 * radius limit) the shipped ones.
 *
 * Computed:
 *  - the cone/lobe LUT (GGX) at sizes 16, 32 (and 64 in production) in both
 *    axis parametrisations, and 16 and 32 (angles) as shipped in BC4:
 *    generation time, quadrature error estimate and trilinear interpolation
 *    error at random points;
 *  - every variant (specular_occlusion/specular_occlusion_screen.h) scored per
 *    roughness by DSSIM, RMSE and mean FLIP against specocc.V, means over
 *    the scenes;
 *    the main ones again on GTAO's inputs;
 *  - the noise floor of specocc.V, a ratio: DSSIM between the ratios of the
 *    even and of the odd samples' means;
 *  - the two- and three-split approximations against the split ground
 *    truth, and the truth's own half-sample noise floor;
 *  - the gloss-to-aperture fit of u (specular_occlusion/aperture_fit.h, exact cap
 *    intersection) against each reference definition, for the talk's cone
 *    and for the cone of reflected directions.
 *
 * Writes <output>/figures/specocc_ref_<scene>.png (V_s at r = 0.5) and
 * specocc_err_<scene>_<k>.png, |error| heatmaps (0 to 0.5) at r = 0.5 of the
 * rows so_study_heatmap_rows names, k = 0..3, and specocc_flip_<scene>_<k>.png,
 * their FLIP maps (magma, 0 to 1; the report draws the labelled colour bar). */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_STUDY_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_STUDY_H

#include "core/image.h"
#include "specular_occlusion/aperture_fit.h"
#include "raytracer/reference_render.h"
#include "specular_occlusion/specular_occlusion_lut.h"
#include "specular_occlusion/specular_occlusion_screen.h"
#include "project/study_context.h"
#include "project/scene_list.h"

enum {
    SO_STUDY_ROUGHNESSES = 3,
    SO_STUDY_MAX_SCENES = STUDY_SCENES_MAX,
    SO_STUDY_MAX_VARIANTS = 28,
    SO_STUDY_MAX_LUTS = 8,
    SO_STUDY_DEFINITIONS = 3, /* the reference definitions the aperture is fitted to */
    SO_STUDY_HEATMAPS = 4,
    SO_STUDY_MAP_ROUGHNESS = 1 /* the maps' roughness: so_study_roughness_values[1], r = 0.5 */
};

/* GTAO's inputs by the bent-normal estimator (issue 25, item 10, downstream):
 * gtlab's exact arc mean, the talk's halfway angles (each slice weighted by
 * its visibility), the talk's average of the two horizon vectors
 * (techniques/gtao/gtao_bent_horizons.h). The AO is the same in all three. */
typedef enum { SO_GTAO_ARC_MEAN = 1, SO_GTAO_HALFWAY, SO_GTAO_HORIZON_VECTORS } so_gtao_bent;
enum { SO_GTAO_INPUTS = 3 };

/* One variant on one kind of input. */
typedef struct {
    so_variant_kind kind;
    so_aperture_mapping mapping; /* cone variants */
    so_ao_weighting weighting;
    int lut_size;                /* SO_VARIANT_LUT: entries per axis */
    so_lut_axes lut_axes;        /* SO_VARIANT_LUT */
    int lut_bc4;                 /* SO_VARIANT_LUT: the table as shipped, BC4 (so_lut_bc4) */
    int on_gtao;                 /* fed by GTAO's AO and bent normal instead of the reference's: a so_gtao_bent
                                    (0: the reference's inputs) */
    char label[64];              /* for display: "cone-exact:exp2-alpha", "lut-ggx-32 on GTAO" */
    double dssim[SO_STUDY_ROUGHNESSES], rmse[SO_STUDY_ROUGHNESSES]; /* means over the scenes */
    double flip[SO_STUDY_ROUGHNESSES]; /* mean FLIP (metrics/flip.h, V_s the reference), means over the scenes */
    double mean_dssim, mean_flip;      /* means of dssim and flip over the roughnesses */
} so_variant_row;

/* One cone/lobe table. */
typedef struct {
    int size;
    so_lut_axes axes;
    const char *axes_name; /* so_lut_axes_name(axes) */
    const char *format;    /* "float" or "BC4" (decoded from BC4 as shipped) */
    double seconds;        /* generation (BC4: encoding and decoding) */
    double quadrature_error, max_interpolation_error, rms_interpolation_error;
} so_lut_row;

/* The split integrals at one roughness, means over the scenes. */
typedef struct {
    double roughness;
    double dssim_two, dssim_three, rmse_two, rmse_three;
    double noise_floor; /* DSSIM of split_truth.V's halves */
} so_split_row;

/* The gloss-to-aperture fit against one reference definition, with the
 * talk's cone (a_s = theta_m, SO_APERTURE_PHONG_U) and with the cone of
 * reflected directions (a_s = 2 theta_m, SO_APERTURE_PHONG_U_REFLECTED). */
typedef struct {
    const char *name;    /* "gtso", "d_only", "phong" */
    const char *channel; /* specocc.V, specocc_d.V, specocc_phong.V */
    aperture_fit fit, reflected;
} so_aperture_row;

/* A paired difference between two variants' scores: its mean over the
 * scenes and the mean's standard error (from the spread of the per-scene
 * differences), and how many scenes it pairs. */
typedef struct {
    double mean, standard_error;
    int cases;
} so_paired_difference;

/* The silhouette region (metrics/silhouette_region.h) of every reference:
 * surface pixels within SO_SILHOUETTE_RADIUS pixels of a depth jump of more
 * than SO_SILHOUETTE_JUMP of the view distance, or of the background. */
typedef enum { SO_REGION_SILHOUETTE, SO_REGION_INTERIOR, SO_REGIONS } so_region;
enum { SO_SILHOUETTE_RADIUS = 3 };
#define SO_SILHOUETTE_JUMP 0.1

/* One variant within a region: DSSIM (window centres in the region) and
 * mean signed error approximation - reference (negative: too dark). */
typedef struct {
    double dssim, bias;
} so_region_score;

/* The rankings the talk states (issue 26, items 2 and 3) in one setting:
 * each a paired difference "a minus b" over the scenes (each scene's mean
 * over the roughnesses, so the standard error counts scenes, not correlated
 * cases), except the gloss bands, paired over the scenes at one roughness.
 * "cone" is cone/cone with exact caps and the talk's cone cos a_s =
 * 2^(-3.32193 alpha^2) (u = 0.01), "lobe" the cone/lobe LUT 32^3 (angles) of
 * the setting's lobe. */
typedef struct {
    const char *name;      /* "talk" or "gtso" */
    const char *reference; /* the channel scored against: specocc_phong.V or specocc.V */
    const char *lobe;      /* so_lobe_name of the cone/lobe LUT */
    so_region_score cone[SO_REGIONS], lobe_score[SO_REGIONS]; /* means over the cases */
    so_paired_difference cone_minus_ao, cone_minus_lagarde; /* DSSIM over the whole mask */
    so_paired_difference lobe_minus_cone[SO_REGIONS];       /* DSSIM */
    so_paired_difference lobe_minus_cone_bias[SO_REGIONS];  /* mean signed error */
    so_paired_difference talk_minus_drobot[SO_STUDY_ROUGHNESSES]; /* DSSIM, cone/cone exp2-alpha minus drobot */
    double noise_floor_dssim[SO_STUDY_ROUGHNESSES];         /* of the reference channel, means over the scenes */
} so_ranking_setting;

/* The talk's setting (its comparisons "were done using Phong": the Phong
 * V_s, the Phong lobe in the LUT) and GTSO's (GGX f_r, the GGX LUT). */
typedef enum { SO_SETTING_TALK, SO_SETTING_GTSO, SO_SETTINGS } so_setting;

typedef struct {
    double silhouette_fraction; /* of the surface pixels, mean over the cases */
    so_ranking_setting settings[SO_SETTINGS];
} so_rankings;

/* The visibility cone against the real visibility, and the dimension the
 * 3-D table drops (issue 26, items 1 and 5), on the reference inputs: with
 * V_s^cone the GGX V_s whose visibility is the AO's cone (cosine AO, bent
 * normal) at the pixel's actual view (specular_occlusion/cone_visibility_view.h),
 *   visibility  V_s^cone vs the reference specocc.V: the cone's own error;
 *   dropped     the cone/lobe LUT 32^3 vs V_s^cone: its lobe taken at normal
 *               incidence (no n.v axis) and its interpolation;
 *   total       the LUT vs the reference.
 * RMSEs against the reference have its noise taken out
 * (metrics/noise_corrected.h). Per roughness: means over the scenes; per
 * n.v band: pooled over the scenes' pixels. */
enum { SO_NV_BANDS = 3 }; /* n.v in [0, 0.3), [0.3, 0.6), [0.6, 1] */
typedef struct {
    int strata; /* of V_s^cone's stratified estimate, per axis */
    double visibility_rmse[SO_STUDY_ROUGHNESSES], dropped_rmse[SO_STUDY_ROUGHNESSES],
        total_rmse[SO_STUDY_ROUGHNESSES];
    double dropped_rmse_band[SO_STUDY_ROUGHNESSES][SO_NV_BANDS];
    long band_pixels[SO_NV_BANDS];
    so_paired_difference visibility;               /* visibility RMSE (minus 0), over the scenes */
    so_paired_difference dropped;                  /* dropped RMSE (minus 0), over the scenes */
    so_paired_difference dropped_minus_visibility; /* dropped RMSE minus visibility RMSE, over the scenes */
} so_cone_view_result;

typedef struct {
    int size, spp;  /* of every reference (square images); spp the most a pixel takes */
    double noise_budget; /* the standard error of quantity 0 a pixel stops at; 0: every pixel takes spp */
    int lut_points; /* random points of the interpolation error */
    int scene_count;
    char scenes[SO_STUDY_MAX_SCENES][64]; /* study_scene_at order */
    /* Whether the closest variant (so_study_best_variants), not one of the
     * heatmap rows, has maps of its own: figures/specocc_err_<scene>_best.png
     * and specocc_flip_<scene>_best.png. */
    int best_maps;
    double roughness[SO_STUDY_ROUGHNESSES];
    int lut_count;
    so_lut_row luts[SO_STUDY_MAX_LUTS];
    int variant_count;
    so_variant_row variants[SO_STUDY_MAX_VARIANTS];
    double noise_floor_dssim[SO_STUDY_ROUGHNESSES]; /* of specocc.V, means over the scenes */
    double noise_floor_mean;                        /* their mean over the roughnesses */
    so_paired_difference bc4_16_cost;               /* DSSIM of lut 16^3 BC4 minus lut 32^3 float, over scenes */
    so_rankings rankings;
    /* the LUT 32^3 on GTAO with the talk's bent normals minus with the arc
     * mean, DSSIM paired over the scenes (issue 25, item 10, downstream) */
    so_paired_difference bent_halfway_cost, bent_vectors_cost;
    /* issue 26, item 6: the cap intersection by Tovchigrechko & Vakser 2001
     * and by Mazonka 2012, largest |difference| over a 97^3 grid of
     * crossing configurations (spherical_caps_compare_derivations) */
    double caps_max_difference;
    long caps_configurations;
    so_cone_view_result cone_view;
    so_split_row splits[SO_STUDY_ROUGHNESSES];
    so_aperture_row fits[SO_STUDY_DEFINITIONS]; /* gtso, d_only, phong */
    double reference_samples_per_second;        /* mean over the specular-occlusion renders */
} so_study_result;

int specular_occlusion_study(const study_context *ctx, so_study_result *out, gt_error *e);

/* The study's references, as it renders them (it keeps them in memory
 * only): the image size (square) and samples per pixel for ctx's quality,
 * the roughnesses, and one scene view's AO reference (q = QUANTITY_AO,
 * roughness < 0) or specular-occlusion reference at a roughness (seed 1,
 * the analytic sky). specular_occlusion/specular_occlusion_score.h renders them again
 * for a project's functions: the same request, the same images. */
void so_study_resolution(const study_context *ctx, int *size, int *spp);
extern const float so_study_roughness_values[SO_STUDY_ROUGHNESSES];
int so_study_render(const study_context *ctx, const scene *s, const char *spec, const camera *cam, reference_quantity q,
                    float roughness, image *out, render_stats *stats, gt_error *e);

/* How the study scores a variant (also specular_occlusion/specular_occlusion_score.h's
 * way): DSSIM and RMSE of approx against truth over the mask, and its mean
 * FLIP (truth the reference) when flip_sum is not NULL, added to the sums. */
int so_study_add_scores(const float *truth, const float *approx, const float *mask, int width, int height,
                        const char *what, double *dssim_sum, double *rmse_sum, double *flip_sum, gt_error *e);

/* The noise floor of a ratio channel of a specular-occlusion reference:
 * DSSIM (and RMSE, when rmse is not NULL) between the ratios of the even and
 * of the odd samples' means, over the mask. */
int so_study_ratio_noise_floor(const image *ref, const char *what, const char *channel, double *dssim, double *rmse,
                               gt_error *e);

/* The row of a variant (lut_size and lut_axes matter for SO_VARIANT_LUT,
 * mapping for the cone variants only), or -1. */
int so_study_find(const so_study_result *r, so_variant_kind kind, so_aperture_mapping mapping, int lut_size,
                  so_lut_axes lut_axes, int on_gtao);
/* The row of the BC4 table of `lut_size` (angles, reference inputs), or -1. */
int so_study_find_bc4(const so_study_result *r, int lut_size);

/* The rows of the heatmaps k = 0..3: AO, Lagarde, cone/cone exact with
 * exp2(-3.32 alpha^2), the LUT 32^3 (angles), all on the reference's inputs. */
void so_study_heatmap_rows(const so_study_result *r, int rows[SO_STUDY_HEATMAPS]);

/* The closest and the next closest variant to the Monte Carlo reference,
 * by mean DSSIM, among those on the reference's inputs (which technique to
 * ship is judged on the same inputs for all). */
void so_study_best_variants(const so_study_result *r, int *best, int *runner_up);

#endif
