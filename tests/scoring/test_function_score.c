/* The scorer for any quantity (scoring/function_score.h) without a GPU: a
 * plug-in variant (the example, examples/multibounce_plugin.c) comes after
 * the built-ins, is applied to the quantity's inputs exactly as
 * plugins/plugin_loader.h applies it and so gives the talk's
 * GTAOMultiBounce bit for bit; a plug-in without the quantity's entry point
 * is refused when it is loaded; the mean row and each variant's means are
 * the means of the rows; a request with nothing, or too much, to score is
 * one line. */
#include <math.h>
#include <string.h>

#include "core/plugin_abi.h"
#include "multibounce/multibounce.h"
#include "multibounce/multibounce_study.h" /* multibounce_apply_model: where gtlab applies its own */
#include "scoring/function_score.h"
#include "tests/check.h"

enum { N = 257 };

static const function_score_quantity kMultibounce = {"multi-bounce", &gpu_function_multibounce,
                                                     GTLAB_MULTIBOUNCE_V1_SYMBOL};
static const function_score_quantity kSpecular = {"specular occlusion", &gpu_function_specular_occlusion,
                                                  GTLAB_SPECULAR_OCCLUSION_V1_SYMBOL};

static void test_plugin_variant(void)
{
    static function_score_result r;
    static float v[N], mask[N], built_in[N], scored[N];
    const char *plugins[] = {GTLAB_EXAMPLE_PLUGIN};
    function_score_files files = {.plugins = plugins, .plugin_count = 1};
    function_scorer *s = NULL;
    gt_error e = {{0}};
    memset(&r, 0, sizeof r);
    function_score_add_builtin(&r, "V_d");
    function_score_add_builtin(&r, "talk");
    CHECK_MSG(function_scorer_open(&kMultibounce, &files, &r, &s, &e) == 0, "%s", e.message);
    CHECK(r.variant_count == 3 && strcmp(r.variants[0].kind, "gtlab") == 0 &&
          strcmp(r.variants[2].name, "libgtlab_example_multibounce.so") == 0 &&
          strcmp(r.variants[2].kind, "plug-in") == 0 && r.device[0] == 0);
    for (int i = 0; i < N; ++i)
        v[i] = (float)i / (N - 1), mask[i] = i % 5 != 0 ? 1.0f : 0.0f;
    multibounce_model talk = multibounce_model_jimenez2016();
    multibounce_apply_model(&talk, v, mask, N, 0.7f, built_in);
    CHECK_MSG(function_scorer_apply(s, 2, (const float *const[]){v, NULL}, (const float[]){0.0f, 0.7f}, mask, N,
                                    scored, &e) == 0,
              "%s", e.message);
    CHECK(memcmp(built_in, scored, sizeof scored) == 0);
    function_scorer_close(s);
}

static void test_missing_entry_point(void)
{
    static function_score_result r;
    const char *plugins[] = {GTLAB_EXAMPLE_PLUGIN};
    function_score_files files = {.plugins = plugins, .plugin_count = 1};
    function_scorer *s = NULL;
    gt_error e = {{0}};
    memset(&r, 0, sizeof r);
    CHECK(function_scorer_open(&kSpecular, &files, &r, &s, &e) != 0);
    function_scorer_close(s);
    CHECK_MSG(strstr(e.message, "libgtlab_example_multibounce.so: exports no gtlab_specular_occlusion_v1 "
                                "(specular occlusion, core/plugin_abi.h)") != NULL,
              "%s", e.message);
}

static void test_means(void)
{
    static function_score_result r;
    memset(&r, 0, sizeof r);
    r.variant_count = 2, r.row_count = 3;
    for (int i = 0; i < 3; ++i) {
        r.rows[i].noise_floor_dssim = 0.5 * (i + 1), r.rows[i].noise_floor_rmse = 2.0 * (i + 1);
        r.rows[i].dssim[0] = 0.25 * i, r.rows[i].rmse[1] = 1.0 + i;
    }
    function_score_take_means(&r);
    CHECK(strcmp(r.mean.scene, "mean") == 0 && isnan(r.mean.value));
    CHECK(fabs(r.mean.noise_floor_dssim - 1.0) < 1e-15 && fabs(r.variants[1].rmse_floor - 4.0) < 1e-15);
    CHECK(fabs(r.variants[0].dssim - 0.25) < 1e-15 && r.variants[0].rmse == 0.0);
    CHECK(fabs(r.variants[1].rmse - 2.0) < 1e-15 && r.variants[1].dssim == 0.0);
}

static void test_bad_requests(void)
{
    const char *many[FUNCTION_SCORE_MAX_FILES + 1] = {0};
    function_score_files none = {0}, too_many = {.functions = many, .function_count = FUNCTION_SCORE_MAX_FILES + 1};
    gt_error e = {{0}};
    CHECK(function_score_check_files(&none, &e) != 0 && strstr(e.message, "nothing to score") != NULL);
    CHECK(function_score_check_files(&too_many, &e) != 0 && strstr(e.message, "at most 16 function files") != NULL);
}

int main(void)
{
    test_plugin_variant();
    test_missing_entry_point();
    test_means();
    test_bad_requests();
    return check_report("test_function_score");
}
