/* A screen-space shader made ready to score (scoring/screen_shader_program.h). */
#include "scoring/screen_shader_program.h"

#include <stdlib.h>
#include <string.h>

/* The plane of the shader's gtlab.output `channel`, or -1 with e. */
static int find_plane(screen_shader_program *p, const char *path, const char *channel, gt_error *e)
{
    for (int k = 0; k < p->interface.output_count; ++k)
        if (strcmp(p->interface.output_name[k], channel) == 0)
            return p->plane = k, 0;
    return gt_error_set(e, path, "no 'gtlab.output %s' line: the stage scores %s", channel, channel);
}

int screen_shader_prepare(const char *path, const char *const *params, int param_count, const char *channel,
                          screen_shader_program *out, gt_error *e)
{
    char *source = NULL;
    memset(out, 0, sizeof *out);
    int rc = gpu_shader_interface_load(path, params, param_count, &source, &out->interface, e) != 0 ||
             find_plane(out, path, channel, e) != 0 ||
             gpu_compile_compute(source, path, gpu_source_language_of(path), NULL, &out->spirv, e) != 0;
    free(source);
    return rc ? -1 : 0;
}

void screen_shader_program_free(screen_shader_program *p) { gpu_spirv_free(&p->spirv); }
