/* The Kulla-Conty table and lobe against mathematics:
 * - F_avg of Schlick's Fresnel: the closed form F0 + (1 - F0)/21 against the
 *   integral 2 int F(mu) mu dmu by Gauss-Kronrod;
 * - E_avg by the table's adaptive quadrature against an independent
 *   composite midpoint rule over mu (two quadratures agreeing);
 * - E_avg -> 1 as r -> 0 (a mirror loses nothing) and falls with r;
 * - the white furnace: E(mu_o) + int f_ms(mu_o, mu_i) mu_i dw_i = 1 with the
 *   lobe integrated numerically (the lobe's 1/pi and E_avg's 2 checked);
 * - the table: entries at the texel centres, the lookup exact there, linear
 *   between, clamped beyond; the same bits for 1 and 2 threads. */
#include <math.h>
#include <string.h>

#include "core/sampling/quadrature.h"
#include "core/vec3.h" /* M_PI */
#include "kulla_conty/kulla_conty_lut.h"
#include "luts/dfg_lut.h"
#include "tests/check.h"

static double schlick_weighted(double mu, void *ctx)
{
    double f0 = *(const double *)ctx;
    return 2.0 * mu * (f0 + (1.0 - f0) * pow(1.0 - mu, 5.0));
}

static void fresnel_average(void)
{
    const double f0s[4] = {0.0, 0.04, 0.5, 1.0};
    for (int i = 0; i < 4; ++i) {
        double f0 = f0s[i], integral = quadrature_gk15(schlick_weighted, &f0, 0.0, 1.0, 1e-13, NULL);
        CHECK_NEAR(kulla_conty_fresnel_average_schlick(f0), integral, 1e-12);
    }
    /* F_avg = 1 (a perfect reflector) leaves the lobe unscaled. */
    CHECK_NEAR(kulla_conty_fresnel_scale(1.0, 0.7), 1.0, 1e-15);
}

static double albedo(double mu, double r)
{
    double e[DFG_CHANNELS];
    dfg_integrate(mu, r, e);
    return e[DFG_ALBEDO];
}

/* 2 int E mu dmu by the midpoint rule on n nodes (E is smooth in mu). */
static double midpoint_average(double r, int n)
{
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        double mu = (i + 0.5) / n;
        sum += 2.0 * mu * albedo(mu, r);
    }
    return sum / n;
}

static void average_albedo(void)
{
    const double rs[3] = {0.3, 0.7, 1.0};
    for (int i = 0; i < 3; ++i)
        CHECK_NEAR(kulla_conty_average_albedo(rs[i], NULL), midpoint_average(rs[i], 200), 2e-5);
    CHECK_NEAR(kulla_conty_average_albedo(0.02, NULL), 1.0, 1e-4);
    double previous = 2.0;
    for (int j = 1; j <= 10; ++j) {
        double e = kulla_conty_average_albedo(j / 10.0, NULL);
        CHECK_MSG(e < previous && e > 0.0, "E_avg(%.1f) = %g", j / 10.0, e);
        previous = e;
    }
}

/* The lobe's cosine-weighted integral over the hemisphere, 2 pi int f mu dmu. */
static double lobe_integral(double mu_o, double r, double e_avg, int n)
{
    double e_out = albedo(mu_o, r), sum = 0.0;
    for (int i = 0; i < n; ++i) {
        double mu = (i + 0.5) / n;
        sum += kulla_conty_lobe(e_out, albedo(mu, r), e_avg) * mu;
    }
    return 2.0 * M_PI * sum / n;
}

static void white_furnace(void)
{
    const double r = 0.8, mus[3] = {0.1, 0.5, 0.95};
    /* The same midpoint nodes for E_avg and for the lobe: the identity is
     * then exact up to rounding, so any wrong constant shows. */
    double e_avg = midpoint_average(r, 100);
    for (int i = 0; i < 3; ++i) {
        double total = albedo(mus[i], r) + lobe_integral(mus[i], r, e_avg, 100);
        CHECK_MSG(fabs(total - 1.0) < 1e-12, "furnace at mu %.2f: %.15f", mus[i], total);
    }
    CHECK(kulla_conty_lobe(0.5, 0.5, 1.0) == 0.0);
}

static void table(void)
{
    kulla_conty_lut one, two;
    CHECK(kulla_conty_lut_build(&one, KULLA_CONTY_MIN_SIZE - 1, 1) == -1 && one.average_albedo == NULL);
    CHECK(kulla_conty_lut_build(&one, 8, 1) == 0 && kulla_conty_lut_build(&two, 8, 2) == 0);
    CHECK(memcmp(one.average_albedo, two.average_albedo, sizeof(float) * 8) == 0);
    for (int j = 0; j < 8; ++j) {
        float centre = (j + 0.5f) / 8.0f;
        CHECK(one.average_albedo[j] == (float)kulla_conty_average_albedo((j + 0.5) / 8.0, NULL));
        CHECK(kulla_conty_lut_sample(&one, centre) == one.average_albedo[j]);
    }
    float mid = kulla_conty_lut_sample(&one, 0.25f); /* halfway between centres 1 and 2 */
    CHECK_NEAR(mid, 0.5f * (one.average_albedo[1] + one.average_albedo[2]), 1e-7);
    CHECK(kulla_conty_lut_sample(&one, 0.0f) == one.average_albedo[0]);
    CHECK(kulla_conty_lut_sample(&one, 1.0f) == one.average_albedo[7]);
    CHECK(one.max_error_estimate < 1e-5);
    kulla_conty_lut_free(&one);
    kulla_conty_lut_free(&two);
}

int main(void)
{
    fresnel_average();
    average_albedo();
    white_furnace();
    table();
    return check_report("test_kulla_conty_lut");
}
