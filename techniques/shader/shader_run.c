#define _POSIX_C_SOURCE 199309L
#include "shader/shader_run.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "core/progress.h"
#include "core/reference_schema.h"
#include "gpu/screen_pass.h"
#include "gpu/shader_interface.h"
#include "project/gbuffer_input.h"

/* What a run holds between its steps. */
typedef struct {
    char *source;
    gpu_shader_interface interface;
    approx_input input;
    int has_input;
    gpu_screen_input screen;
    image reference, output;
    int has_reference, has_output;
    float *planes;
} run_state;

/* The shader's text, its declarations and the --param values. */
static int read_shader(const shader_run_request *r, run_state *s, gt_error *e)
{
    if (gpu_shader_interface_load(r->shader, r->params, r->param_count, &s->source, &s->interface, e) != 0)
        return -1;
    for (int k = 0; k < s->interface.output_count; ++k)
        if (strcmp(s->interface.output_name[k], CH_MASK) == 0)
            return gt_error_set(e, r->shader, "gtlab.output %s: gtlab writes %s itself", CH_MASK, CH_MASK);
    return 0;
}

void shader_run_camera_globals(const ss_camera *c, gpu_screen_globals *g)
{
    memcpy(g->right, (float[4]){c->right.x, c->right.y, c->right.z, 0.0f}, sizeof g->right);
    memcpy(g->up, (float[4]){c->up.x, c->up.y, c->up.z, 0.0f}, sizeof g->up);
    memcpy(g->forward, (float[4]){c->forward.x, c->forward.y, c->forward.z, 0.0f}, sizeof g->forward);
    g->tan_half_yfov = c->tan_half_yfov;
    g->aspect = c->aspect;
}

/* The G-buffer, its camera as binding 0 wants it, and the reference. */
static int read_inputs(const shader_run_request *r, run_state *s, gt_error *e)
{
    if (approx_load(r->gbuffer, r->camera, &s->input, e) != 0)
        return -1;
    s->has_input = 1;
    if (gpu_screen_input_from_image(&s->input.img, r->gbuffer, &s->screen, e) != 0)
        return -1;
    shader_run_camera_globals(&s->input.g.camera, &s->screen.globals);
    s->screen.globals.frames = r->frames;
    if (r->reference && exr_read(r->reference, &s->reference, e) != 0)
        return -1;
    s->has_reference = r->reference != NULL;
    return 0;
}

/* Compiles and runs the shader on the device, into s->planes. */
static int run_on_device(const shader_run_request *r, run_state *s, shader_run_result *out, gt_error *e)
{
    gpu_device *device = NULL;
    gpu_spirv spirv = {0};
    size_t pixels = (size_t)s->screen.globals.width * (size_t)s->screen.globals.height;
    s->planes = malloc(pixels * (size_t)s->interface.output_count * sizeof *s->planes);
    if (!s->planes)
        return gt_error_set(e, r->gbuffer, "out of memory");
    int rc = gpu_compile_compute(s->source, r->shader, gpu_source_language_of(r->shader), r->entry, &spirv, e);
    if (rc == 0)
        rc = gpu_device_open(r->device, &device, e);
    if (rc == 0) {
        snprintf(out->device, sizeof out->device, "%s", gpu_device_name(device));
        rc = gpu_screen_pass(device, &spirv, r->shader, &s->screen, s->interface.param_value,
                             s->interface.param_count, s->interface.output_count, s->planes, r->timeout,
                             &out->seconds_per_frame, e);
    }
    gpu_device_close(device);
    gpu_spirv_free(&spirv);
    return rc;
}

/* "shader=gtao.glsl entry=main frames=1 radius=1 falloff=0.25" */
static void settings_text(const shader_run_request *r, const run_state *s, char *text, size_t size)
{
    size_t used = (size_t)snprintf(text, size, "shader=%s entry=%s frames=%d", r->shader, r->entry ? r->entry : "main",
                                   r->frames);
    for (int i = 0; i < s->interface.param_count && used < size; ++i)
        used += (size_t)snprintf(text + used, size - used, " %s=%.9g", s->interface.param_name[i],
                                 s->interface.param_value[i]);
}

/* The output image: mask.A, the header, the shader's planes. */
static int make_output(const shader_run_request *r, run_state *s, gt_error *e)
{
    char settings[2048];
    settings_text(r, s, settings, sizeof settings);
    if (approx_output_init(&s->input, "shader", settings, &s->output) != 0)
        return gt_error_set(e, r->output, "out of memory");
    s->has_output = 1;
    size_t pixels = (size_t)s->output.width * (size_t)s->output.height;
    for (int k = 0; k < s->interface.output_count; ++k) {
        float *plane = image_add_channel(&s->output, s->interface.output_name[k]);
        if (!plane)
            return gt_error_set(e, r->shader, "gtlab.output %s: cannot add the channel (a duplicate?)",
                                s->interface.output_name[k]);
        memcpy(plane, s->planes + (size_t)k * pixels, pixels * sizeof *plane);
    }
    return 0;
}

/* The output's channel against the reference's, as `gtlab compare` does. */
static int score(const shader_run_request *r, run_state *s, shader_run_result *out, gt_error *e)
{
    const char *channel = r->channel ? r->channel : s->interface.output_name[0];
    metrics_pair pair;
    if (metrics_pair_init(&pair, &s->reference, r->reference, &s->output, r->output, channel, e) != 0)
        return -1;
    int rc = metrics_pair_measure(&pair, &s->reference, r->reference, &s->output, r->output,
                                  metrics_is_reference_of(&s->reference, channel), NULL, &out->figures, e);
    metrics_pair_free(&pair);
    snprintf(out->channel, sizeof out->channel, "%s", channel);
    out->scored = rc == 0;
    return rc;
}

static void release(run_state *s)
{
    free(s->source);
    free(s->planes);
    if (s->has_input)
        approx_input_free(&s->input);
    if (s->has_reference)
        image_free(&s->reference);
    if (s->has_output)
        image_free(&s->output);
}

int shader_run(const shader_run_request *r, shader_run_result *out, gt_error *e)
{
    double start = seconds_now();
    run_state s;
    memset(&s, 0, sizeof s);
    memset(out, 0, sizeof *out);
    if (r->frames < 1)
        return gt_error_set(e, r->shader, "--frames must be at least 1");
    int rc = read_shader(r, &s, e) != 0 || read_inputs(r, &s, e) != 0 || run_on_device(r, &s, out, e) != 0 ||
                     make_output(r, &s, e) != 0 || (r->reference && score(r, &s, out, e) != 0) ||
                     exr_write(r->output, &s.output, e) != 0
                 ? -1
                 : 0;
    out->width = s.screen.globals.width;
    out->height = s.screen.globals.height;
    out->frames = r->frames;
    out->total_seconds = seconds_now() - start;
    release(&s);
    return rc;
}

void shader_run_print(FILE *out, const shader_run_result *r)
{
    fprintf(out, "%dx%d on %s: %.4g s per frame (device), %.4g s in all\n", r->width, r->height, r->device,
           r->seconds_per_frame, r->total_seconds);
    if (!r->scored)
        return;
    const metrics_pair_figures *f = &r->figures;
    fprintf(out, "%s: DSSIM %.6g, RMSE %.6g, max |A-B| %.6g", r->channel, f->ssim.dssim, f->error.rmse, f->error.max_abs);
    if (f->has_floor_a)
        fprintf(out, ", reference noise floor DSSIM %.6g", f->floor_a.dssim);
    fprintf(out, "\n");
}
