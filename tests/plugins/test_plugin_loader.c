/* The C plug-in loader (plugins/plugin_loader.h; core/plugin_abi.h, issue
 * 15, item 5): the example plug-in examples/multibounce_plugin.c,
 * GTAOMultiBounce with the talk's coefficients, loaded with dlopen and
 * applied where gtlab applies its own function (multibounce_apply_model),
 * its albedo a constant input repeated, gives the built-in's values bit for
 * bit and so exactly its scores (DSSIM, RMSE against a target); an entry
 * point it does not export, a library that is not a plug-in, or no
 * library, is one clear line. */
#include <math.h>
#include <string.h>

#include "metrics/image_error.h"
#include "metrics/ssim.h"
#include "multibounce/multibounce.h"
#include "multibounce/multibounce_study.h" /* multibounce_apply_model: where gtlab applies its own */
#include "plugins/plugin_loader.h"
#include "tests/check.h"

enum { W = 96, H = 64, N = W * H };

/* V_d over [0, 1] in a smooth pattern, a background corner, and a target. */
static void inputs(float *v, float *mask, float *target)
{
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            int i = y * W + x;
            v[i] = 0.5f + 0.5f * sinf(0.11f * x) * cosf(0.07f * y);
            mask[i] = x + y > 12 ? 1.0f : 0.0f;
            target[i] = mask[i] * powf(v[i], 0.6f);
        }
}

static void score(const float *approx, const float *target, const float *mask, double *dssim, double *rmse)
{
    ssim_result s;
    image_error_stats err;
    gt_error e = {{0}};
    CHECK_MSG(ssim_compute(approx, target, mask, W, H, "test", NULL, &s, &e) == 0 &&
                  image_error_compute(approx, target, mask, W, H, "test", &err, &e) == 0,
              "%s", e.message);
    *dssim = s.dssim, *rmse = err.rmse;
}

static void test_scores_like_built_in(void)
{
    static float v[N], mask[N], target[N], built_in[N], plugged[N];
    gtlab_plugin p;
    gt_error e = {{0}};
    CHECK_MSG(plugin_open(GTLAB_EXAMPLE_PLUGIN, &p, &e) == 0, "%s", e.message);
    if (!p.handle)
        return;
    inputs(v, mask, target);
    multibounce_model talk = multibounce_model_jimenez2016();
    static const float albedos[] = {0.0f, 0.3f, 0.6f, 0.9f, 1.0f};
    for (int k = 0; k < 5; ++k) {
        multibounce_apply_model(&talk, v, mask, N, albedos[k], built_in);
        CHECK_MSG(plugin_apply(&p, GTLAB_MULTIBOUNCE_V1_SYMBOL, 2, (const float *const[]){v, NULL},
                               (const float[]){0.0f, albedos[k]}, mask, N, plugged, "example", &e) == 0,
                  "%s", e.message);
        CHECK_MSG(memcmp(built_in, plugged, sizeof built_in) == 0, "albedo %g: the plug-in's values differ", albedos[k]);
        double d1, r1, d2, r2;
        score(built_in, target, mask, &d1, &r1);
        score(plugged, target, mask, &d2, &r2);
        CHECK(d1 == d2 && r1 == r2 && r1 > 0.0);
        printf("albedo %.1f: built-in DSSIM %.9g RMSE %.9g, plug-in DSSIM %.9g RMSE %.9g\n", albedos[k], d1, r1, d2,
               r2);
    }
    plugin_close(&p);
}

/* The example exports the multi-bounce entry point only: the other is one line naming it. */
static void test_missing_entry_point(void)
{
    static float v[N], mask[N], target[N], out[N];
    gtlab_plugin p;
    gt_error e = {{0}};
    CHECK_MSG(plugin_open(GTLAB_EXAMPLE_PLUGIN, &p, &e) == 0, "%s", e.message);
    if (!p.handle)
        return;
    CHECK(plugin_exports(&p, GTLAB_MULTIBOUNCE_V1_SYMBOL) && !plugin_exports(&p, GTLAB_SPECULAR_OCCLUSION_V1_SYMBOL));
    inputs(v, mask, target);
    CHECK(plugin_apply(&p, GTLAB_SPECULAR_OCCLUSION_V1_SYMBOL, 4, (const float *const[]){v, v, v, v},
                       (const float[]){0}, mask, N, out, "example", &e) != 0);
    CHECK_MSG(strcmp(e.message, "example: the plug-in has no gtlab_specular_occlusion_v1") == 0, "%s", e.message);
    plugin_close(&p);
    CHECK(p.handle == NULL);
}

static void test_not_a_plugin(void)
{
    gtlab_plugin p;
    gt_error e = {{0}};
    CHECK(plugin_open("libm.so.6", &p, &e) != 0 && p.handle == NULL);
    CHECK_MSG(strcmp(e.message, "libm.so.6: not a gtlab plug-in: no gtlab_plugin_abi() (core/plugin_abi.h)") == 0,
              "%s", e.message);
    CHECK(plugin_open("/nonexistent/libnothing.so", &p, &e) != 0);
    CHECK_MSG(strncmp(e.message, "/nonexistent/libnothing.so: cannot load the plug-in: ", 53) == 0 &&
                  !strchr(e.message, '\n'),
              "%s", e.message);
}

int main(void)
{
    test_scores_like_built_in();
    test_missing_entry_point();
    test_not_a_plugin();
    return check_report("test_plugin_loader");
}
