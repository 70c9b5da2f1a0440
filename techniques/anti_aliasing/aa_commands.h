/* What `gtlab render frames`, `gtlab approx aa` and `gtlab bench aa` run
 * (issue 19), the bodies of the command-line face (anti_aliasing_cli.c), in
 * the study part so that tests reach them:
 *   aa_frames_write   frames of a scene along a camera path, one EXR each
 *                     (linear colour, depth, motion, disocclusion; names from
 *                     core/reference_schema.h), with a technique's jitter,
 *                     and if asked the frame's truth: S x S stratified
 *                     jittered samples per pixel (the same strata every
 *                     frame, as the study's) resolved by a pixel filter;
 *   aa_approx         a technique over those frames, one display PNG and EXR
 *                     (display values) per frame;
 *   aa_bench          milliseconds per 1920 x 1080 frame of each technique in C. */
#ifndef GTLAB_ANTI_ALIASING_AA_COMMANDS_H
#define GTLAB_ANTI_ALIASING_AA_COMMANDS_H

#include <stdio.h>

#include "anti_aliasing/aa_temporal_study.h"
#include "core/error.h"

enum { AA_FRAMES_TRUTH_SEED = 1 }; /* the truth's strata jitter: the same every frame */

typedef struct {
    const char *scene;       /* builtin:NAME or a glTF file */
    int width, height, frames;
    float step[3], yaw_deg;  /* the camera path: translation and yaw per frame */
    int technique;           /* whose jitter (and, for aa_approx, which technique): 0 .. AA_T_TECHNIQUES - 1 */
    const char *dir;         /* output folder */
    int threads;
    int truth_strata;        /* aa_frames_write: 0, or S (S x S samples a pixel) */
    int truth_filter;        /* a pixel_filter (core/sampling/pixel_filter.h) */
} aa_frames_request;

/* The technique's index from its short name (none, fxaa, taa, edge-taa,
 * checkerboard), or -1; and its short name. */
int aa_technique_parse(const char *name);
const char *aa_technique_short_name(int technique);

/* Writes dir/frame_NNN.exr for every frame. */
int aa_frames_write(const aa_frames_request *rq, gt_error *e);
/* Writes dir/<technique>_NNN.exr (frame.R/G/B display values) and .png. */
int aa_approx(const aa_frames_request *rq, gt_error *e);
/* ms[t]: mean milliseconds per 1080p frame of technique t over `frames`
 * frames (a synthetic image of edges every 5 and 7 pixels, a slow pan);
 * aa_bench_print runs 8 frames and prints one line per technique. */
int aa_bench(int threads, int frames, double ms[AA_T_TECHNIQUES], gt_error *e);
int aa_bench_print(FILE *out, int threads, gt_error *e);

#endif
