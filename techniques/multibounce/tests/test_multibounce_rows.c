/* The multi-bounce study's rows and findings (multibounce/multibounce_study.h) from an
 * analysis of synthetic data, and its model pass over an image: standard
 * errors positive, the farthest coefficient really the farthest, our fit at
 * least as good as the talk's on its own data and each albedo's own cubic at
 * least as good as the joint fit on that albedo, the held-out table's mean
 * row, and the two-step gap of data rendered on the same pixels for every
 * albedo (least squares decomposes exactly then). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "multibounce/multibounce_study.h"
#include "tests/check.h"

enum { SCENES = 3, PIXELS = 600 };
static const float kAlbedos[3] = {0.3f, 0.5f, 0.9f};

/* A number in [-0.5, 0.5) from a hash of i. */
static double noise(uint64_t i)
{
    i = (i ^ (i >> 30)) * 0xBF58476D1CE4E5B9ull;
    i = (i ^ (i >> 27)) * 0x94D049BB133111EBull;
    i ^= i >> 31;
    return (double)(i >> 11) * 0x1p-53 - 0.5;
}

/* The talk's curve raised by a bump that differs by scene, plus noise; every
 * albedo sees the same V_d at the same pixel, as one multi-bounce pass. */
static void synthesise(multibounce_data *d)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    gt_error e;
    for (int s = 0; s < SCENES; ++s) {
        char name[32];
        snprintf(name, sizeof name, "builtin:scene%d", s);
        int scene = multibounce_data_scene(d, name, &e);
        for (int k = 0; k < 3; ++k) {
            int a = multibounce_data_albedo(d, kAlbedos[k], &e);
            for (int i = 0; i < PIXELS; ++i) {
                double v = (i + 0.5) / PIXELS;
                double y = gtao_multibounce(&talk, v, kAlbedos[k]) + (0.04 + 0.02 * s) * v * (1.0 - v) +
                           0.01 * noise((uint64_t)(s * PIXELS + i));
                CHECK(multibounce_data_push(d, scene, a, (float)v, (float)fmin(y, 1.0), &e) == 0);
            }
        }
    }
    multibounce_data_weigh(d);
}

static void check_coefficients(const multibounce_study_result *r)
{
    const multibounce_findings *f = &r->findings;
    for (int i = 0; i < MULTIBOUNCE_COEFFICIENTS; ++i) {
        const multibounce_coefficient_row *c = &r->coefficients[i];
        CHECK(c->standard_error > 0.0 && c->jackknife_se > 0.0);
        CHECK(c->rho_power == i % 2 && c->name[0] == "abc"[i / 2]);
        CHECK(fabs(c->talk - c->ours) / c->standard_error <= f->farthest_pixels_sigmas);
        CHECK(fabs(c->talk - c->ours) / c->jackknife_se <= f->farthest_scenes_sigmas);
    }
    const multibounce_coefficient_row *p = &r->coefficients[f->farthest_pixels], *s = &r->coefficients[f->farthest_scenes];
    CHECK_NEAR(fabs(p->talk - p->ours) / p->standard_error, f->farthest_pixels_sigmas, 1e-12);
    CHECK_NEAR(fabs(s->talk - s->ours) / s->jackknife_se, f->farthest_scenes_sigmas, 1e-12);
}

static void check_errors(const multibounce_study_result *r)
{
    CHECK(r->fit.samples == (uint64_t)SCENES * 3 * PIXELS && r->fit.scenes == SCENES && r->fit.albedos == 3);
    CHECK(r->fit.rmse_ours <= r->fit.rmse_talk);
    CHECK(r->fit.max_error_talk >= r->fit.rmse_talk && r->fit.max_error_ours >= r->fit.rmse_ours);
    CHECK(r->albedo_count == 3);
    for (int k = 0; k < r->albedo_count; ++k) {
        CHECK(r->albedos[k].albedo == (double)kAlbedos[k]);
        CHECK(r->albedos[k].rmse_own <= r->albedos[k].rmse_joint + 1e-6);
        CHECK(r->albedos[k].se_a > 0.0 && r->albedos[k].se_b > 0.0 && r->albedos[k].se_c > 0.0);
    }
    CHECK(r->findings.two_step_gap >= 0.0 && r->findings.two_step_gap < 1e-4);
}

static void check_heldout(const multibounce_study_result *r)
{
    CHECK(r->heldout_rows == SCENES + 1 && r->fit.heldout_scenes == SCENES);
    double talk = 0.0;
    int talk_better = 0;
    for (int i = 0; i < SCENES; ++i) {
        const multibounce_heldout_row *h = &r->heldout[i];
        CHECK(!h->is_mean && h->samples == 3 * PIXELS && strncmp(h->scene, "builtin:scene", 13) == 0);
        CHECK(!isnan(h->rmse_linear) && !isnan(h->rmse_quadratic) && !isnan(h->rmse_anchored));
        talk += h->rmse_talk / SCENES;
        talk_better += h->rmse_talk < h->rmse_linear;
    }
    const multibounce_heldout_row *mean = &r->heldout[SCENES];
    CHECK(mean->is_mean && strcmp(mean->scene, "mean") == 0 && mean->samples == r->fit.samples);
    CHECK_NEAR(mean->rmse_talk, talk, 1e-12);
    CHECK(mean->rmse_linear == r->fit.heldout_mean_rmse_linear);
    CHECK(r->findings.talk_better_heldout == talk_better);
}

static void test_rows_from_synthetic_data(void)
{
    static multibounce_study_result r;
    static multibounce_analysis a;
    multibounce_data d;
    gt_error e;
    multibounce_data_init(&d);
    synthesise(&d);
    CHECK_MSG(multibounce_analyse(&d, &a, &e) == 0, "%s", e.message);
    multibounce_study_fit_rows(&d, &a, &r);
    check_coefficients(&r);
    check_errors(&r);
    check_heldout(&r);
    multibounce_data_free(&d);
}

/* The model at the surface pixels (with the shader's max), 0 elsewhere. */
static void test_apply_model(void)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    const float vd[4] = {0.0f, 0.3f, 0.7f, 1.0f}, mask[4] = {1.0f, 0.0f, 1.0f, 1.0f};
    float out[4];
    multibounce_apply_model(&talk, vd, mask, 4, 0.05f, out);
    CHECK(out[1] == 0.0f);
    for (int i = 0; i < 4; ++i)
        if (mask[i] != 0.0f)
            CHECK(out[i] == (float)gtao_multibounce(&talk, vd[i], 0.05f) && out[i] >= vd[i]);
}

int main(void)
{
    test_rows_from_synthetic_data();
    test_apply_model();
    return check_report("multibounce_rows");
}
