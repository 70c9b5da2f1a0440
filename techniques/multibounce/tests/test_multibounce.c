/* GTAOMultiBounce (multibounce/multibounce.c) against values derived by hand,
 * the talk's own shader code, and its own derivatives. */
#include "multibounce/multibounce.h"
#include "tests/check.h"

/* The talk's shader code ("Shader Code" slide), transcribed for one colour
 * channel: an independent second implementation to compare with. */
static float talk_shader(float visibility, float albedo)
{
    float a = 2.0404f * albedo - 0.3324f;
    float b = -4.7951f * albedo + 0.6417f;
    float c = 2.7552f * albedo + 0.6903f;
    float x = visibility;
    return fmaxf(x, ((x * a + b) * x + c) * x);
}

static void test_hand_values(void)
{
    /* a = 1, b = -2, c = 2 at any albedo: ((0.5 - 2) 0.5 + 2) 0.5 = 0.625. */
    multibounce_model m = {.degree = 0, .a = {1.0}, .b = {-2.0}, .c = {2.0}};
    CHECK_NEAR(gtao_multibounce(&m, 0.5, 0.3), 0.625, 1e-15);
    /* x = 0 gives 0 whatever the model; x = 1 gives a + b + c (or 1 if less). */
    multibounce_model talk = multibounce_model_jimenez2016();
    for (int i = 0; i <= 10; ++i) {
        double rho = i / 10.0;
        CHECK(gtao_multibounce(&talk, 0.0, rho) == 0.0);
        multibounce_cubic c = multibounce_cubic_at(&talk, rho);
        CHECK_NEAR(multibounce_cubic_eval(&c, 1.0), c.a + c.b + c.c, 1e-15);
        /* The talk's numbers give V'_d(1) = 0.0005 rho + 0.9996: an unoccluded
         * point sees the dome, V' = 1, to the talk's 4 decimals. Read with
         * slope and intercept swapped (its slide's "a = a0 + a1 rho" beside
         * x0 -> 2.0404) it would give ~rho: that reading is wrong. */
        CHECK_NEAR(multibounce_cubic_eval(&c, 1.0), 0.0005 * rho + 0.9996, 1e-12);
        CHECK_NEAR(gtao_multibounce(&talk, 1.0, rho), 1.0, 5e-4);
    }
    /* At rho = 0 the talk's cubic lies below x: the max(x, .) gives V_d back
     * (0.464025 < 0.5 by hand). */
    multibounce_cubic zero = multibounce_cubic_at(&talk, 0.0);
    CHECK_NEAR(multibounce_cubic_eval(&zero, 0.5), 0.464025, 1e-12);
    CHECK(gtao_multibounce(&talk, 0.5, 0.0) == 0.5);
}

static void test_against_talk_shader(void)
{
    multibounce_model talk = multibounce_model_jimenez2016();
    double worst = 0.0;
    for (int i = 0; i <= 100; ++i)
        for (int j = 0; j <= 20; ++j) {
            double x = i / 100.0, rho = j / 20.0;
            worst = fmax(worst, fabs(gtao_multibounce(&talk, x, rho) - talk_shader((float)x, (float)rho)));
        }
    CHECK_MSG(worst < 2e-6, "largest difference from the talk's shader %g (float rounding only)", worst);
}

static void test_model_algebra(void)
{
    multibounce_model m = {.degree = 2, .a = {0.1, -0.2, 0.3}, .b = {0.4, 0.5, -0.6}, .c = {0.7, 0.8, 0.9}};
    double p[MULTIBOUNCE_MAX_PARAMETERS];
    CHECK(multibounce_model_parameter_count(2) == 9);
    multibounce_model_to_vector(&m, p);
    multibounce_model back = multibounce_model_from_vector(2, p);
    for (int k = 0; k < 3; ++k)
        CHECK(back.a[k] == m.a[k] && back.b[k] == m.b[k] && back.c[k] == m.c[k]);
    /* cubic_at: a = 0.1 - 0.2 rho + 0.3 rho^2 at rho = 0.5 is 0.075. */
    multibounce_cubic c = multibounce_cubic_at(&m, 0.5);
    CHECK_NEAR(c.a, 0.075, 1e-15);
    CHECK_NEAR(c.b, 0.4 + 0.25 - 0.15, 1e-15);
    CHECK_NEAR(c.c, 0.7 + 0.4 + 0.225, 1e-15);
    /* The gradient: the model is linear in its parameters, so the gradient
     * dotted with the parameters is the cubic itself, and central
     * differences agree. */
    for (int i = 0; i <= 8; ++i) {
        double x = i / 8.0, rho = 0.37, g[9], dot = 0.0;
        multibounce_model_gradient(2, x, rho, g);
        for (int k = 0; k < 9; ++k)
            dot += g[k] * p[k];
        multibounce_cubic ci = multibounce_cubic_at(&m, rho);
        CHECK_NEAR(dot, multibounce_cubic_eval(&ci, x), 1e-14);
        for (int k = 0; k < 9; ++k) {
            double q[9], h = 1e-6;
            for (int j = 0; j < 9; ++j)
                q[j] = p[j];
            q[k] += h;
            multibounce_model up = multibounce_model_from_vector(2, q);
            q[k] -= 2 * h;
            multibounce_model down = multibounce_model_from_vector(2, q);
            multibounce_cubic cu = multibounce_cubic_at(&up, rho), cd = multibounce_cubic_at(&down, rho);
            CHECK_NEAR((multibounce_cubic_eval(&cu, x) - multibounce_cubic_eval(&cd, x)) / (2 * h), g[k], 1e-8);
        }
    }
}

/* The anchored form against its defining expression, and its limits. */
static void test_anchored(void)
{
    const double p[4] = {0.8, -0.3, 0.5, 0.4};
    multibounce_model m = multibounce_model_anchored(p);
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j) {
            double v = i / 10.0, rho = j / 10.0;
            double direct = v + v * (1 - v) * (rho * (p[0] + p[1] * v) + rho * rho * (p[2] + p[3] * v));
            multibounce_cubic c = multibounce_cubic_at(&m, rho);
            CHECK_NEAR(multibounce_cubic_eval(&c, v), direct, 1e-14);
        }
    for (int j = 0; j <= 10; ++j) {
        multibounce_cubic c = multibounce_cubic_at(&m, j / 10.0);
        CHECK_NEAR(multibounce_cubic_eval(&c, 1.0), 1.0, 1e-14);
    }
    multibounce_cubic zero = multibounce_cubic_at(&m, 0.0);
    CHECK(zero.a == 0.0 && zero.b == 0.0 && zero.c == 1.0);
}

int main(void)
{
    test_anchored();
    test_hand_values();
    test_against_talk_shader();
    test_model_algebra();
    return check_report("multibounce_realtime");
}
