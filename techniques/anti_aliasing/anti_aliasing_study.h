/* Anti-aliasing against supersampled ground truth (issue 19, first part):
 * shaded frames of built-in scenes (raytracer/shaded_frame.h), the truth at
 * 16 (4 x 4) and 64 (8 x 8) stratified samples per pixel resolved with box
 * and Blackman-Harris filters (core/sampling/pixel_filter.h), and the techniques run
 * on one sample per pixel: none, FXAA 3.11 (anti_aliasing/fxaa.h), and 2 x 2
 * supersampling as a point of comparison. Everything is scored on display
 * values, d = sRGB(L / (1 + L)) (Reinhard, then the sRGB encode): the
 * truth is the filtered radiance, then displayed. Scores: RMSE over the RGB
 * display values and DSSIM of the display luma (Rec. 709 weights), against
 * the 64-sample truth with the same filter; the 16-sample truth's own RMSE
 * against the 64-sample one bounds the truth's error. Writes previews of the
 * first scene to <output>/aa/. */
#ifndef GTLAB_ANTI_ALIASING_ANTI_ALIASING_STUDY_H
#define GTLAB_ANTI_ALIASING_ANTI_ALIASING_STUDY_H

#include "anti_aliasing/aa_temporal_study.h"
#include "core/sampling/pixel_filter.h"
#include "project/study_context.h"

#define AA_DIR "anti_aliasing"

enum { AA_MAX_SCENES = 4, AA_TECHNIQUES = 3 };

typedef struct {
    int width, height;
    const char *scenes[AA_MAX_SCENES];
    int scene_count;
    unsigned seed;
    aa_temporal_request temporal; /* the second part (anti_aliasing/aa_temporal_study.h); frames 0: skipped */
} aa_request;

typedef struct {
    const char *scene, *technique, *filter;
    double rmse, dssim;
} aa_row;

typedef struct {
    const char *scene, *filter;
    double truth16_rmse; /* 16 against 64 samples per pixel */
} aa_truth_row;

typedef struct {
    aa_request request;
    int row_count, truth_count;
    aa_row rows[AA_MAX_SCENES * AA_TECHNIQUES * PIXEL_FILTER_COUNT];
    aa_truth_row truth[AA_MAX_SCENES * PIXEL_FILTER_COUNT];
    aa_temporal_result temporal;
} aa_result;

/* The request of `gtlab all` at a quality: its image size is the quality
 * table's (anti_aliasing rows of techniques/quality_table.txt); scenes boxes,
 * menger, cornell; the temporal part's aa_temporal_default_request. */
aa_request aa_default_request(study_quality quality);

int aa_study(const study_context *ctx, const aa_request *rq, aa_result *out, gt_error *e);

#endif
