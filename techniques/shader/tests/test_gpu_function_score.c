/* The per-sample function contract (issue 15, items 3 and 5): gtlab's
 * template function (shaders/template_multibounce.glsl/.hlsl, the talk's
 * GTAOMultiBounce), wrapped and run on Vulkan over a multi-bounce reference,
 * scores within float rounding of the built-in C function; the example
 * plug-in (examples/multibounce_plugin.c, the same function in C) scores
 * exactly like it. Bad function files are one line each: shaderc's file:line
 * for a compile error, no gtlab_multibounce, a #version line, NaN.
 *
 * The bound: |RMSE(f) - RMSE(g)| <= RMS(f - g) <= max |f - g| (the triangle
 * inequality of the RMS over the same pixels), and per sample the float
 * shader is within 11 u S of the double C (u = 2^-24, S the cubic with
 * absolute coefficients: Horner's bound, docs/decisions.md "Shaders on
 * Vulkan"), so |RMSE_gpu - RMSE_c| <= 11 u max S over the albedos at V_d = 1. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/files/exr_io.h"
#include "multibounce/multibounce.h"
#include "multibounce/multibounce_quantity.h"
#include "raytracer/reference_render.h"
#include "shader/shader_scores.h"
#include "project/study_context.h"
#include "tests/check.h"
#include "tests/test_files.h"
#include "tests/test_reference_file.h"

static const float kAlbedos[] = {0.2f, 0.5f, 0.9f};
enum { ALBEDOS = 3 };

/* A small `gtlab render multibounce --albedo 0.2,0.5,0.9` of builtin:corner into path. */
static int render_reference(const char *path)
{
    multibounce_render_settings mb = {{QUANTITY_MULTIBOUNCE}, {.albedo_count = ALBEDOS, .bounces = 4}};
    memcpy(mb.multibounce.albedos, kAlbedos, sizeof kAlbedos);
    reference_request rq = {.quantity = QUANTITY_MULTIBOUNCE, .sampling = {.spp = 16, .seed = 1, .threads = 2},
                            .normals = NORMAL_SHADING, .settings = &mb.header};
    return test_render_reference_file("builtin:corner", 32, 24, &rq, path);
}

static double abs_poly(const double *k, int degree, double rho)
{
    double v = 0.0;
    for (int d = degree; d >= 0; --d)
        v = v * fabs(rho) + fabs(k[d]);
    return v;
}

/* 11 u max S (the header's bound) over the albedos. */
static double rmse_bound(void)
{
    multibounce_model m = multibounce_model_jimenez2016();
    double s = 0.0;
    for (int k = 0; k < ALBEDOS; ++k)
        s = fmax(s, abs_poly(m.a, m.degree, kAlbedos[k]) + abs_poly(m.b, m.degree, kAlbedos[k]) +
                        abs_poly(m.c, m.degree, kAlbedos[k]) + 1.0);
    return 11.0 * s / 16777216.0;
}

static void test_scores(const char *reference)
{
    static function_score_result r;
    const char *functions[] = {GTLAB_SOURCE_DIR "/shaders/template_multibounce.glsl",
                               GTLAB_SOURCE_DIR "/shaders/template_multibounce.hlsl"};
    const char *plugins[] = {GTLAB_EXAMPLE_PLUGIN};
    shader_score_request rq = {.references = &reference, .reference_count = 1,
                               .files = {functions, 2, plugins, 1, NULL, 60.0}};
    gt_error e = {{0}};
    CHECK_MSG(shader_score(&rq, &r, &e) == 0, "%s", e.message);
    function_score_print(stdout, &r);
    CHECK(r.variant_count == 5 && r.row_count == ALBEDOS && strcmp(r.variants[1].name, "talk") == 0);
    double bound = rmse_bound();
    for (int i = 0; i <= r.row_count && r.variant_count == 5; ++i) {
        const function_score_row *row = i < r.row_count ? &r.rows[i] : &r.mean;
        CHECK_MSG(row->dssim[4] == row->dssim[1] && row->rmse[4] == row->rmse[1], "%s: the plug-in differs",
                  row->scene);
        for (int k = 2; k <= 3; ++k)
            CHECK_MSG(fabs(row->rmse[k] - row->rmse[1]) <= bound, "%s %s: RMSE %.9g against %.9g (bound %.3g)",
                      row->scene, r.variants[k].name, row->rmse[k], row->rmse[1], bound);
        CHECK(row->rmse[1] > 0.0 && row->noise_floor_rmse > 0.0 && row->rmse[0] != row->rmse[1]);
    }
    printf("GLSL, HLSL - C: RMSE %.3g, %.3g (bound %.3g)\n", r.mean.rmse[2] - r.mean.rmse[1],
           r.mean.rmse[3] - r.mean.rmse[1], bound);
}

/* A function file with `text` scored: the error message. */
static void expect_error(const char *reference, const char *name, const char *text, const char *message)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", check_tmp_dir(), name);
    if (write_text_file(path, text) != 0) {
        CHECK_MSG(0, "cannot write %s", path);
        return;
    }
    static function_score_result r;
    const char *functions[] = {path};
    shader_score_request rq = {.references = &reference, .reference_count = 1,
                               .files = {functions, 1, NULL, 0, NULL, 60.0}};
    gt_error e = {{0}};
    char want[4200];
    snprintf(want, sizeof want, "%s%s", path, message);
    CHECK(shader_score(&rq, &r, &e) != 0);
    CHECK_MSG(strncmp(e.message, want, strlen(want)) == 0 && !strchr(e.message, '\n'), "%s (expected %s...)",
              e.message, want);
}

static void test_errors(const char *reference)
{
    expect_error(reference, "broken.glsl", "// line 1\nfloat gtlab_multibounce(float visibility, float albedo)\n"
                 "{\n    return visibilty;\n}\n", ":4: error: 'visibilty' : undeclared identifier");
    expect_error(reference, "broken.hlsl", "// line 1\n\nfloat gtlab_multibounce(float visibility, float albedo)\n"
                 "{\n    return visibilty;\n}\n", ":5: error: ");
    expect_error(reference, "signature.hlsl", "float gtlab_multibounce(float v) { return v; }\n",
                 ": gtlab cannot call float gtlab_multibounce(float visibility, float albedo) (the contract's "
                 "signature, docs/shaders.md): 'gtlab_multibounce' : no matching overloaded function found");
    expect_error(reference, "none.glsl", "float f(float x) { return x; }\n", ": defines no gtlab_multibounce");
    expect_error(reference, "version.glsl", "#version 450\nfloat gtlab_multibounce(float v, float a) { return v; }\n",
                 ": a function file has no #version line");
    expect_error(reference, "nan.glsl",
                 "float gtlab_multibounce(float v, float a) { return a > 0.4 ? uintBitsToFloat(0x7fc00000u) : v; }\n",
                 ": gtlab_multibounce(");
}

int main(void)
{
    char reference[4096];
    snprintf(reference, sizeof reference, "%s/function_score_corner.exr", check_tmp_dir());
    if (render_reference(reference) == 0) {
        test_scores(reference);
        test_errors(reference);
    }
    return check_report("test_gpu_function_score");
}
