/* What a screen-space shader declares of itself to gtlab (docs/shaders.md),
 * in comment lines of its own text, so GLSL and HLSL read the same and the
 * shader stays valid for any other compiler:
 *   // gtlab.param NAME DEFAULT     one float of the Params block (binding 1),
 *                                   in the order of these lines
 *   // gtlab.output CHANNEL         one output plane (binding 3), in order,
 *                                   written to the output EXR as CHANNEL
 * `--param NAME=VALUE` replaces a default; a name the shader does not
 * declare is an error (no parameter is silently ignored). */
#ifndef GTLAB_GPU_SHADER_INTERFACE_H
#define GTLAB_GPU_SHADER_INTERFACE_H

#include "core/error.h"

#define GPU_MAX_PARAMS 64
#define GPU_MAX_OUTPUTS 8
#define GPU_NAME_MAX 64

typedef struct {
    int param_count;
    char param_name[GPU_MAX_PARAMS][GPU_NAME_MAX];
    float param_value[GPU_MAX_PARAMS];
    int output_count;
    char output_name[GPU_MAX_OUTPUTS][GPU_NAME_MAX];
} gpu_shader_interface;

/* Reads the declarations of `source` (named `name` in messages). At least
 * one output. Returns 0, or -1 with e = "<name>:<line>: <problem>". */
int gpu_shader_interface_parse(const char *source, const char *name, gpu_shader_interface *out, gt_error *e);

/* Applies "NAME=VALUE". Returns 0, or -1 with e naming the shader and the
 * parameters it declares. */
int gpu_shader_interface_set(gpu_shader_interface *s, const char *assignment, const char *name, gt_error *e);

/* A screen-space shader file read: its text into *source (malloc'd, the
 * caller frees it, also after an error), its declarations, and the
 * "NAME=VALUE" params applied. Returns 0, or -1 with e. */
int gpu_shader_interface_load(const char *path, const char *const *params, int param_count, char **source,
                              gpu_shader_interface *out, gt_error *e);

#endif
