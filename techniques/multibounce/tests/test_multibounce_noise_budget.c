/* The multi-bounce references under a noise budget (issue 46 item 1): every
 * pixel stops at a standard error of quantity 0 (V'_d at the first albedo)
 * at most the budget, or at the cap; and the noise the report states
 * (multibounce_reference_noise_variance) against a direct sum over the
 * channels and pixels. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/reference_schema.h"
#include "multibounce/multibounce_quantity.h"
#include "multibounce/multibounce_study.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

enum { SIZE = 16, CAP = 4096 };
static const double kBudget = 0.02;
static const float kAlbedos[2] = {0.1f, 0.9f};
static const char *const kAlbedoText[2] = {"0.1", "0.9"}; /* as the channel names write them */

static image render_budgeted(multibounce_plan *plan)
{
    gt_error e;
    scene s;
    camera cam;
    image img = {0};
    render_stats stats;
    multibounce_render_settings mb = {{QUANTITY_MULTIBOUNCE}, {.albedo_count = 2, .bounces = 4}};
    memcpy(mb.multibounce.albedos, kAlbedos, sizeof kAlbedos);
    reference_request req = {.quantity = QUANTITY_MULTIBOUNCE,
                             .sampling = {.spp = CAP, .seed = 5, .target_stderr = kBudget, .threads = 2},
                             .normals = NORMAL_SHADING,
                             .settings = &mb.header};
    int rc = scene_load("builtin:corner", &s, &e);
    if (rc == 0)
        rc = scene_choose_camera(&s, NULL, SIZE, SIZE, &cam, &e);
    if (rc == 0)
        rc = reference_render(&s, s.name, &cam, &req, &img, &stats, &e);
    if (rc == 0)
        rc = multibounce_plan_init(plan, &mb.multibounce, req.normals, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    scene_free(&s);
    return img;
}

/* Each covered pixel stopped at a power of two from 64 on, with quantity 0's
 * standard error within the budget unless it reached the cap; some stopped
 * early (the budget did something) and some took more than 64. */
static void check_stopping(const image *img)
{
    char first[64];
    snprintf(first, sizeof first, CH_MULTIBOUNCE_ALBEDO_FMT, kAlbedoText[0]);
    const float *mask = image_channel_data(img, CH_MASK), *spp = image_channel_data(img, CH_SPP);
    const float *se = schema_stderr_data(img, first);
    CHECK(mask && spp && se);
    int early = 0, beyond_first = 0, covered = 0;
    for (size_t i = 0; mask && spp && se && i < image_pixel_count(img); ++i) {
        if (mask[i] == 0.0f)
            continue;
        int n = (int)spp[i];
        ++covered;
        CHECK_MSG(n >= 64 && (n & (n - 1)) == 0, "pixel %zu: %d samples", i, n);
        CHECK_MSG(se[i] <= kBudget || n == CAP, "pixel %zu: stderr %g at %d samples", i, (double)se[i], n);
        early += n < CAP;
        beyond_first += n > 64;
    }
    CHECK_MSG(covered > SIZE * SIZE / 2 && early > 0 && beyond_first > 0, "covered %d, early %d, beyond 64 %d",
              covered, early, beyond_first);
}

/* The stated noise: the mean over both V'_d channels of the mean squared
 * standard error over covered pixels, summed here directly. */
static void check_noise(const image *img, const multibounce_plan *plan)
{
    const float *mask = image_channel_data(img, CH_MASK);
    double expected = 0.0;
    size_t count = 0;
    for (int a = 0; a < 2; ++a) {
        char name[64];
        snprintf(name, sizeof name, CH_MULTIBOUNCE_ALBEDO_FMT, kAlbedoText[a]);
        const float *se = schema_stderr_data(img, name);
        CHECK_MSG(se != NULL, "no standard error of %s", name);
        double sum = 0.0;
        count = 0;
        for (size_t i = 0; se && i < image_pixel_count(img); ++i)
            if (mask[i] != 0.0f) {
                sum += (double)se[i] * se[i];
                ++count;
            }
        expected += sum / (double)count / 2.0;
    }
    double variance = -1.0;
    size_t covered = 0;
    gt_error e;
    CHECK_MSG(multibounce_reference_noise_variance(img, plan, &variance, &covered, &e) == 0, "%s", e.message);
    CHECK_MSG(fabs(variance - expected) <= 1e-12 * expected, "noise variance %.17g, direct %.17g", variance, expected);
    CHECK(covered == count && variance > 0.0);
}

int main(void)
{
    multibounce_plan plan;
    image img = render_budgeted(&plan);
    check_stopping(&img);
    check_noise(&img, &plan);
    image_free(&img);
    return check_report("test_multibounce_noise_budget");
}
