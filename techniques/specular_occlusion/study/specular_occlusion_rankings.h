/* Inside the specular-occlusion study (specular_occlusion/specular_occlusion_study.c): the
 * silhouette and interior regions of a reference, a variant's scores in
 * each, and the paired differences over scenes that the talk's rankings
 * (issue 26, items 2 and 3) are judged by. */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_RANKINGS_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_RANKINGS_H

#include "core/image.h"
#include "specular_occlusion/specular_occlusion_study.h"

typedef struct {
    int width, height;
    float *mask[SO_REGIONS];     /* 1 inside the region */
    long pixels[SO_REGIONS];     /* surface pixels in each */
} so_regions;

/* The regions of a reference from its G-buffer (positions, mask) and camera. */
int so_regions_from_reference(const image *ref, const char *what, so_regions *r, gt_error *e);
void so_regions_free(so_regions *r);

/* DSSIM and mean signed error (approx - truth) of approx in each region;
 * NaN for a region with no pixel (or, for DSSIM, no SSIM window centre). */
int so_region_scores(const float *truth, const float *approx, const so_regions *r, const char *what,
                     so_region_score out[SO_REGIONS], gt_error *e);

/* The variants the rankings compare, in every case of one setting. */
enum { SO_RANK_AO, SO_RANK_LAGARDE, SO_RANK_CONE, SO_RANK_DROBOT, SO_RANK_LOBE, SO_RANK_VARIANTS };
enum { SO_RANK_CASES = SO_STUDY_MAX_SCENES * SO_STUDY_ROUGHNESSES };

typedef struct {
    so_variant variants[SO_RANK_VARIANTS];
    double dssim[SO_RANK_VARIANTS][SO_RANK_CASES]; /* over the whole mask */
    so_region_score region[SO_RANK_VARIANTS][SO_RANK_CASES][SO_REGIONS];
    double floor_sum[SO_STUDY_ROUGHNESSES];        /* the reference's noise floor, summed over the scenes */
    int cases;
} so_ranking_scores;

/* The variants, with `lobe_lut` (not owned; the setting's 32^3 angles table). */
void so_ranking_scores_init(so_ranking_scores *s, const so_lut *lobe_lut);
/* Scores every variant on one more case (cases in scene-major, roughness-
 * minor order) against `reference` (one float per pixel of `in`). */
int so_ranking_scores_add(so_ranking_scores *s, const so_pixel_inputs *in, const float *reference,
                          const so_regions *regions, const char *what, gt_error *e);
/* The setting's rankings from its scores over `scenes` scenes. */
void so_ranking_setting_compute(const so_ranking_scores *s, int scenes, so_ranking_setting *out);

/* The per-case sums of so_cone_view_result (specular_occlusion_cone_view.c). */
typedef struct {
    const so_lut *lut; /* the GGX 32^3 angles table (not owned) */
    int strata, cases;
    double visibility[SO_RANK_CASES], dropped[SO_RANK_CASES], total[SO_RANK_CASES]; /* RMSE per case */
    double band_sq[SO_STUDY_ROUGHNESSES][SO_NV_BANDS];
    long band_count[SO_STUDY_ROUGHNESSES][SO_NV_BANDS];
} so_cone_view_scores;

/* One more case: the reference V_s (`reference`, its standard errors
 * `reference_stderr`) of the G-buffer and AO buffers b seen from eye. */
int so_cone_view_add(so_cone_view_scores *s, const so_screen_buffers *b, vec3 eye, const so_pixel_inputs *in,
                     const float *reference, const float *reference_stderr, int roughness_index, const char *what,
                     gt_error *e);
void so_cone_view_compute(const so_cone_view_scores *s, int scenes, so_cone_view_result *out);

/* a minus b over `scenes` scenes of per-case scores (case = scene *
 * SO_STUDY_ROUGHNESSES + roughness index, `stride` doubles apart): each
 * scene's mean over the roughnesses (roughness < 0) or its value at one
 * roughness, then their mean and its standard error over the scenes. Cases
 * with a NaN score are left out, a scene with none too. */
so_paired_difference so_paired_over_scenes(const double *a, const double *b, int stride, int scenes, int roughness);

#endif
