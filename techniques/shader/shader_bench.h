/* The cost of running a screen-space shader (`gtlab bench shader`; issue 15,
 * Performance): a shader under the contract of docs/shaders.md (e.g.
 * techniques/gtao/gtao.glsl, its gtlab.param defaults) over a 1920x1080
 * G-buffer of a scene (one primary ray per pixel: no path tracing), `frames` frames on a
 * Vulkan device, in one run (gpu_screen_pass_timed):
 *   dispatch    the device's wall time per frame, submission to fence: the
 *               shader's work alone
 *   per frame   gtlab's loop per frame: the Gtlab block and the cleared
 *               outputs uploaded, the dispatch, the read-back, the NaN check
 *               and the accumulation
 *   set-up      once per run: packing and uploading the G-buffer, building
 *               the pipeline (the driver compiles the SPIR-V there) and the
 *               descriptor set
 *   overhead    (per frame - dispatch) / per frame, gtlab's share of a
 *               frame; and with the set-up spread over the run's frames
 * and, apart, the shader's compile time (shaderc, once per run). Writes no
 * file. */
#ifndef GTLAB_SHADER_SHADER_BENCH_H
#define GTLAB_SHADER_SHADER_BENCH_H

#include <stdio.h>

#include "core/error.h"
#include "gpu/screen_pass.h"

enum { SHADER_BENCH_WIDTH = 1920, SHADER_BENCH_HEIGHT = 1080 };

typedef struct {
    const char *shader; /* F.glsl or F.hlsl, its gtlab.param defaults */
    const char *scene;  /* builtin:NAME or a glTF file */
    const char *device; /* a device name substring; NULL: the preferred device */
    int width, height, frames, threads; /* threads: the G-buffer's rendering only */
} shader_bench_request;

typedef struct {
    char device[256];
    int width, height, frames;
    double compile_seconds;    /* shaderc, once */
    gpu_screen_timing time;    /* set-up, per frame, dispatch */
    double overhead;           /* (per frame - dispatch) / per frame */
    double overhead_amortised; /* the same with set-up / frames added to a frame */
} shader_bench_result;

int shader_bench_run(const shader_bench_request *r, shader_bench_result *out, gt_error *e);
void shader_bench_print(FILE *out, const shader_bench_request *r, const shader_bench_result *b);

#endif
