/* The noise-corrected RMSE against closed forms: a reference made of the
 * truth plus zero-mean noise of known variance, and an approximation off the
 * truth by a known constant. */
#include <math.h>

#include "metrics/image_error.h"
#include "metrics/noise_corrected.h"
#include "tests/check.h"

enum { W = 8, H = 4, N = W * H };

/* Mean of the squared standard errors over the mask, ignoring the rest. */
static void test_mean_variance(void)
{
    float se[N], mask[N];
    double sum = 0.0;
    int inside = 0;
    for (int i = 0; i < N; ++i) {
        mask[i] = i % 3 == 0 ? 0.0f : 1.0f;
        se[i] = mask[i] != 0.0f ? 0.01f * (float)(i % 5 + 1) : 100.0f; /* outside: huge, must not count */
        if (mask[i] != 0.0f) {
            sum += (double)se[i] * se[i];
            ++inside;
        }
    }
    CHECK_NEAR(noise_mean_variance(se, mask, N), sum / inside, 1e-15);
    CHECK(noise_mean_variance(NULL, mask, N) == 0.0);
    for (int i = 0; i < N; ++i)
        mask[i] = 0.0f;
    CHECK(noise_mean_variance(se, mask, N) == 0.0);
    float constant[N];
    for (int i = 0; i < N; ++i)
        constant[i] = 0.25f;
    CHECK_NEAR(noise_mean_variance(constant, NULL, N), 0.0625, 1e-15);
}

/* r = t + n with n = +-sigma alternating (mean 0, variance sigma^2) and
 * a = t + d: RMSE(a, r)^2 = d^2 + sigma^2, so the corrected RMSE is |d|. */
static void check_recovers_offset(double d, double sigma)
{
    float truth[N], ref[N], approx[N], se[N];
    for (int i = 0; i < N; ++i) {
        truth[i] = 0.5f + (float)(i % 7) / 64.0f; /* dyadic: every figure exact */
        ref[i] = (float)(truth[i] + (i % 2 ? sigma : -sigma));
        approx[i] = (float)(truth[i] + d);
        se[i] = (float)sigma;
    }
    image_error_stats st;
    gt_error e;
    CHECK(image_error_compute(approx, ref, NULL, W, H, "t", &st, &e) == 0);
    CHECK_NEAR(st.rmse * st.rmse, d * d + sigma * sigma, 1e-12);
    CHECK_NEAR(noise_corrected_rmse(st.rmse, noise_mean_variance(se, NULL, N)), fabs(d), 1e-6);
}

static void test_corrected_rmse(void)
{
    check_recovers_offset(0.125, 0.0625);
    check_recovers_offset(-0.03125, 0.25);
    check_recovers_offset(0.0, 0.125); /* the whole error is noise */
    CHECK(noise_corrected_rmse(0.1, 0.02) == 0.0); /* below the noise: clamped */
    CHECK_NEAR(noise_corrected_rmse(0.5, 0.0), 0.5, 1e-15);
    CHECK_NEAR(noise_corrected_rmse(0.5, 0.09), 0.4, 1e-15);
}

/* The budget against its definition: a reference with exactly the budget's
 * noise, put through the measured-RMSE identity above (an image whose true
 * RMSE is f against a reference with noise RMSE n, check_recovers_offset),
 * shows f + m/4; half the budget's variance shows less. */
static void check_budget(double figure, double margin)
{
    double n = noise_budget_for_rmse(figure, margin);
    float truth[N], ref[N], approx[N];
    for (int i = 0; i < N; ++i) {
        truth[i] = 0.5f;
        ref[i] = (float)(truth[i] + (i % 2 ? n : -n));
        approx[i] = (float)(truth[i] + figure);
    }
    image_error_stats st;
    gt_error e;
    CHECK(image_error_compute(approx, ref, NULL, W, H, "t", &st, &e) == 0);
    CHECK_NEAR(st.rmse, figure + 0.25 * margin, 1e-6);
    CHECK_NEAR(noise_inflation_of_rmse(figure, n), 0.25 * margin, 1e-12);
    CHECK(noise_inflation_of_rmse(figure, n / sqrt(2.0)) < 0.25 * margin);
}

static void test_budget(void)
{
    check_budget(0.125, 1.0 / 255.0);
    check_budget(0.0, 0.01); /* a perfect figure: the budget is m/4 itself */
    CHECK_NEAR(noise_budget_for_rmse(0.0, 0.01), 0.0025, 1e-15);
    check_budget(0.5, 0.25);
    /* Closed form, worked by hand: f = 0.12, m = 0.004: sqrt(0.00024 + 1e-6). */
    CHECK_NEAR(noise_budget_for_rmse(0.12, 0.004), sqrt(0.000241), 1e-15);
    CHECK(noise_budget_for_rmse(0.1, 0.0) == 0.0);
    CHECK(noise_budget_for_rmse(0.1, NAN) == 0.0);
    /* A larger figure tolerates more noise: the inflation is second order in n. */
    CHECK(noise_budget_for_rmse(0.2, 0.004) > noise_budget_for_rmse(0.1, 0.004));
    /* Measured against the reference itself: 0.13 under noise 0.05 is a true 0.12. */
    CHECK_NEAR(noise_budget_for_measured_rmse(0.13, 0.05, 0.004), noise_budget_for_rmse(0.12, 0.004), 1e-12);
}

int main(void)
{
    test_mean_variance();
    test_corrected_rmse();
    test_budget();
    return check_report("metrics_noise_corrected");
}
