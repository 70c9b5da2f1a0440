/* The cost of running a screen-space shader; see shader_bench.h. */
#include "shader/shader_bench.h"

#include <stdlib.h>
#include <string.h>

#include "core/progress.h"
#include "gpu/screen_pass.h"
#include "gpu/shader_interface.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "shader/shader_run.h"
#include "project/gbuffer_input.h"

typedef struct {
    char *source;
    gpu_shader_interface interface;
    gpu_spirv spirv;
    image gbuffer;
    int has_gbuffer;
    gpu_screen_input screen;
    gpu_device *device;
    float *planes;
} bench_state;

/* The shader's declarations (their defaults) and its SPIR-V, timed. */
static int compile_shader(const shader_bench_request *r, bench_state *s, shader_bench_result *out, gt_error *e)
{
    if (gpu_shader_interface_load(r->shader, NULL, 0, &s->source, &s->interface, e) != 0)
        return -1;
    double start = seconds_now();
    int rc = gpu_compile_compute(s->source, r->shader, gpu_source_language_of(r->shader), NULL, &s->spirv, e);
    out->compile_seconds = seconds_now() - start;
    return rc;
}

/* The scene's G-buffer at the bench's size, one primary ray per pixel, and
 * binding 0's camera. */
static int render_gbuffer(const shader_bench_request *r, bench_state *s, gt_error *e)
{
    scene sc;
    camera cam;
    if (scene_load(r->scene, &sc, e) != 0)
        return -1;
    reference_request req = {.quantity = QUANTITY_GBUFFER, .sampling = {.threads = r->threads},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    int rc = scene_choose_camera(&sc, NULL, r->width, r->height, &cam, e) != 0 ||
                     reference_render(&sc, r->scene, &cam, &req, &s->gbuffer, &stats, e) != 0
                 ? -1
                 : 0;
    scene_free(&sc);
    if (rc != 0)
        return -1;
    s->has_gbuffer = 1;
    ss_camera c = approx_ss_camera(&cam);
    shader_run_camera_globals(&c, &s->screen.globals);
    s->screen.globals.frames = r->frames;
    return gpu_screen_input_from_image(&s->gbuffer, r->scene, &s->screen, e);
}

/* The pass over the frames, timed. */
static int time_frames(const shader_bench_request *r, bench_state *s, shader_bench_result *out, gt_error *e)
{
    size_t count = (size_t)r->width * (size_t)r->height * (size_t)s->interface.output_count;
    if (gpu_device_open(r->device, &s->device, e) != 0)
        return -1;
    snprintf(out->device, sizeof out->device, "%s", gpu_device_name(s->device));
    s->planes = malloc(count * sizeof *s->planes);
    if (!s->planes)
        return gt_error_set(e, r->shader, "out of memory for %zu output floats", count);
    gpu_screen_timing *t = &out->time;
    if (gpu_screen_pass_timed(s->device, &s->spirv, r->shader, &s->screen, s->interface.param_value,
                              s->interface.param_count, s->interface.output_count, s->planes, 600.0, t, e) != 0)
        return -1;
    double amortised = t->frame_seconds + t->setup_seconds / r->frames;
    out->overhead = (t->frame_seconds - t->dispatch_seconds) / t->frame_seconds;
    out->overhead_amortised = (amortised - t->dispatch_seconds) / amortised;
    return 0;
}

int shader_bench_run(const shader_bench_request *r, shader_bench_result *out, gt_error *e)
{
    bench_state s;
    memset(&s, 0, sizeof s);
    memset(out, 0, sizeof *out);
    out->width = r->width, out->height = r->height, out->frames = r->frames;
    int rc = r->frames < 1 ? gt_error_set(e, r->shader, "--frames must be at least 1")
             : compile_shader(r, &s, out, e) != 0 || render_gbuffer(r, &s, e) != 0 || time_frames(r, &s, out, e) != 0
                 ? -1
                 : 0;
    gpu_device_close(s.device);
    gpu_spirv_free(&s.spirv);
    free(s.source);
    free(s.planes);
    if (s.has_gbuffer)
        image_free(&s.gbuffer);
    return rc;
}

void shader_bench_print(FILE *out, const shader_bench_request *r, const shader_bench_result *b)
{
    fprintf(out, "%s on %s, %dx%d G-buffer of %s, %d frames\n", r->shader, b->device, b->width, b->height, r->scene,
            b->frames);
    fprintf(out, "%-44s %12.2f\n", "compile (shaderc, once), ms", 1e3 * b->compile_seconds);
    fprintf(out, "%-44s %12.2f\n", "set-up (G-buffer upload, pipeline; once), ms", 1e3 * b->time.setup_seconds);
    fprintf(out, "%-44s %12.2f\n", "dispatch only, ms per frame", 1e3 * b->time.dispatch_seconds);
    fprintf(out, "%-44s %12.2f\n", "end to end, ms per frame", 1e3 * b->time.frame_seconds);
    fprintf(out, "%-44s %11.2f%%\n", "gtlab's overhead around the dispatch", 100.0 * b->overhead);
    fprintf(out, "%-44s %11.2f%%\n", "the same with the set-up over the frames", 100.0 * b->overhead_amortised);
}
