/* The GTAO talk's setting for its claims rows (issue 42, item 4, "the
 * talk's setting first"): a 1080p frame whose AO is computed at half
 * resolution (PS4, 960x540). gtlab renders a scene's G-buffer at 1920x1080
 * from its AO reference's camera (the same position, target and vertical
 * field of view, the frame widened to 16:9; primary rays only: about a
 * second on 2 cores) and halves it as the talk's pass does (each 2x2
 * block's covered pixel closest to the camera, gtao_depth_mip.h).
 * No Monte Carlo reference is rendered at this size (a 16-spp 3-D AO
 * reference of one 1080p frame takes ~19 s on 2 cores, a converged one many
 * minutes): the rows measured here are a shortcut's own change (GTAO with
 * it minus without it) or GTAO against its own brute force, which need none.
 *
 * The radius: the talk's horizon samples count fully to 150 inches and fade
 * to none at 200 ("Minimizing Artifacts"); gtlab reads 200 inches as a
 * quarter of the camera's distance to its target (as the distance-fade
 * study does) and the fade as the radius's last quarter (falloff 0.25, the
 * presets' default), the screen radius unclamped (the pass's width). The
 * references' "no radius limit" is not the talk's regime: 4 samples per
 * side spread over the whole screen.
 *
 * The scenes (gtao_talk_scene): of the built-in ones, boxes (64 boxes
 * standing on a floor) and cornell (a room with two blocks) at every
 * quality: the closest to the talk's game levels, objects on floors and
 * walls meeting at creases, the horizontal and vertical features its row
 * order is chosen for, where contact occlusion is what AO is for; menger
 * (thin detail, the hardest case for half resolution) and corner at
 * production. On a project's scenes: its first (preview) or first two. */
#ifndef GTLAB_GTAO_GTAO_TALK_SETTING_H
#define GTLAB_GTAO_GTAO_TALK_SETTING_H

#include "gtao/gtao.h"
#include "gtao/gtao_depth_mip.h"
#include "project/gbuffer_input.h"
#include "project/study_context.h"

enum { GTAO_TALK_WIDTH = 1920, GTAO_TALK_HEIGHT = 1080 };
#define GTAO_TALK_RADIUS_FRACTION 0.25f /* of the camera's distance to its target: the talk's 200 inches */
#define GTAO_TALK_FALLOFF 0.25f         /* the talk's 150 to 200 inches */

typedef struct {
    approx_input full;   /* the 1920x1080 G-buffer and its camera */
    ss_half_gbuffer half; /* its 960x540 half, the talk's AO pass */
    float camera_distance; /* from the camera to its target */
} gtao_talk_frame;

/* 1 if the scene `label` is one of the talk-setting scenes at ctx's quality. */
int gtao_talk_scene(const study_context *ctx, const char *label);
/* The frame of scene `label` seen from `reference_camera` (its size
 * ignored). Returns 0, or -1 with e (nothing to free then). */
int gtao_talk_frame_render(const study_context *ctx, const char *label, const camera *reference_camera,
                           gtao_talk_frame *out, gt_error *e);
void gtao_talk_frame_free(gtao_talk_frame *f);
/* p's radius, falloff and screen radius set to the talk's on `pass` (its
 * AO pass, e.g. the frame's half) of a camera camera_distance from its
 * target. */
void gtao_talk_radius(float camera_distance, const ss_gbuffer *pass, gtao_params *p);

#endif
