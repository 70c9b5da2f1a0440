/* A reference stopped by its noise budget (issue 46 item 1) reaches it, and
 * the noise it reports is the noise it has. builtin:boxes at 40x32 with a
 * per-pixel budget b and a cap no pixel reaches: every covered pixel stops
 * at b (raytracer/render_loop.h's stop rule), so the noise RMSE the report
 * states, sqrt(mean stderr^2), is at most b; and the noise is no more than
 * stated: against an independent render (another seed, a fixed 4096
 * samples) the mean squared difference is at most the two renders' stated
 * mean variances, within k standard errors of a mean of squares over the
 * pixels (a mean of P squared residuals has relative standard error about
 * sqrt(2 / P)). The stated figure is an upper bound, not an estimate: the
 * per-pixel standard error is the independent-sample formula, and
 * Owen-scrambled Sobol' points converge faster than independent ones (on
 * this view the measured noise is about half the stated). */
#include <math.h>
#include <stdio.h>

#include "ao/ao_quantity.h"
#include "core/reference_schema.h"
#include "metrics/noise_corrected.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

enum { CAP = 65536, INDEPENDENT_SPP = 4096 };
static const double BUDGET = 0.03, K = 4.0;

static image render(const scene *s, const camera *cam, int spp, uint32_t seed, double target)
{
    gt_error e;
    image img = {0};
    reference_request req = {.quantity = QUANTITY_AO,
                             .sampling = {.spp = spp, .seed = seed, .target_stderr = target, .threads = 2},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    CHECK_MSG(reference_render(s, "builtin:boxes", cam, &req, &img, &stats, &e) == 0, "%s", e.message);
    return img;
}

int main(void)
{
    gt_error e;
    scene s;
    camera cam;
    CHECK_MSG(scene_load("builtin:boxes", &s, &e) == 0, "%s", e.message);
    CHECK(scene_choose_camera(&s, NULL, 40, 32, &cam, &e) == 0);
    image budgeted = render(&s, &cam, CAP, 1, BUDGET), independent = render(&s, &cam, INDEPENDENT_SPP, 99, 0.0);
    const float *mask = image_channel_data(&budgeted, CH_MASK), *n = image_channel_data(&budgeted, CH_SPP);
    const float *a = image_channel_data(&budgeted, CH_AO), *se = image_channel_data(&budgeted, CH_AO_STDERR);
    const float *b = image_channel_data(&independent, CH_AO);
    size_t count = image_pixel_count(&budgeted);
    double squares = 0.0;
    int covered = 0, capped = 0;
    for (size_t i = 0; i < count; ++i)
        if (mask[i] != 0.0f) {
            squares += ((double)a[i] - b[i]) * ((double)a[i] - b[i]);
            covered++, capped += n[i] >= CAP;
        }
    CHECK(covered > 500 && capped == 0);
    double stated = sqrt(noise_mean_variance(se, mask, count));
    CHECK_MSG(stated <= BUDGET, "stated noise %.4g above the budget %.4g", stated, BUDGET);
    double independent_variance = noise_mean_variance(image_channel_data(&independent, CH_AO_STDERR), mask, count);
    double bound = (stated * stated + independent_variance) * (1.0 + K * sqrt(2.0 / covered));
    CHECK_MSG(squares / covered <= bound, "mean squared difference %.4g above the stated %.4g", squares / covered,
              stated * stated + independent_variance);
    image_free(&budgeted);
    image_free(&independent);
    scene_free(&s);
    return check_report("ao_noise_budget");
}
