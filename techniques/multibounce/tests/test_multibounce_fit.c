/* The multi-bounce refit (multibounce/multibounce_fit.c) on synthetic data of
 * known coefficients: recovery within its own standard errors (k-sigma, and
 * z^2 averaging 1 over replicas), standard errors shrinking as 1/sqrt(n),
 * the scene/albedo weighting, leave-one-scene-out bookkeeping, and reading
 * samples from reference images. */
#include "multibounce/multibounce_fit.h"
#include "tests/check.h"

#include <stdint.h>
#include <string.h>

#include "tests/test_noise.h"

/* A made-up truth (not the talk's numbers), degree 1. */
static multibounce_model truth(void)
{
    multibounce_model m = {.degree = 1, .a = {-0.2, 1.5}, .b = {0.5, -4.0}, .c = {0.7, 2.5}};
    return m;
}

static const float kAlbedos[7] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.7f, 0.9f};
static const double kSigma = 0.01;

/* `per_group` samples for each of `scenes` scenes and the 7 albedos, V_d
 * spread over (0, 1], V'_d = model + sigma N(0, 1). */
static void synthesise(multibounce_data *d, const multibounce_model *m, int scenes, int per_group, uint64_t seed)
{
    gt_error e;
    for (int s = 0; s < scenes; ++s) {
        char name[16];
        snprintf(name, sizeof name, "scene%d", s);
        int si = multibounce_data_scene(d, name, &e);
        for (int a = 0; a < 7; ++a) {
            int ai = multibounce_data_albedo(d, kAlbedos[a], &e);
            for (int i = 0; i < per_group; ++i) {
                double v = (i + 0.5) / per_group;
                multibounce_cubic c = multibounce_cubic_at(m, kAlbedos[a]);
                double y = multibounce_cubic_eval(&c, v) + kSigma * gaussian(seed, (uint64_t)(s * 7 + a) * 1000003u + i);
                multibounce_data_push(d, si, ai, (float)v, (float)y, &e);
            }
        }
    }
    multibounce_data_weigh(d);
}

static void test_recovery(void)
{
    multibounce_model t = truth();
    double p_true[6], sum_z2 = 0.0;
    multibounce_model_to_vector(&t, p_true);
    int replicas = 20, worst_ok = 1;
    for (int r = 0; r < replicas; ++r) {
        multibounce_data d;
        multibounce_data_init(&d);
        synthesise(&d, &t, 3, 400, 100 + (uint64_t)r);
        multibounce_fit f;
        gt_error e;
        int rc = multibounce_fit_model(&d, 1, NULL, &f, &e);
        CHECK_MSG(rc == 0, "%s", e.message);
        double p[6];
        multibounce_model_to_vector(&f.model, p);
        for (int k = 0; k < 6; ++k) {
            double z = (p[k] - p_true[k]) / f.standard_errors[k];
            sum_z2 += z * z;
            worst_ok &= fabs(z) < 4.5;
        }
        multibounce_data_free(&d);
    }
    CHECK_MSG(worst_ok, "a coefficient beyond 4.5 of its standard errors");
    /* 120 values of z^2: their mean is 1 +- 0.13 if the standard errors are right. */
    double mean_z2 = sum_z2 / (6.0 * replicas);
    CHECK_MSG(mean_z2 > 0.55 && mean_z2 < 1.45, "mean z^2 %g, expected 1", mean_z2);
}

/* The anchored form: a truth of that form is recovered within its
 * standard errors, and every fit keeps V'_d(1) = 1 and V'_d = V_d at rho = 0. */
static void test_anchored(void)
{
    const double p_true[4] = {1.2, -0.4, 0.9, -0.6};
    multibounce_model t = multibounce_model_anchored(p_true);
    multibounce_data d;
    multibounce_data_init(&d);
    synthesise(&d, &t, 3, 600, 21);
    multibounce_fit f;
    gt_error e;
    CHECK_MSG(multibounce_fit_anchored(&d, NULL, &f, &e) == 0, "%s", e.message);
    CHECK(f.anchored && f.parameter_count == 4);
    for (int k = 0; k < 4; ++k)
        CHECK_MSG(fabs(f.params[k] - p_true[k]) < 4.5 * f.standard_errors[k], "p[%d] = %g +- %g, truth %g", k,
                  f.params[k], f.standard_errors[k], p_true[k]);
    for (int j = 0; j <= 10; ++j)
        CHECK_NEAR(gtao_multibounce(&f.model, 1.0, j / 10.0), 1.0, 1e-12);
    CHECK_NEAR(gtao_multibounce(&f.model, 0.37, 0.0), 0.37, 1e-15);
    char name[8];
    multibounce_fit_parameter_name(&f, 3, name, sizeof name);
    CHECK(strcmp(name, "q2") == 0);
    multibounce_data_free(&d);
}

/* With every albedo sampled at the same V_d with the same weights (as one
 * multi-bounce pass gives), least squares decomposes: the joint linear fit
 * IS the talk's lines through the per-albedo coefficients, exactly (sum_k
 * |X(beta_k - B z_k)|^2 with one metric X^T X for all k is minimised by the
 * unweighted line fit). With different V_d per albedo they differ. */
static void test_joint_equals_two_step_on_common_design(void)
{
    multibounce_model t = truth();
    for (int common = 1; common >= 0; --common) {
        multibounce_data d;
        multibounce_data_init(&d);
        synthesise(&d, &t, 2, 300, 31);
        if (!common) /* squeeze V_d of albedo 0.9 towards 1: another design */
            for (size_t i = 0; i < d.count; ++i)
                if (d.samples[i].albedo_index == 6)
                    d.samples[i].visibility = 0.5f + 0.5f * d.samples[i].visibility;
        multibounce_analysis *a = malloc(sizeof *a);
        gt_error e;
        CHECK_MSG(multibounce_analyse(&d, a, &e) == 0, "%s", e.message);
        double joint[6], lines[6], worst = 0.0;
        multibounce_model_to_vector(&a->joint[MB_JOINT_LINEAR].model, joint);
        multibounce_model_to_vector(&a->two_step, lines);
        for (int k = 0; k < 6; ++k)
            worst = fmax(worst, fabs(joint[k] - lines[k]));
        if (common)
            CHECK_MSG(worst < 1e-6, "joint and two-step differ by %g on a common design", worst);
        else
            CHECK_MSG(worst > 1e-3, "joint and two-step agree (%g) on different designs", worst);
        free(a);
        multibounce_data_free(&d);
    }
}

static void test_standard_error_scaling(void)
{
    multibounce_model t = truth();
    multibounce_fit f[2];
    for (int k = 0; k < 2; ++k) {
        multibounce_data d;
        multibounce_data_init(&d);
        synthesise(&d, &t, 2, k == 0 ? 500 : 2000, 7);
        gt_error e;
        CHECK(multibounce_fit_model(&d, 1, NULL, &f[k], &e) == 0);
        multibounce_data_free(&d);
    }
    for (int j = 0; j < 6; ++j)
        CHECK_NEAR(f[1].standard_errors[j] / f[0].standard_errors[j], 0.5, 0.03);
    /* Per-albedo and quadratic fits too. */
    multibounce_data d;
    multibounce_data_init(&d);
    synthesise(&d, &t, 2, 500, 8);
    multibounce_fit q;
    gt_error e;
    CHECK(multibounce_fit_model(&d, 2, NULL, &q, &e) == 0);
    /* The truth is linear: the quadratic terms a2, b2, c2 are 0 within 4 se. */
    CHECK(fabs(q.model.a[2]) < 4 * q.standard_errors[2] && fabs(q.model.b[2]) < 4 * q.standard_errors[5] &&
          fabs(q.model.c[2]) < 4 * q.standard_errors[8]);
    multibounce_data_free(&d);
}

/* Scene 0 has 10x the pixels (each of its samples repeated 10 times) and a
 * different truth: with the weighting the fit is exactly that of the data
 * without repeats; without it (all weights 1), scene 0 dominates. */
static void test_weighting(void)
{
    multibounce_model t = truth(), other = t;
    other.c[0] = 0.9;
    other.b[0] = 0.2;
    multibounce_data base, heavy;
    multibounce_data_init(&base);
    multibounce_data_init(&heavy);
    gt_error e;
    for (int pass = 0; pass < 2; ++pass) {
        multibounce_data *d = pass ? &heavy : &base;
        for (int s = 0; s < 2; ++s) {
            int si = multibounce_data_scene(d, s ? "B" : "A", &e);
            for (int a = 0; a < 7; ++a) {
                int ai = multibounce_data_albedo(d, kAlbedos[a], &e);
                multibounce_cubic c = multibounce_cubic_at(s ? &other : &t, kAlbedos[a]);
                for (int i = 0; i < 200; ++i) {
                    double v = (i + 0.5) / 200;
                    float y = (float)(multibounce_cubic_eval(&c, v) + kSigma * gaussian(3, (uint64_t)(s * 7 + a) * 1000 + i));
                    for (int rep = 0; rep < (pass && s == 0 ? 10 : 1); ++rep)
                        multibounce_data_push(d, si, ai, (float)v, y, &e);
                }
            }
        }
        multibounce_data_weigh(d);
    }
    multibounce_fit fb, fh, fu;
    CHECK(multibounce_fit_model(&base, 1, NULL, &fb, &e) == 0);
    CHECK(multibounce_fit_model(&heavy, 1, NULL, &fh, &e) == 0);
    double pb[6], ph[6], pu[6];
    multibounce_model_to_vector(&fb.model, pb);
    multibounce_model_to_vector(&fh.model, ph);
    for (int k = 0; k < 6; ++k)
        CHECK_NEAR(ph[k], pb[k], 1e-7);
    for (size_t i = 0; i < heavy.count; ++i)
        heavy.samples[i].weight = 1.0f;
    CHECK(multibounce_fit_model(&heavy, 1, NULL, &fu, &e) == 0);
    multibounce_model_to_vector(&fu.model, pu);
    /* Unweighted, c0 moves most of the way to scene A's 0.7 from the
     * balanced fit's ~0.8: the test above would have failed. */
    CHECK_MSG(pu[4] < pb[4] - 0.05, "unweighted c0 %g, weighted %g", pu[4], pb[4]);
    /* Weights: mean 1, equal total per (scene, albedo) group. */
    multibounce_data_weigh(&heavy);
    double group_total[2] = {0, 0}, total = 0;
    for (size_t i = 0; i < heavy.count; ++i) {
        total += heavy.samples[i].weight;
        if (heavy.samples[i].albedo_index == 0)
            group_total[heavy.samples[i].scene] += heavy.samples[i].weight;
    }
    CHECK_NEAR(total / (double)heavy.count, 1.0, 1e-6);
    CHECK_NEAR(group_total[0], group_total[1], 1e-3 * group_total[1]);
    multibounce_data_free(&base);
    multibounce_data_free(&heavy);
}

static void test_leave_one_scene_out(void)
{
    multibounce_model t = truth(), odd = t;
    odd.b[0] = 0.0; /* scene 2 follows another curve */
    multibounce_data d;
    multibounce_data_init(&d);
    synthesise(&d, &t, 2, 300, 11);
    multibounce_data extra;
    multibounce_data_init(&extra);
    synthesise(&extra, &odd, 3, 300, 12);
    gt_error e;
    for (size_t i = 0; i < extra.count; ++i)
        if (extra.samples[i].scene == 2)
            multibounce_data_push(&d, multibounce_data_scene(&d, "scene2", &e), extra.samples[i].albedo_index,
                                  extra.samples[i].visibility, extra.samples[i].multibounce, &e);
    multibounce_data_free(&extra);
    multibounce_data_weigh(&d);
    multibounce_analysis *a = malloc(sizeof *a);
    CHECK_MSG(multibounce_analyse(&d, a, &e) == 0, "%s", e.message);
    CHECK(a->heldout_count == 3);
    for (int s = 0; s < 3; ++s) {
        const multibounce_heldout *h = &a->heldout[s];
        CHECK(h->scene == s);
        CHECK(h->err[MB_JOINT_LINEAR].samples == 7 * 300);
        /* The held-out model is the fit without the scene, scored on the scene. */
        multibounce_data train, test;
        multibounce_data_select(&d, s, 1, -1, &train, &e);
        multibounce_data_select(&d, s, 0, -1, &test, &e);
        CHECK(train.count == 2 * 7 * 300 && test.count == 7 * 300);
        multibounce_fit f;
        CHECK(multibounce_fit_model(&train, 1, NULL, &f, &e) == 0);
        for (int k = 0; k < 2; ++k)
            CHECK_NEAR(h->model[MB_JOINT_LINEAR].a[k] + h->model[MB_JOINT_LINEAR].b[k] + h->model[MB_JOINT_LINEAR].c[k], f.model.a[k] + f.model.b[k] + f.model.c[k], 1e-9);
        multibounce_errors err;
        multibounce_measure(&test, &h->model[MB_JOINT_LINEAR], 1, &err);
        CHECK_NEAR(h->err[MB_JOINT_LINEAR].rmse, err.rmse, 1e-12);
        multibounce_data_free(&train);
        multibounce_data_free(&test);
    }
    /* The odd scene, held out, is predicted worse than the two alike. */
    CHECK(a->heldout[2].err[MB_JOINT_LINEAR].rmse > 3 * a->heldout[0].err[MB_JOINT_LINEAR].rmse);
    CHECK(a->heldout[2].err[MB_JOINT_LINEAR].rmse > 3 * a->heldout[1].err[MB_JOINT_LINEAR].rmse);
    CHECK_NEAR(a->heldout_mean[MB_JOINT_LINEAR],
               (a->heldout[0].err[MB_JOINT_LINEAR].rmse + a->heldout[1].err[MB_JOINT_LINEAR].rmse + a->heldout[2].err[MB_JOINT_LINEAR].rmse) / 3, 1e-12);
    /* Jackknife standard errors from the held-out fits' parameters. */
    for (int k = 0; k < 6; ++k) {
        double mean = 0, ss = 0;
        for (int i = 0; i < 3; ++i)
            mean += a->heldout[i].params[MB_JOINT_LINEAR][k] / 3;
        for (int i = 0; i < 3; ++i)
            ss += pow(a->heldout[i].params[MB_JOINT_LINEAR][k] - mean, 2);
        CHECK_NEAR(a->jackknife_se[MB_JOINT_LINEAR][k], sqrt(2.0 / 3.0 * ss), 1e-12);
        CHECK(a->jackknife_se[MB_JOINT_LINEAR][k] > 0);
    }
    /* The chosen joint model has the lowest held-out mean. */
    for (int j = 0; j < MB_JOINT_COUNT; ++j)
        CHECK(a->has[j] && a->heldout_mean[a->chosen] <= a->heldout_mean[j]);
    /* Per albedo: a degree-0 cubic fitted to that albedo's samples only. */
    for (int k = 0; k < 7; ++k) {
        CHECK(a->per_albedo[k].albedo == kAlbedos[k]);
        CHECK(a->per_albedo[k].fit.model.degree == 0 && a->per_albedo[k].own.samples == 3 * 300);
    }
    free(a);
    multibounce_data_free(&d);
}

/* A 4x2 reference image as gtlab render multibounce writes it. */
static void make_image(image *img, const char *albedos, const char *bounces)
{
    image_init(img, 4, 2);
    image_set_attribute(img, "gtlab.quantity", "multibounce");
    image_set_attribute(img, "gtlab.scene", "builtin:corner");
    image_set_attribute(img, "gtlab.albedos", albedos);
    image_set_attribute(img, "gtlab.bounces", bounces);
    float *mask = image_add_channel(img, "mask.A"), *v = image_add_channel(img, "ao.V");
    float *m1 = image_add_channel(img, "multibounce_0.2.V"), *m2 = image_add_channel(img, "multibounce_0.7.V");
    for (int i = 0; i < 8; ++i) {
        mask[i] = i % 4 != 3;
        v[i] = mask[i] * 0.1f * (float)i;
        m1[i] = v[i] * 1.1f;
        m2[i] = v[i] * 1.3f;
    }
}

static void test_reading_images(void)
{
    multibounce_data d;
    multibounce_data_init(&d);
    image img;
    gt_error e;
    make_image(&img, "0.2 0.7", "4");
    CHECK(multibounce_data_add_image(&d, &img, "a.exr", &e) == 0);
    CHECK(d.count == 12 && d.albedo_count == 2 && d.scene_count == 1 && d.file_count == 1);
    CHECK(d.albedos[0] == 0.2f && d.albedos[1] == 0.7f);
    CHECK(d.samples[3].visibility == 0.1f && d.samples[3].multibounce == 0.1f * 1.3f);
    image_free(&img);
    make_image(&img, "0.2 0.7", "inf");
    CHECK(multibounce_data_add_image(&d, &img, "b.exr", &e) != 0 && strstr(e.message, "b.exr: rendered with --bounces inf"));
    image_free(&img);
    make_image(&img, "0.2 0.5", "4");
    CHECK(multibounce_data_add_image(&d, &img, "c.exr", &e) != 0 && strstr(e.message, "multibounce_0.5.V is missing"));
    image_free(&img);
    make_image(&img, "scene", "4");
    CHECK(multibounce_data_add_image(&d, &img, "d.exr", &e) != 0 && strstr(e.message, "coloured"));
    image_free(&img);
    make_image(&img, "0.2 0.7", "4");
    image_set_attribute(&img, "gtlab.quantity", "ao");
    CHECK(multibounce_data_add_image(&d, &img, "e.exr", &e) != 0 && strstr(e.message, "no multibounce channels"));
    image_free(&img);
    make_image(&img, "0.2 0.7", "4");
    image_channel_data(&img, "ao.V")[2] = NAN;
    CHECK(multibounce_data_add_image(&d, &img, "f.exr", &e) != 0 && strstr(e.message, "outside [0, 1]"));
    image_free(&img);
    multibounce_data_free(&d);
}

int main(void)
{
    test_recovery();
    test_anchored();
    test_joint_equals_two_step_on_common_design();
    test_standard_error_scaling();
    test_weighting();
    test_leave_one_scene_out();
    test_reading_images();
    return check_report("multibounce_fit");
}
