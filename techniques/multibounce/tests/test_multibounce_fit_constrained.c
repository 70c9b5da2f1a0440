/* The constrained multi-bounce refit (multibounce/multibounce_fit_constrained.h):
 * its fit satisfies V'_d(1) = 1 and V'_d >= V_d exactly (in floating point,
 * on a grid of the unit square) whatever the data, even data from the
 * talk's cubic, which violates them; the degree-1 copy of the form is the
 * same cubic; a truth of the form is recovered; the unconstrained fit, whose
 * family contains the constrained one, never fits worse; the clamp's domain
 * fraction matches a closed form. */
#include "multibounce/multibounce_fit_constrained.h"
#include "tests/check.h"

#include <stdint.h>
#include <string.h>

#include "tests/test_noise.h"

static const float kAlbedos[7] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.7f, 0.9f};

/* `per_group` samples per scene and albedo: V'_d = truth(V_d, rho) + sigma N(0, 1). */
static void synthesise(multibounce_data *d, double (*truth)(double, double), int scenes, int per_group,
                       double sigma)
{
    gt_error e;
    multibounce_data_init(d);
    for (int s = 0; s < scenes; ++s) {
        char name[16];
        snprintf(name, sizeof name, "scene%d", s);
        int si = multibounce_data_scene(d, name, &e);
        for (int a = 0; a < 7; ++a) {
            int ai = multibounce_data_albedo(d, kAlbedos[a], &e);
            for (int i = 0; i < per_group; ++i) {
                double v = (i + 0.5) / per_group;
                double y = truth(v, kAlbedos[a]) + sigma * gaussian(0, (uint64_t)(s * 7 + a) * 1000003u + i);
                multibounce_data_push(d, si, ai, (float)v, (float)y, &e);
            }
        }
    }
    multibounce_data_weigh(d);
}

static const double kTruthS[4] = {0.3, 0.9, 0.2, 0.6};
static double constrained_truth(double x, double rho) { return multibounce_constrained_eval(kTruthS, x, rho); }
/* The talk's bare cubic, lowered at low albedos: below V_d on much of the square. */
static double violating_truth(double x, double rho)
{
    const multibounce_model talk = multibounce_model_jimenez2016();
    const multibounce_cubic c = multibounce_cubic_at(&talk, rho);
    return multibounce_cubic_eval(&c, x) - 0.1 * x * (1.0 - rho);
}

/* V'_d(1) == 1 and V'_d >= V_d, exactly, on a 201 x 201 grid; the degree-1
 * copy within rounding. */
static void check_constraints(const multibounce_constrained_fit *f)
{
    int exact = 1;
    double worst_copy = 0.0;
    for (int j = 0; j <= 200; ++j) {
        double rho = j / 200.0;
        exact &= multibounce_constrained_eval(f->s, 1.0, rho) == 1.0;
        multibounce_cubic c = multibounce_cubic_at(&f->model, rho);
        for (int i = 0; i <= 200; ++i) {
            double x = i / 200.0, y = multibounce_constrained_eval(f->s, x, rho);
            exact &= y >= x;
            worst_copy = fmax(worst_copy, fabs(multibounce_cubic_eval(&c, x) - y));
        }
    }
    CHECK_MSG(exact, "a constraint fails on the grid");
    CHECK_MSG(worst_copy < 1e-12, "degree-1 copy off by %g", worst_copy);
}

static void test_recovers_a_truth_of_the_form(void)
{
    multibounce_data d;
    synthesise(&d, constrained_truth, 3, 400, 0.01);
    multibounce_constrained_fit f;
    gt_error e;
    CHECK_MSG(multibounce_fit_constrained(&d, &f, &e) == 0, "%s", e.message);
    check_constraints(&f);
    for (int k = 0; k < 4; ++k)
        CHECK_NEAR(f.corner[k], kTruthS[k] * kTruthS[k], 0.03);
    multibounce_fit free_fit;
    CHECK(multibounce_fit_model(&d, 1, NULL, &free_fit, &e) == 0);
    multibounce_errors bare;
    multibounce_measure(&d, &free_fit.model, 0, &bare);
    CHECK(bare.rmse <= multibounce_constrained_rmse(&d, f.s) + 1e-12);
    multibounce_data_free(&d);
}

/* The talk's cubic dips below V_d at low albedos; the constrained fit to it
 * (and to a curve below V_d everywhere at low rho) still holds its constraints. */
static void test_constraints_hold_on_violating_data(void)
{
    multibounce_data d;
    synthesise(&d, violating_truth, 4, 300, 0.02);
    multibounce_constrained_analysis a;
    gt_error e;
    CHECK_MSG(multibounce_analyse_constrained(&d, &a, &e) == 0, "%s", e.message);
    check_constraints(&a.fit);
    CHECK(a.heldout_count == 4);
    double mean = 0.0;
    for (int i = 0; i < a.heldout_count; ++i) {
        CHECK(a.heldout[i].scene == i);
        mean += (a.heldout[i].rmse_constrained - a.heldout[i].rmse_unconstrained) / a.heldout_count;
    }
    CHECK_NEAR(a.mean_difference, mean, 1e-15);
    CHECK(a.difference_se > 0.0);
    /* The optimum: no feasible point nearby (any s is feasible) fits better. */
    const double best = multibounce_constrained_rmse(&d, a.fit.s);
    int optimal = 1;
    for (int trial = 0; trial < 64; ++trial) {
        double s[4];
        for (int k = 0; k < 4; ++k)
            s[k] = a.fit.s[k] + 0.05 * gaussian(0, 7000u + 4u * (uint64_t)trial + (uint64_t)k);
        optimal &= multibounce_constrained_rmse(&d, s) >= best - 1e-12;
    }
    CHECK_MSG(optimal, "a perturbed parameter vector fits better than the fit");
    multibounce_data_free(&d);
}

/* c = 0.5 + rho, a = b = 0: the cubic is below x exactly where rho < 0.5,
 * i.e. at rho = j/10 for j = 0..4: 5 of the 11 rows of the grid. */
static void test_clamp_domain_fraction(void)
{
    multibounce_model m = {.degree = 1, .c = {0.5, 1.0}};
    CHECK_NEAR(multibounce_clamp_domain_fraction(&m, 10), 5.0 / 11.0, 1e-15);
    multibounce_model identity = {.degree = 0, .c = {1.0}};
    CHECK(multibounce_clamp_domain_fraction(&identity, 50) == 0.0);
}

int main(void)
{
    test_recovers_a_truth_of_the_form();
    test_constraints_hold_on_violating_data();
    test_clamp_domain_fraction();
    return check_report("multibounce_fit_constrained");
}
