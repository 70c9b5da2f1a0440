/* `gtlab shader run` (issue 15, item 2): a user's screen-space shader
 * (GLSL or HLSL, docs/shaders.md) run on Vulkan over a G-buffer EXR, its
 * outputs written to an EXR, and optionally scored against a reference
 * channel like `gtlab compare` (DSSIM, RMSE, the reference's noise floor). */
#ifndef GTLAB_SHADER_SHADER_RUN_H
#define GTLAB_SHADER_SHADER_RUN_H

#include <stdio.h>

#include "core/error.h"
#include "gpu/screen_pass.h"
#include "metrics/image_pair.h"
#include "realtime/screen_space.h"

typedef struct {
    const char *shader;    /* F.glsl or F.hlsl */
    const char *entry;     /* NULL: main */
    const char *gbuffer;   /* an EXR with depth.Z, N.X/Y/Z, mask.A and a camera */
    const char *camera;    /* NULL: the G-buffer's own (gbuffer_input.h) */
    const char *output;    /* the EXR written: the shader's outputs and mask.A */
    const char *reference; /* NULL: no scoring */
    const char *channel;   /* the reference channel scored (NULL: the first output) */
    const char *device;    /* a device name substring (NULL: the preferred device) */
    const char *const *params; /* "name=value" */
    int param_count;
    int frames;     /* >= 1 */
    double timeout; /* seconds per frame */
} shader_run_request;

typedef struct {
    char device[256];
    int width, height, frames;
    double seconds_per_frame; /* device wall time, mean over the frames */
    double total_seconds;     /* the whole run: reading, compiling, running, scoring, writing */
    int scored;
    char channel[64];
    metrics_pair_figures figures;
} shader_run_result;

/* Binding 0's camera (basis, tan_half_yfov, aspect) from a screen-space camera. */
void shader_run_camera_globals(const ss_camera *c, gpu_screen_globals *g);

/* Runs it. Returns 0, or -1 with e the one line naming the file at fault;
 * on failure nothing is written. */
int shader_run(const shader_run_request *request, shader_run_result *result, gt_error *e);

/* The run as `gtlab shader run` prints it: size, device, seconds per frame
 * and, when scored, DSSIM, RMSE, max |A-B| and the reference's noise floor. */
void shader_run_print(FILE *out, const shader_run_result *r);

#endif
