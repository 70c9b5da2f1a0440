/* A user's screen-space shader (docs/shaders.md's screen-space contract)
 * made ready to score, for any channel it writes: its declarations with the
 * caller's parameters applied, its SPIR-V, and which output plane holds the
 * scored channel. The project reader compiles each screen shader with it
 * before any work (project/project_file.h), the stage screen-shaders runs
 * them (techniques/shader/screen_shader_score.h). No device is needed. */
#ifndef GTLAB_SCORING_SCREEN_SHADER_PROGRAM_H
#define GTLAB_SCORING_SCREEN_SHADER_PROGRAM_H

#include "core/error.h"
#include "gpu/shader_compiler.h"
#include "gpu/shader_interface.h"

typedef struct {
    gpu_shader_interface interface;
    gpu_spirv spirv;
    int plane; /* the output plane of the scored channel */
} screen_shader_program;

/* Reads, checks and compiles the shader `path` with `params` ("name=value",
 * as --param takes them) applied. Returns 0, or -1 with e the one line
 * naming the file: shaderc's message and line for a compile error, an
 * unknown parameter, no `gtlab.output <channel>` line. */
int screen_shader_prepare(const char *path, const char *const *params, int param_count, const char *channel,
                          screen_shader_program *out, gt_error *e);
void screen_shader_program_free(screen_shader_program *p);

#endif
