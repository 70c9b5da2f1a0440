/* The main job's plan (cli/all_plan.h): stages that read one another stay in
 * one task, the costliest chain first to the least loaded task, at most one
 * task per chain, unknown costs taken as the mean of the known. */
#include "cli/all_plan.h"

#include <math.h>

#include "tests/check.h"

static int run_nothing(report_context *ctx, gt_error *e)
{
    (void)ctx, (void)e;
    return 0;
}

/* a -> b -> c, a -> d, e -> f, g, h (registry order). */
static const all_stage kStages[] = {
    {"a", "a", run_nothing, "a", NULL}, {"b", "b", run_nothing, "b", "a"}, {"c", "c", run_nothing, NULL, "b"},
    {"d", "d", run_nothing, NULL, "a"}, {"e", "e", run_nothing, "e", NULL}, {"f", "f", run_nothing, NULL, "e"},
    {"g", "g", run_nothing, NULL, NULL}, {"h", "h", run_nothing, NULL, NULL}};
enum { N = 8 };

static void make(const int *selected, const double *seconds, int jobs, all_plan *plan)
{
    const all_stage *stages[N];
    for (int i = 0; i < N; ++i)
        stages[i] = &kStages[i];
    all_plan_make(stages, N, selected, seconds, jobs, plan);
}

static void test_chains_and_balance(void)
{
    const int all[N] = {1, 1, 1, 1, 1, 1, 1, 1};
    /* chains: {a,b,c,d} 10, {e,f} 6, {g} 5, {h} 1 */
    const double seconds[N] = {1, 4, 3, 2, 5, 1, 5, 1};
    all_plan plan;
    make(all, seconds, 2, &plan);
    CHECK(plan.tasks == 2);
    CHECK(plan.task[0] == 0 && plan.task[1] == 0 && plan.task[2] == 0 && plan.task[3] == 0);
    CHECK(plan.task[4] == 1 && plan.task[5] == 1); /* 6 to the empty task */
    CHECK(plan.task[6] == 1);                      /* 5: task 1 holds 6 < 10 */
    CHECK(plan.task[7] == 0);                      /* 1: task 0 holds 10 < 11 */
    CHECK_NEAR(plan.cost[0] + plan.cost[1], 22.0, 1e-9);
    make(all, seconds, 64, &plan);
    CHECK(plan.tasks == 4); /* one per chain */
    make(all, seconds, 1, &plan);
    CHECK(plan.tasks == 1 && plan.task[7] == 0 && plan.cost[0] == 22.0);
}

static void test_selection_and_unknown_costs(void)
{
    /* a not run: b (reading a's files from an earlier run) starts its own chain. */
    const int some[N] = {0, 1, 1, 0, 0, 0, 1, 1};
    const double seconds[N] = {NAN, 8, NAN, NAN, NAN, NAN, 2, NAN};
    all_plan plan;
    make(some, seconds, 3, &plan);
    CHECK(plan.tasks == 3);
    CHECK(plan.task[0] == -1 && plan.task[3] == -1 && plan.task[4] == -1);
    CHECK(plan.task[1] == plan.task[2]);
    /* costs: b 8, c the mean 5, g 2, h 5: {b,c} 13 first, then h 5, then g 2 */
    CHECK_NEAR(plan.cost[plan.task[1]], 13.0, 1e-9);
    CHECK_NEAR(plan.cost[plan.task[7]], 5.0, 1e-9);
    CHECK_NEAR(plan.cost[plan.task[6]], 2.0, 1e-9);
}

int main(void)
{
    test_chains_and_balance();
    test_selection_and_unknown_costs();
    return check_report("test_all_plan");
}
