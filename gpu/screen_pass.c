#include "gpu/screen_pass.h"

#include <stdlib.h>
#include <string.h>

#include "core/progress.h"
#include "core/reference_schema.h"
#include "gpu/compute_dispatch.h"

const char *const gpu_gbuffer_channel_names[GPU_GB_CHANNELS] = {
    CH_DEPTH, CH_N_X,       CH_N_Y,       CH_N_Z,       CH_P_X,  CH_P_Y,    CH_P_Z,    CH_ALBEDO_R,
    CH_ALBEDO_G, CH_ALBEDO_B, CH_ROUGHNESS, CH_MASK, CH_BENT_X, CH_BENT_Y, CH_BENT_Z};

static int required(int c)
{
    return c == GPU_GB_DEPTH || c == GPU_GB_N_X || c == GPU_GB_N_Y || c == GPU_GB_N_Z || c == GPU_GB_MASK;
}

int gpu_screen_input_from_image(const image *img, const char *what, gpu_screen_input *in, gt_error *e)
{
    in->globals.width = img->width;
    in->globals.height = img->height;
    in->globals.present = 0;
    for (int c = 0; c < GPU_GB_CHANNELS; ++c) {
        in->planes[c] = image_channel_data(img, gpu_gbuffer_channel_names[c]);
        if (!in->planes[c] && required(c))
            return gt_error_set(e, what, "missing channel %s (a G-buffer needs depth.Z, N.X, N.Y, N.Z and mask.A; "
                                         "'gtlab render gbuffer' writes them)", gpu_gbuffer_channel_names[c]);
        in->globals.present |= in->planes[c] ? 1 << c : 0;
    }
    return 0;
}

/* Binding 2: the planes one after another, zeros for absent ones. */
static float *pack_gbuffer(const gpu_screen_input *in, size_t pixels)
{
    float *packed = calloc(GPU_GB_CHANNELS * pixels, sizeof *packed);
    for (int c = 0; packed && c < GPU_GB_CHANNELS; ++c)
        if (in->planes[c])
            memcpy(packed + (size_t)c * pixels, in->planes[c], pixels * sizeof *packed);
    return packed;
}

/* out += frame / frames, plane by plane. */
static void accumulate(float *out, const float *frame, size_t count, int frames)
{
    for (size_t i = 0; i < count; ++i)
        out[i] += frame[i] / (float)frames;
}

/* One dispatch per frame, each into `frame_out`, averaged into out: the
 * pipeline and the G-buffer's upload once, per frame only the Gtlab block
 * and the outputs' read-back (the device clears them). t: the session's set-up (added),
 * the frames' wall and device time. */
static int run_frames(gpu_device *device, gpu_dispatch *d, gpu_screen_globals *globals, float *frame_out,
                      float *out, size_t count, gpu_screen_timing *t, gt_error *e)
{
    int frames = globals->frames, rc = 0;
    double start = seconds_now();
    gpu_dispatch_session *session;
    memset(out, 0, count * sizeof *out);
    if (gpu_dispatch_open(device, d, &session, e) != 0)
        return -1;
    t->setup_seconds += seconds_now() - start;
    start = seconds_now();
    for (int f = 0; f < frames && rc == 0; ++f) {
        double dispatch = 0.0;
        globals->frame = f;
        rc = gpu_dispatch_frame(session, &dispatch, e); /* outputs start as zeros: a pixel left unwritten is 0 */
        if (rc == 0)
            accumulate(out, frame_out, count, frames);
        t->dispatch_seconds += dispatch / frames;
    }
    t->frame_seconds = (seconds_now() - start) / frames;
    gpu_dispatch_close(session);
    return rc;
}

int gpu_screen_pass_timed(gpu_device *device, const gpu_spirv *shader, const char *what, const gpu_screen_input *in,
                          const float *params, int param_count, int outputs, float *out, double timeout,
                          gpu_screen_timing *timing, gt_error *e)
{
    double start = seconds_now();
    gpu_screen_globals globals = in->globals;
    size_t pixels = (size_t)globals.width * (size_t)globals.height, count = pixels * (size_t)outputs;
    memset(timing, 0, sizeof *timing);
    if (globals.frames < 1 || outputs < 1 || pixels == 0)
        return gt_error_set(e, what, "nothing to run: %d frames, %d outputs, %zu pixels", globals.frames, outputs,
                            pixels);
    float block[64 + 4] = {0}; /* Params: at least 16 bytes */
    memcpy(block, params, (size_t)(param_count < 64 ? param_count : 64) * sizeof *params);
    float *packed = pack_gbuffer(in, pixels), *frame_out = calloc(count, sizeof *frame_out);
    gpu_buffer buffers[4] = {{"Gtlab", GPU_UNIFORM, &globals, sizeof globals},
                             {"Params", GPU_UNIFORM, block, ((size_t)param_count + 3) / 4 * 16 + 16},
                             {"gbuffer", GPU_INPUT, packed, GPU_GB_CHANNELS * pixels * sizeof(float)},
                             {"outputs", GPU_OUTPUT, frame_out, count * sizeof(float)}};
    gpu_dispatch d = {shader, what, buffers, 4,
                      {(uint32_t)(globals.width + GPU_SCREEN_GROUP - 1) / GPU_SCREEN_GROUP,
                       (uint32_t)(globals.height + GPU_SCREEN_GROUP - 1) / GPU_SCREEN_GROUP, 1},
                      timeout};
    timing->setup_seconds = seconds_now() - start;
    int rc = packed && frame_out ? run_frames(device, &d, &globals, frame_out, out, count, timing, e)
                                 : gt_error_set(e, what, "out of memory for a %dx%d G-buffer", globals.width,
                                                globals.height);
    free(packed);
    free(frame_out);
    return rc;
}

int gpu_screen_pass(gpu_device *device, const gpu_spirv *shader, const char *what, const gpu_screen_input *in,
                    const float *params, int param_count, int outputs, float *out, double timeout, double *seconds,
                    gt_error *e)
{
    gpu_screen_timing t;
    int rc = gpu_screen_pass_timed(device, shader, what, in, params, param_count, outputs, out, timeout, &t, e);
    if (seconds)
        *seconds = t.dispatch_seconds;
    return rc;
}
