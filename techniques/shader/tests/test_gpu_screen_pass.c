/* The screen-space contract end to end (issue 15, items 2 and 4):
 * techniques/gtao/gtao.glsl and techniques/gtao/gtao.hlsl, gtlab's GTAO in one
 * configuration (one source, techniques/gtao/gtao.inc, behind each
 * language's bindings), run by `gtlab shader run`'s study (techniques/shader/shader_run.c) on a built-in scene's
 * G-buffer EXR, against the C gtao_frame on the same G-buffer; then the
 * failures that must leave no output behind.
 *
 * The bound (docs/decisions.md, "Shaders on Vulkan"): the shader places its
 * samples where the C does (the same float expressions; `precise`: no fused
 * multiply-adds), so what differs is the rounding of cos, sin, acos, sqrt and
 * division. Vulkan allows cos and sin an absolute error of 2^-11; a slice's
 * arc integral, 1/4 sum over both sides of (-cos(2h - n) + cos n + 2h sin n)
 * with |h| <= pi, may then be off by 1/4 * 2 * (2 + 2 pi) * 2^-11 = 2.0e-3,
 * and the AO (a mean of slices, each weighted by n_len <= 1) by as much.
 * Checked for each language: max |gpu - c| <= 2e-3 (lavapipe: about 9e-5),
 * and the score's largest difference is that maximum. The bound holds for
 * HLSL unchanged: glslang's HLSL front end emits the same SPIR-V operations
 * (GLSL.std.450 Cos, Sin, Acos; NoContraction on `precise`), under the same
 * Vulkan precision rules. */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/files/exr_io.h"
#include "gpu/shader_compiler.h"
#include "gpu/shader_interface.h"
#include "gtao/gtao.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "shader/shader_run.h"
#include "project/gbuffer_input.h"
#include "tests/check.h"

static const char kCamera[] = "{\"position\":[0,26,0],\"target\":[0,0,0],\"up\":[0,0,-1],\"yfov_deg\":40,"
                              "\"width\":64,\"height\":48}";

static char g_path[4096], out_path[4096], ref_path[4096];

/* builtin:boxes' G-buffer, written where the study reads it. */
static int write_gbuffer(void)
{
    gt_error e;
    scene s;
    camera cam;
    image img;
    if (scene_load("builtin:boxes", &s, &e) != 0 || camera_parse_json(kCamera, "test camera", &cam, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return -1;
    }
    reference_request req = {.quantity = QUANTITY_GBUFFER, .sampling = {.spp = 1, .seed = 7, .threads = 2},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    int rc = reference_render(&s, "builtin:boxes", &cam, &req, &img, &stats, &e);
    scene_free(&s);
    if (rc == 0)
        rc = exr_write(g_path, &img, &e);
    if (rc == 0)
        image_free(&img);
    if (rc != 0)
        fprintf(stderr, "%s\n", e.message);
    return rc;
}

/* The C GTAO in the shader's configuration (its gtlab.param defaults), as a
 * reference EXR (ao.V) beside the G-buffer, and in ao. */
static int c_gtao(float **ao)
{
    approx_input in;
    gt_error e;
    if (approx_load(g_path, NULL, &in, &e) != 0) {
        fprintf(stderr, "%s\n", e.message);
        return -1;
    }
    gtao_params p = gtao_params_shader_port();
    image out;
    int rc = approx_output_init(&in, "gtao", "test", &out);
    float *plane = rc == 0 ? image_add_channel(&out, "ao.V") : NULL;
    *ao = malloc(sizeof **ao * (size_t)in.g.width * (size_t)in.g.height);
    if (plane && *ao) {
        gtao_frame(&in.g, &p, 0, plane, NULL);
        memcpy(*ao, plane, sizeof **ao * (size_t)in.g.width * (size_t)in.g.height);
        rc = exr_write(ref_path, &out, &e);
    } else
        rc = -1;
    if (rc == 0)
        image_free(&out);
    approx_input_free(&in);
    return rc;
}

/* The shader's gtlab.param defaults are gtao_params_shader_port's: the C
 * GTAO it is compared with here (and in the screen-shaders stage) is its own
 * configuration. */
static void test_defaults_are_the_c_configuration(const char *shader)
{
    const gtao_params c = gtao_params_shader_port();
    const char *names[6] = {"radius", "falloff", "max_radius_px", "slices", "steps", "thickness"};
    const float want[6] = {c.radius, c.falloff, c.max_radius_px, (float)c.slices, (float)c.steps, c.thickness};
    char *source = NULL;
    gpu_shader_interface s;
    gt_error e;
    CHECK_MSG(gpu_read_source(shader, &source, &e) == 0 && gpu_shader_interface_parse(source, shader, &s, &e) == 0,
              "%s", e.message);
    free(source);
    for (int k = 0; k < 6; ++k) {
        int found = 0;
        for (int i = 0; i < s.param_count; ++i) {
            if (strcmp(s.param_name[i], names[k]) != 0)
                continue;
            found = 1;
            CHECK_MSG(s.param_value[i] == want[k], "%s: %s = %g, the C's %g", shader, names[k],
                      (double)s.param_value[i], (double)want[k]);
        }
        CHECK_MSG(found, "%s declares no %s", shader, names[k]);
    }
}

static shader_run_request request(const char *shader)
{
    return (shader_run_request){.shader = shader, .gbuffer = g_path, .output = out_path, .frames = 1,
                                .timeout = 60.0};
}

static void test_gtao_matches_c(const float *ao, const char *shader)
{
    shader_run_request r = request(shader);
    r.reference = ref_path;
    r.channel = "ao.V";
    shader_run_result result;
    gt_error e = {{0}};
    int rc = shader_run(&r, &result, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    image out;
    if (rc != 0 || exr_read(out_path, &out, &e) != 0)
        return;
    const float *gpu = image_channel_data(&out, "ao.V");
    size_t n = (size_t)out.width * (size_t)out.height;
    double worst = 0.0, sum = 0.0;
    for (size_t i = 0; gpu && i < n; ++i) {
        worst = fmax(worst, fabs(gpu[i] - ao[i]));
        sum += fabs(gpu[i] - ao[i]);
    }
    CHECK(gpu != NULL && result.scored);
    printf("%s on %s: max |gpu - c| %.3g (bound 2e-3), mean %.3g; DSSIM %.3g, %.3g s per frame\n",
           strrchr(shader, '/') + 1, result.device, worst, sum / (double)n, result.figures.ssim.dssim, result.seconds_per_frame);
    CHECK(worst <= 2e-3);
    CHECK_NEAR(result.figures.error.max_abs, worst, 1e-7);
    image_free(&out);
}

/* A failing run: its one line contains `want`, and out_path is not written. */
static void check_fails(const shader_run_request *r, const char *want)
{
    shader_run_result result;
    gt_error e = {{0}};
    unlink(out_path);
    CHECK(shader_run(r, &result, &e) != 0);
    CHECK_MSG(strstr(e.message, want) != NULL && !strchr(e.message, '\n'), "\"%s\" lacks \"%s\"", e.message, want);
    CHECK_MSG(access(out_path, F_OK) != 0, "%s was written by a failing run", out_path);
}

static const char *write_shader(const char *name, const char *text)
{
    static char path[4096];
    snprintf(path, sizeof path, "%s/%s", check_tmp_dir(), name);
    FILE *f = fopen(path, "w");
    if (f)
        fputs(text, f), fclose(f);
    return path;
}

/* --frames 3 with a shader that writes frame 0 only: the mean is 1/3 where
 * it writes (each frame starts from zeros) and 0 in the background; and a
 * write far past the outputs' end is dropped (robust buffer access). */
static void test_frames_average(void)
{
    shader_run_request r = request(write_shader(
        "frame0.glsl", "#version 450\n// gtlab.output ao.V\nlayout(local_size_x = 8, local_size_y = 8) in;\n"
                       "layout(std140, binding = 0) uniform Gtlab { vec4 r, u, f; float t, a; int width, height, "
                       "frame, frames, present, reserved; };\n"
                       "layout(std430, binding = 2) readonly buffer G { float g[]; };\n"
                       "layout(std430, binding = 3) writeonly buffer O { float o[]; };\n"
                       "void main() { int i = int(gl_GlobalInvocationID.y) * width + int(gl_GlobalInvocationID.x);\n"
                       "  if (gl_GlobalInvocationID.x < uint(width) && gl_GlobalInvocationID.y < uint(height) && "
                       "frame == 0 && g[11 * width * height + i] != 0.0) o[i] = 1.0;\n"
                       "  o[i + 50000000] = 7.0; }\n"));
    r.frames = 3;
    shader_run_result result;
    gt_error e = {{0}};
    image out, gbuffer;
    int rc = shader_run(&r, &result, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    if (rc != 0 || exr_read(out_path, &out, &e) != 0 || exr_read(g_path, &gbuffer, &e) != 0)
        return;
    const float *v = image_channel_data(&out, "ao.V"), *mask = image_channel_data(&gbuffer, "mask.A");
    int wrong = 0;
    for (size_t i = 0; v && mask && i < (size_t)out.width * (size_t)out.height; ++i)
        wrong += v[i] != (mask[i] != 0.0f ? 1.0f / 3.0f : 0.0f);
    CHECK_MSG(v && mask && wrong == 0, "%d pixels are not the mean of frames 1, 0, 0", wrong);
    image_free(&out);
    image_free(&gbuffer);
}

static void test_failures(void)
{
    shader_run_request r = request(GTLAB_SOURCE_DIR "/techniques/gtao/gtao.glsl");
    const char *params[1] = {"radius_typo=2"};
    r.params = params, r.param_count = 1;
    check_fails(&r, "--param radius_typo: the shader declares no such parameter (its gtlab.param lines: radius,");
    r = request(write_shader("broken.glsl", "#version 450\n// gtlab.output ao.V\nlayout(local_size_x = 8, "
                                            "local_size_y = 8) in;\nvoid main() { undeclared_thing = 1.0; }\n"));
    check_fails(&r, "broken.glsl:4: error: 'undeclared_thing' : undeclared identifier");
    r = request(write_shader("nan.glsl", "#version 450\n// gtlab.output ao.V\nlayout(local_size_x = 8, local_size_y = "
                                         "8) in;\nlayout(std430, binding = 3) writeonly buffer O { float o[]; };\n"
                                         "layout(std430, binding = 2) readonly buffer G { float g[]; };\n"
                                         "void main() { o[gl_GlobalInvocationID.y * 64u + gl_GlobalInvocationID.x]"
                                         " = sqrt(g[0] - 1e30); }\n"));
    check_fails(&r, "nan.glsl: NaN in output outputs at element");
    r = request(write_shader("includes.hlsl", "// gtlab.output ao.V\n\n#include \"no_such_file.inc\"\n"));
    check_fails(&r, "includes.hlsl:3: error:");
    write_shader("loop.inc", "#include \"loop.inc\"\n");
    r = request(write_shader("loop.glsl", "#version 450\n// gtlab.output ao.V\n#include \"loop.inc\"\n"));
    check_fails(&r, "error: '#include' : includes nested more than 32 deep (an include loop?)");
}

int main(void)
{
    snprintf(g_path, sizeof g_path, "%s/screen_pass_gbuffer.exr", check_tmp_dir());
    snprintf(out_path, sizeof out_path, "%s/screen_pass_out.exr", check_tmp_dir());
    snprintf(ref_path, sizeof ref_path, "%s/screen_pass_gtao_c.exr", check_tmp_dir());
    float *ao = NULL;
    if (write_gbuffer() != 0 || c_gtao(&ao) != 0)
        return 1;
    test_defaults_are_the_c_configuration(GTLAB_SOURCE_DIR "/techniques/gtao/gtao.glsl");
    test_defaults_are_the_c_configuration(GTLAB_SOURCE_DIR "/techniques/gtao/gtao.hlsl");
    test_gtao_matches_c(ao, GTLAB_SOURCE_DIR "/techniques/gtao/gtao.glsl");
    test_gtao_matches_c(ao, GTLAB_SOURCE_DIR "/techniques/gtao/gtao.hlsl");
    test_frames_average();
    test_failures();
    free(ao);
    return check_report("test_gpu_screen_pass");
}
