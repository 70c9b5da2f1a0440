/* Temporal anti-aliasing against supersampled truth (issue 19, second part):
 * frames along camera paths (scene/camera_path.h) of scenes with thin
 * geometry, alpha-tested cards and high-frequency texture
 * (builtin:aa-thin), rendered per technique with its own jitter and exact
 * motion vectors (anti_aliasing/frames_render.h), and the truth of every frame
 * at 16 and 64 stratified samples per pixel, Blackman-Harris resolve (the
 * same jittered strata every frame, so a static truth does not change). On
 * display values (aa_display):
 *   none          the unjittered frame;
 *   FXAA 3.11     on it;
 *   TAA           the conventional accumulating TAA (anti_aliasing/taa_accumulate.h),
 *                 Halton (2, 3) jitter of period 8;
 *   edge TAA      the talk's 2-frame edge-sample TAA (anti_aliasing/taa_edge.h);
 *   checkerboard  the talk's corner checkerboard (anti_aliasing/checkerboard.h),
 *                 half the samples a frame;
 *   checkerboard 2x  the same at twice the width and height (the talk's
 *                 2160p checkerboard beside its 1080p TAA: twice the
 *                 samples a frame per screen area of the edge TAA), shown
 *                 on the W x H display by a 2 x 2 box (the display's
 *                 footprint); a study row only (AA_T_ROWS), not one of
 *                 aa_work's techniques.
 * Scores (frames from AA_T_WARMUP on, so every technique has its history):
 * RMSE and DSSIM per frame against the 64- and 16-sample truths, their
 * means; flicker, the RMS over pixels and frames of (o_k - o_{k-1}) -
 * (t_k - t_{k-1}), the frame-to-frame change the truth does not have;
 * ghosting, the RMSE over the pixels disoccluded since the previous frame
 * (frames_render.h's exact mask), where reprojected history is wrong;
 * settle, on the static path the largest RMS change o_k - o_{k-1} over
 * frames k >= 2 (0 when the output is final after two frames). Each of
 * RMSE, flicker and ghosting also as this row's minus every other's on the
 * same path with a standard error: the difference of the two RMS values,
 * its error from the per-pixel sums linearised (delta method) and
 * clustered over 8x8-pixel blocks (metrics/cluster_mean.h). */
#ifndef GTLAB_ANTI_ALIASING_AA_TEMPORAL_STUDY_H
#define GTLAB_ANTI_ALIASING_AA_TEMPORAL_STUDY_H

#include "core/error.h"
#include "metrics/cluster_mean.h"
#include "raytracer/embree_scene.h"
#include "scene/camera.h"
#include "project/study_context.h"

enum { AA_T_TECHNIQUES = 5, AA_T_PATHS = 2, AA_T_MAX_SCENES = 2, AA_T_MAX_FRAMES = 64, AA_T_WARMUP = 4 };
/* The error maps' scale: the mean over RGB of |rgb - truth|, inferno from 0 to this. */
#define AA_T_ERROR_MAP_MAX 0.25f
/* The study's rows per path: the techniques, then the checkerboard at 2x. */
enum { AA_T_CHECKER_2X = AA_T_TECHNIQUES, AA_T_ROWS = AA_T_TECHNIQUES + 1 };

typedef struct {
    int width, height, frames;
    const char *scenes[AA_T_MAX_SCENES];
    int scene_count;
    unsigned seed;
} aa_temporal_request;

typedef struct {
    const char *scene, *path, *technique;
    double rmse, dssim;     /* means against the 64-sample truth */
    double rmse16, dssim16; /* against the 16-sample truth */
    double flicker;         /* RMS of the change the truth does not have */
    double ghost_rmse;      /* RMSE over disoccluded pixels (0 if none) */
    double settle;          /* largest RMS of o_k - o_{k-1} over k >= 2 */
    double rmse_frame[AA_T_MAX_FRAMES];
    int frames; /* scored (after the warm-up) */
    /* this technique's DSSIM minus each other's on the same path, per pixel
     * averaged over the scored frames, with its 8x8-block standard error */
    cluster_mean dssim_minus[AA_T_ROWS];
    /* the same for RMSE, flicker and ghosting (RMS differences, delta-method
     * standard errors over 8x8 blocks) */
    cluster_mean rmse_minus[AA_T_ROWS], flicker_minus[AA_T_ROWS], ghost_minus[AA_T_ROWS];
} aa_temporal_row;

typedef struct {
    const char *scene, *path;
    double truth16_rmse;  /* 16 against 64 samples, mean over frames */
    double truth_change;  /* RMS of the truth's own t_k - t_{k-1} */
    double disoccluded;   /* fraction of pixels disoccluded a frame */
} aa_temporal_truth;

typedef struct {
    aa_temporal_request request;
    int row_count, truth_count;
    aa_temporal_row rows[AA_T_MAX_SCENES * AA_T_PATHS * AA_T_ROWS];
    aa_temporal_truth truth[AA_T_MAX_SCENES * AA_T_PATHS];
} aa_temporal_result;

extern const char *const aa_temporal_technique_names[AA_T_ROWS];
extern const char *const aa_temporal_path_names[AA_T_PATHS];

/* The request of `gtlab all` at a quality: its frames' size and count are the
 * quality table's (anti_aliasing temporal_* rows of techniques/quality_table.txt);
 * builtin:aa-thin. */
aa_temporal_request aa_temporal_default_request(study_quality quality);

/* The techniques' state along one camera path (its histories), for
 * `gtlab approx aa` and `gtlab bench aa`: aa_work_frame renders frame k's
 * inputs (prev NULL for k = 0) and runs every technique on them;
 * aa_work_run runs them on one given display image and motion field used
 * as every technique's input (the benchmark). Frames in order from k = 0. */
typedef struct aa_work aa_work;
aa_work *aa_work_new(int width, int height); /* NULL if out of memory */
void aa_work_delete(aa_work *w);
int aa_work_frame(aa_work *w, const embree_scene *es, const camera *now, const camera *prev, int k, int threads);
int aa_work_run(aa_work *w, const float *input, const float *motion, int k, int threads);
const float *aa_work_output(const aa_work *w, int technique); /* W x H RGB display values */
double aa_work_seconds(const aa_work *w, int technique);      /* its time so far (wall clock) */

/* Runs the study, writing frame strips and error maps to <output>/aa/. */
int aa_temporal_study(const study_context *ctx, const aa_temporal_request *rq, aa_temporal_result *out, gt_error *e);

/* The display value of linear radiance L (Reinhard, then sRGB): what both
 * anti-aliasing studies compare. */
float aa_display(float radiance);

#endif
