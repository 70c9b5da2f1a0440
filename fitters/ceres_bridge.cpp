// The Ceres bridge: the thin C++ adapter behind fitters/ceres_bridge.h. A
// gt_fit is one ceres::Problem with a single parameter block (the caller's
// parameter vector); each C residual callback becomes a ceres::CostFunction.
// The fit owns the cost and loss functions itself (Ceres does not take
// ownership), which keeps Ceres from keeping a reference count per cost
// function: a million residual blocks cost one small object each.
#include <ceres/ceres.h>
#include <glog/logging.h>

#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <utility>
#include <vector>

extern "C" {
#include "fitters/ceres_bridge.h"
}

namespace {

const char *const kSubject = "fit";

// A residual block whose C callback fills the Jacobian itself. Ceres' layout
// for the one parameter block (row-major m x n) is the callback's.
class AnalyticResidual final : public ceres::CostFunction {
public:
    AnalyticResidual(gt_fit_residual_fn evaluate, void *user, int residual_count, int parameter_count)
        : evaluate_(evaluate), user_(user)
    {
        set_num_residuals(residual_count);
        mutable_parameter_block_sizes()->push_back(parameter_count);
    }

    bool Evaluate(double const *const *parameters, double *residuals, double **jacobians) const override
    {
        // jacobians[0] is NULL when the whole parameter block is held.
        double *jacobian = jacobians ? jacobians[0] : nullptr;
        return evaluate_(user_, parameters[0], residuals, jacobian) == 0;
    }

private:
    gt_fit_residual_fn evaluate_;
    void *user_;
};

// The functor Ceres' DynamicNumericDiffCostFunction differentiates.
struct NumericResidual {
    gt_fit_residual_fn evaluate;
    void *user;

    bool operator()(double const *const *parameters, double *residuals) const
    {
        return evaluate(user, parameters[0], residuals, nullptr) == 0;
    }
};

using NumericCost = ceres::DynamicNumericDiffCostFunction<NumericResidual, ceres::CENTRAL>;

// Ceres logs through glog, which writes to stderr before InitGoogleLogging
// (gtlab never calls it: that would also create log files). Library code must
// not print, and every failure reaches the caller as a gt_error, so only
// FATAL (a Ceres CHECK about to abort) is let through.
void silence_glog()
{
    static std::once_flag once;
    std::call_once(once, [] { FLAGS_minloglevel = google::GLOG_FATAL; });
}

// Runs body, turning any C++ exception into a gt_error: none may cross the C
// interface.
template <class Body>
int guarded(gt_error *e, Body &&body)
{
    try {
        return body();
    } catch (const std::bad_alloc &) {
        return gt_error_set(e, kSubject, "out of memory");
    } catch (const std::exception &x) {
        return gt_error_set(e, kSubject, "internal error: %s", x.what());
    } catch (...) {
        return gt_error_set(e, kSubject, "internal error: unknown exception");
    }
}

ceres::Problem::Options problem_options()
{
    ceres::Problem::Options o;
    o.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    o.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    // The checks (a sorted copy of each block's parameter list, to find
    // duplicates and size mismatches) cannot fail here: every block has the
    // one parameter block, of its size, by construction.
    o.disable_all_safety_checks = true;
    return o;
}

ceres::LossFunction *new_loss(gt_fit_loss kind, double a)
{
    switch (kind) {
    case GT_FIT_LOSS_HUBER: return new ceres::HuberLoss(a);
    case GT_FIT_LOSS_CAUCHY: return new ceres::CauchyLoss(a);
    case GT_FIT_LOSS_SOFT_L1: return new ceres::SoftLOneLoss(a);
    case GT_FIT_LOSS_NONE: break;
    }
    return nullptr;
}

// A C caller may store any int in an enum field, but C++ may not even load
// an enum holding a value outside its enumerators' range: until validated,
// such fields are read as the int they are in C.
template <class Enum>
int int_of(const Enum &field)
{
    static_assert(sizeof(Enum) == sizeof(int), "C enums are ints");
    int v;
    std::memcpy(&v, &field, sizeof v);
    return v;
}

bool valid_block_options(const gt_fit_block_options &o, gt_error *e)
{
    const int derivatives = int_of(o.derivatives), loss = int_of(o.loss);
    if (derivatives != GT_FIT_ANALYTIC && derivatives != GT_FIT_NUMERIC) {
        gt_error_set(e, kSubject, "unknown derivative mode %d", derivatives);
        return false;
    }
    if (loss != GT_FIT_LOSS_NONE && loss != GT_FIT_LOSS_HUBER && loss != GT_FIT_LOSS_CAUCHY &&
        loss != GT_FIT_LOSS_SOFT_L1) {
        gt_error_set(e, kSubject, "unknown loss %d", loss);
        return false;
    }
    if (o.loss != GT_FIT_LOSS_NONE && !(o.loss_scale > 0.0 && std::isfinite(o.loss_scale))) {
        gt_error_set(e, kSubject, "the loss scale must be positive and finite, not %g", o.loss_scale);
        return false;
    }
    return true;
}

bool valid_solver_options(const gt_fit_options &o, gt_error *e)
{
    if (o.max_iterations < 0) {
        gt_error_set(e, kSubject, "max_iterations must be >= 0, not %d", o.max_iterations);
        return false;
    }
    const double tolerances[3] = {o.function_tolerance, o.gradient_tolerance, o.parameter_tolerance};
    for (double t : tolerances) {
        if (!(t >= 0.0 && std::isfinite(t))) {
            gt_error_set(e, kSubject, "tolerances must be finite and >= 0, not %g", t);
            return false;
        }
    }
    const int solver = int_of(o.linear_solver);
    if (solver != GT_FIT_DENSE_QR && solver != GT_FIT_DENSE_NORMAL_CHOLESKY) {
        gt_error_set(e, kSubject, "unknown linear solver %d", solver);
        return false;
    }
    if (o.threads < 1) {
        gt_error_set(e, kSubject, "threads must be >= 1, not %d", o.threads);
        return false;
    }
    return true;
}

ceres::Solver::Options solver_options(const gt_fit_options &o)
{
    ceres::Solver::Options s;
    s.max_num_iterations = o.max_iterations;
    s.function_tolerance = o.function_tolerance;
    s.gradient_tolerance = o.gradient_tolerance;
    s.parameter_tolerance = o.parameter_tolerance;
    s.linear_solver_type =
        o.linear_solver == GT_FIT_DENSE_NORMAL_CHOLESKY ? ceres::DENSE_NORMAL_CHOLESKY : ceres::DENSE_QR;
    s.num_threads = o.threads;
    s.logging_type = ceres::SILENT;
    s.minimizer_progress_to_stdout = false;
    return s;
}

gt_fit_termination termination_of(ceres::TerminationType t)
{
    switch (t) {
    case ceres::CONVERGENCE:
    case ceres::USER_SUCCESS: return GT_FIT_CONVERGENCE;
    case ceres::NO_CONVERGENCE: return GT_FIT_NO_CONVERGENCE;
    case ceres::FAILURE:
    case ceres::USER_FAILURE: break;
    }
    return GT_FIT_FAILURE;
}

} // namespace

struct gt_fit {
    gt_fit(int n, double *p) : parameter_count(n), params(p), held(n, 0), problem(problem_options())
    {
        problem.AddParameterBlock(params, parameter_count);
    }

    int parameter_count;
    double *params;
    std::vector<char> held; // by the caller (gt_fit_hold)
    bool bounded = false;   // gt_fit_set_bounds was called
    size_t residual_count = 0;
    // Owned here, not by the problem (see the top of the file). One loss
    // object per distinct (kind, scale): blocks share them.
    std::vector<std::unique_ptr<ceres::CostFunction>> costs;
    std::map<std::pair<int, double>, std::unique_ptr<ceres::LossFunction>> losses;
    // Declared last so it is destroyed first, while the functions it points
    // to still exist.
    ceres::Problem problem;

    int free_parameter_count() const
    {
        int held_count = 0;
        for (char h : held)
            held_count += h != 0;
        return parameter_count - held_count;
    }

    ceres::LossFunction *loss(gt_fit_loss kind, double a)
    {
        if (kind == GT_FIT_LOSS_NONE)
            return nullptr;
        std::unique_ptr<ceres::LossFunction> &slot = losses[{(int)kind, a}];
        if (!slot)
            slot.reset(new_loss(kind, a));
        return slot.get();
    }

    // Tells Ceres which parameters stay where they are: a SubsetManifold
    // moves only the others; with all held, the block is constant (a
    // manifold of tangent size 0 is not allowed). A replaced manifold stays
    // owned by the problem.
    void hold_in_ceres(const std::vector<char> &mask)
    {
        std::vector<int> held_indices;
        for (int i = 0; i < parameter_count; ++i)
            if (mask[(size_t)i])
                held_indices.push_back(i);
        if ((int)held_indices.size() == parameter_count) {
            problem.SetManifold(params, nullptr);
            problem.SetParameterBlockConstant(params);
            return;
        }
        problem.SetParameterBlockVariable(params);
        problem.SetManifold(params, held_indices.empty()
                                        ? nullptr
                                        : new ceres::SubsetManifold(parameter_count, held_indices));
    }

    double lower(int i) const { return problem.GetParameterLowerBound(params, i); }
    double upper(int i) const { return problem.GetParameterUpperBound(params, i); }

    // The start must be finite and inside the bounds: Ceres would refuse it
    // with a message naming pointers, not parameters.
    bool start_is_feasible(gt_error *e) const
    {
        for (int i = 0; i < parameter_count; ++i) {
            double lo = lower(i), hi = upper(i);
            if (!std::isfinite(params[i]) || params[i] < lo || params[i] > hi) {
                gt_error_set(e, kSubject, "parameter %d starts at %g, outside its bounds [%g, %g]", i, params[i],
                             lo, hi);
                return false;
            }
        }
        return true;
    }

    // The cost (with losses), the raw residuals or the gradient of the cost
    // (of all n parameters unless some are held), at the current parameters.
    bool evaluate(bool apply_loss, double *cost, std::vector<double> *residuals,
                  std::vector<double> *gradient = nullptr)
    {
        ceres::Problem::EvaluateOptions o;
        o.apply_loss_function = apply_loss;
        return problem.Evaluate(o, cost, residuals, gradient, nullptr);
    }
};

namespace {

// RMSE and max |r| of the raw residuals at the solution.
int residual_statistics(gt_fit *fit, gt_fit_result *r, gt_error *e)
{
    double cost = 0.0;
    std::vector<double> residuals;
    if (!fit->evaluate(false, &cost, &residuals))
        return gt_error_set(e, kSubject, "the residuals cannot be evaluated at the solution");
    double max_abs = 0.0;
    for (double v : residuals)
        max_abs = std::fmax(max_abs, std::fabs(v));
    r->rmse = std::sqrt(2.0 * cost / (double)residuals.size());
    r->max_abs_residual = max_abs;
    return 0;
}

// One Ceres solve from the current parameters, accumulated into r. Returns
// false when Ceres found no usable solution.
bool ceres_solve(gt_fit *fit, const ceres::Solver::Options &so, gt_fit_result *r, bool first)
{
    ceres::Solver::Summary summary;
    ceres::Solve(so, &fit->problem, &summary);
    r->termination = termination_of(summary.termination_type);
    r->success = r->termination == GT_FIT_CONVERGENCE;
    std::snprintf(r->message, sizeof r->message, "%s", summary.message.c_str());
    // Ceres' list starts with iteration 0, the evaluation at the start.
    if (!summary.iterations.empty())
        r->iterations += (int)summary.iterations.size() - 1;
    if (first)
        r->initial_cost = summary.initial_cost;
    r->final_cost = summary.final_cost;
    r->seconds += summary.total_time_in_seconds;
    return summary.IsSolutionUsable();
}

// Holds (in active) the free parameters resting on a bound; true if any is new.
bool hold_parameters_on_bounds(const gt_fit *fit, std::vector<char> *active)
{
    bool changed = false;
    for (int i = 0; i < fit->parameter_count; ++i) {
        double p = fit->params[i];
        if (!fit->held[(size_t)i] && !(*active)[(size_t)i] && (p == fit->lower(i) || p == fit->upper(i))) {
            (*active)[(size_t)i] = 1;
            changed = true;
        }
    }
    return changed;
}

// Frees (from active) the parameters whose bound no longer binds: the cost
// decreases into the box (the Karush-Kuhn-Tucker sign test on the gradient).
// True if any was freed; false with *failed if the gradient cannot be had.
bool release_inactive_bounds(gt_fit *fit, std::vector<char> *active, bool *failed)
{
    fit->hold_in_ceres(std::vector<char>((size_t)fit->parameter_count, 0)); // the gradient of all n
    std::vector<double> gradient;
    double cost = 0.0;
    *failed = !fit->evaluate(true, &cost, nullptr, &gradient);
    bool changed = false;
    for (int i = 0; i < fit->parameter_count && !*failed; ++i) {
        if (!(*active)[(size_t)i])
            continue;
        double p = fit->params[i], g = gradient[(size_t)i];
        if ((p == fit->lower(i) && g < 0.0) || (p == fit->upper(i) && g > 0.0)) {
            (*active)[(size_t)i] = 0;
            changed = true;
        }
    }
    return changed;
}

// Ceres keeps the iterates inside the bounds by projecting each
// Levenberg-Marquardt step onto the box. When a bound is active and the
// parameters are correlated, the projected steps crawl: a cubic fit stopped
// at 7x the optimal cost. So a bounded fit is polished by an active-set loop
// (Nocedal & Wright, Numerical Optimization, 16.5): parameters that Ceres
// left on a bound are held there and the rest re-solved, until no new bound
// is reached and every held one passes the KKT sign test. Each round is an
// ordinary Ceres solve.
int solve_bounded(gt_fit *fit, const ceres::Solver::Options &so, gt_fit_result *r, gt_error *e)
{
    std::vector<char> active((size_t)fit->parameter_count, 0);
    const int max_rounds = 2 * fit->parameter_count + 2;
    bool settled = false, usable = true, no_gradient = false;
    for (int round = 0; round < max_rounds && usable && !settled; ++round) {
        std::vector<char> mask = fit->held;
        for (size_t i = 0; i < mask.size(); ++i)
            mask[i] |= active[i];
        fit->hold_in_ceres(mask);
        usable = ceres_solve(fit, so, r, round == 0);
        if (usable && !hold_parameters_on_bounds(fit, &active)) {
            settled = !release_inactive_bounds(fit, &active, &no_gradient);
            usable = !no_gradient;
        }
    }
    fit->hold_in_ceres(fit->held);
    if (no_gradient)
        return gt_error_set(e, kSubject, "the gradient cannot be evaluated at the solution");
    if (!usable)
        return gt_error_set(e, kSubject, "the solver failed: %s", r->message);
    if (!settled) {
        r->success = 0;
        r->termination = GT_FIT_NO_CONVERGENCE;
        std::snprintf(r->message, sizeof r->message, "the set of active bounds did not settle in %d solves",
                      max_rounds);
    }
    return 0;
}

int solve(gt_fit *fit, const gt_fit_options &options, gt_fit_result *r, gt_error *e)
{
    if (fit->costs.empty())
        return gt_error_set(e, kSubject, "nothing to fit: no residual blocks");
    if (!valid_solver_options(options, e) || !fit->start_is_feasible(e))
        return -1;
    ceres::Solver::Options so = solver_options(options);
    std::string why;
    if (!so.IsValid(&why))
        return gt_error_set(e, kSubject, "invalid solver options: %s", why.c_str());
    if (fit->bounded) {
        if (solve_bounded(fit, so, r, e) != 0)
            return -1;
    } else if (!ceres_solve(fit, so, r, true)) {
        return gt_error_set(e, kSubject, "the solver failed: %s", r->message);
    }
    return residual_statistics(fit, r, e);
}

int covariance(gt_fit *fit, double *cov_out, double *se_out, double *variance_out, gt_error *e)
{
    const int n = fit->parameter_count;
    const int n_free = fit->free_parameter_count();
    if (fit->residual_count <= (size_t)n_free)
        return gt_error_set(e, kSubject,
                            "%zu residuals cannot give the covariance of %d free parameters: it needs more "
                            "residuals than free parameters",
                            fit->residual_count, n_free);
    double cost = 0.0;
    if (!fit->evaluate(true, &cost, nullptr))
        return gt_error_set(e, kSubject, "the residuals cannot be evaluated at the current parameters");
    const double variance = 2.0 * cost / (double)(fit->residual_count - (size_t)n_free);

    std::vector<double> cov((size_t)n * (size_t)n, 0.0);
    if (n_free > 0) {
        // DENSE_SVD detects rank deficiency from the singular values of J
        // (min/max below sqrt(min_reciprocal_condition_number)) and fails
        // rather than returning a meaningless inverse.
        ceres::Covariance::Options co;
        co.algorithm_type = ceres::DENSE_SVD;
        ceres::Covariance c(co);
        std::vector<const double *> blocks{fit->params};
        if (!c.Compute(blocks, &fit->problem) || !c.GetCovarianceBlock(fit->params, fit->params, cov.data()))
            return gt_error_set(e, kSubject,
                                "no covariance: the Jacobian at the solution is rank-deficient (the data do "
                                "not determine every free parameter) or cannot be evaluated");
    }
    for (double &v : cov)
        v *= variance;
    if (cov_out)
        std::copy(cov.begin(), cov.end(), cov_out);
    if (se_out)
        for (int i = 0; i < n; ++i)
            se_out[i] = std::sqrt(std::fmax(cov[(size_t)i * (size_t)n + (size_t)i], 0.0));
    if (variance_out)
        *variance_out = variance;
    return 0;
}

} // namespace

extern "C" {

gt_fit_options gt_fit_default_options(void)
{
    gt_fit_options o;
    o.max_iterations = 100;
    o.function_tolerance = 1e-12;
    o.gradient_tolerance = 0.0;
    o.parameter_tolerance = 1e-10;
    o.linear_solver = GT_FIT_DENSE_QR;
    o.threads = 1;
    return o;
}

gt_fit *gt_fit_create(int parameter_count, double *params, gt_error *e)
{
    if (parameter_count < 1 || !params) {
        gt_error_set(e, kSubject, "a fit needs at least one parameter and a parameter array");
        return nullptr;
    }
    silence_glog();
    gt_fit *fit = nullptr;
    guarded(e, [&] {
        fit = new gt_fit(parameter_count, params);
        return 0;
    });
    return fit;
}

void gt_fit_destroy(gt_fit *fit) { delete fit; }

int gt_fit_set_bounds(gt_fit *fit, int index, double lower, double upper, gt_error *e)
{
    if (!fit || index < 0 || index >= fit->parameter_count)
        return gt_error_set(e, kSubject, "no parameter %d to bound", index);
    if (!(lower < upper))
        return gt_error_set(e, kSubject, "parameter %d: the lower bound %g must be below the upper bound %g", index,
                            lower, upper);
    // Ceres marks "unbounded" with the largest finite double.
    fit->problem.SetParameterLowerBound(fit->params, index, std::isinf(lower) ? -DBL_MAX : lower);
    fit->problem.SetParameterUpperBound(fit->params, index, std::isinf(upper) ? DBL_MAX : upper);
    fit->bounded = true;
    return 0;
}

int gt_fit_hold(gt_fit *fit, int index, int held, gt_error *e)
{
    if (!fit || index < 0 || index >= fit->parameter_count)
        return gt_error_set(e, kSubject, "no parameter %d to hold", index);
    return guarded(e, [&] {
        fit->held[(size_t)index] = held != 0;
        fit->hold_in_ceres(fit->held);
        return 0;
    });
}

int gt_fit_add_block(gt_fit *fit, int residual_count, gt_fit_residual_fn evaluate, void *user,
                     const gt_fit_block_options *options, gt_error *e)
{
    if (!fit || !evaluate)
        return gt_error_set(e, kSubject, "a residual block needs a fit and a callback");
    if (residual_count < 1)
        return gt_error_set(e, kSubject, "a residual block needs at least one residual, not %d", residual_count);
    // Ceres counts residuals in an int.
    if (fit->residual_count + (size_t)residual_count > (size_t)INT_MAX)
        return gt_error_set(e, kSubject, "too many residuals: Ceres allows at most %d", INT_MAX);
    const gt_fit_block_options o = options ? *options : gt_fit_block_options{};
    if (!valid_block_options(o, e))
        return -1;
    return guarded(e, [&] {
        const int n = fit->parameter_count;
        std::unique_ptr<ceres::CostFunction> cost;
        if (o.derivatives == GT_FIT_NUMERIC) {
            auto functor = std::make_unique<NumericResidual>(NumericResidual{evaluate, user});
            auto numeric = std::make_unique<NumericCost>(functor.get());
            functor.release(); // now owned by numeric
            numeric->AddParameterBlock(n);
            numeric->SetNumResiduals(residual_count);
            cost = std::move(numeric);
        } else {
            cost = std::make_unique<AnalyticResidual>(evaluate, user, residual_count, n);
        }
        ceres::LossFunction *loss = fit->loss(o.loss, o.loss_scale);
        fit->costs.push_back(std::move(cost));
        fit->problem.AddResidualBlock(fit->costs.back().get(), loss, fit->params);
        fit->residual_count += (size_t)residual_count;
        return 0;
    });
}

int gt_fit_solve(gt_fit *fit, const gt_fit_options *options, gt_fit_result *result, gt_error *e)
{
    gt_fit_result local;
    gt_fit_result *r = result ? result : &local;
    *r = gt_fit_result{};
    r->termination = GT_FIT_FAILURE;
    if (!fit)
        return gt_error_set(e, kSubject, "no fit to solve");
    r->residual_count = fit->residual_count;
    r->free_parameter_count = fit->free_parameter_count();
    const gt_fit_options o = options ? *options : gt_fit_default_options();
    return guarded(e, [&] { return solve(fit, o, r, e); });
}

int gt_fit_covariance(gt_fit *fit, double *covariance_out, double *standard_errors, double *residual_variance,
                      gt_error *e)
{
    if (!fit)
        return gt_error_set(e, kSubject, "no fit for a covariance");
    return guarded(e, [&] { return covariance(fit, covariance_out, standard_errors, residual_variance, e); });
}

} // extern "C"
