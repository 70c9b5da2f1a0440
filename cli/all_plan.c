/* The main job's tasks (all_plan.h). */
#include "cli/all_plan.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/files/batch_script.h"

/* chain[i]: the first stage of stage i's chain (i itself when it reads no
 * selected stage); needs name earlier stages, so one pass suffices. */
static void find_chains(const all_stage *const *stages, int count, const int *selected, int *chain)
{
    for (int i = 0; i < count; ++i) {
        chain[i] = i;
        for (int k = 0; stages[i]->needs && k < i; ++k)
            if (selected[k] && strcmp(stages[k]->key, stages[i]->needs) == 0)
                chain[i] = chain[k];
    }
}

/* Each selected stage's cost: its seconds, else the mean of those known, else 1. */
static void stage_costs(int count, const int *selected, const double *seconds, double *cost)
{
    double sum = 0;
    int known = 0;
    for (int i = 0; i < count; ++i)
        if (selected[i] && !isnan(seconds[i]))
            sum += seconds[i], ++known;
    for (int i = 0; i < count; ++i)
        cost[i] = !selected[i] ? 0 : !isnan(seconds[i]) ? seconds[i] : known ? sum / known : 1.0;
}

/* The unassigned chain of highest cost (ties: the earliest), or -1. */
static int costliest_chain(int count, const double *chain_cost, const int *assigned)
{
    int best = -1;
    for (int c = 0; c < count; ++c)
        if (chain_cost[c] > 0 && !assigned[c] && (best < 0 || chain_cost[c] > chain_cost[best]))
            best = c;
    return best;
}

static int least_loaded(const all_plan *plan, int tasks)
{
    int best = 0;
    for (int t = 1; t < tasks; ++t)
        if (plan->cost[t] < plan->cost[best])
            best = t;
    return best;
}

void all_plan_make(const all_stage *const *stages, int count, const int *selected, const double *seconds, int jobs,
                   all_plan *plan)
{
    int chain[ALL_PLAN_STAGES_MAX], assigned[ALL_PLAN_STAGES_MAX] = {0}, chains = 0;
    double cost[ALL_PLAN_STAGES_MAX], chain_cost[ALL_PLAN_STAGES_MAX] = {0};
    memset(plan, 0, sizeof *plan);
    find_chains(stages, count, selected, chain);
    stage_costs(count, selected, seconds, cost);
    for (int i = 0; i < count; ++i) {
        plan->task[i] = -1;
        if (selected[i])
            chains += chain[i] == i, chain_cost[chain[i]] += cost[i] > 0 ? cost[i] : 1e-9;
    }
    plan->tasks = chains < jobs ? chains : jobs;
    for (int c; (c = costliest_chain(count, chain_cost, assigned)) >= 0;) {
        int t = least_loaded(plan, plan->tasks);
        assigned[c] = 1;
        plan->cost[t] += chain_cost[c];
        for (int i = 0; i < count; ++i)
            if (selected[i] && chain[i] == c)
                plan->task[i] = t;
    }
}

/* What a job of the plan needs: the stages, the plan, the run. */
typedef struct {
    const all_stage *const *stages;
    int count;
    const all_plan *plan;
    const all_plan_run *run;
} plan_text;

/* " all --quality Q [--project P]": the options every command shares. */
static void put_run_options(FILE *out, const all_plan_run *run)
{
    fputs(" all --quality ", out);
    batch_put_quoted(out, run->quality);
    if (run->project)
        fputs(" --project ", out), batch_put_quoted(out, run->project);
}

/* Task j: its stages, their parts only. */
static void put_task(FILE *out, const void *text, const batch_places *p, int j)
{
    const plan_text *t = text;
    char list[4096];
    size_t n = 0;
    list[0] = 0;
    for (int i = 0; i < t->count && n < sizeof list; ++i)
        if (t->plan->task[i] == j)
            n += (size_t)snprintf(list + n, sizeof list - n, "%s%s", n ? "," : "", t->stages[i]->key);
    (void)p;
    put_run_options(out, t->run);
    fputs(" --stages ", out);
    batch_put_quoted(out, list);
    fputs(" --parts-only -o ", out);
    batch_put_quoted(out, t->run->output_dir);
}

static void put_jobs_txt(FILE *out, const void *text, const batch_places *p)
{
    batch_put_jobs_txt(out, p, put_task, text);
}

static void put_job_sh(FILE *out, const void *text, const batch_places *p)
{
    batch_put_job_sh(out, p, "gtlab-all", put_task, text);
}

static void put_assemble_sh(FILE *out, const void *text, const batch_places *p)
{
    const plan_text *t = text;
    batch_put_script_start(out, p, "#SBATCH --job-name=gtlab-report\n");
    fputs("exec \"$GTLAB\"", out);
    put_run_options(out, t->run);
    if (t->run->stage_list)
        fputs(" --stages ", out), batch_put_quoted(out, t->run->stage_list);
    fputs(" --assemble -o ", out);
    batch_put_quoted(out, t->run->output_dir);
    fputc('\n', out);
}

static void put_submit_sh(FILE *out, const void *text, const batch_places *p)
{
    (void)text, (void)p;
    batch_put_submit_sh(out, "assemble.sh", "report");
}

int all_plan_write(const all_stage *const *stages, int count, const all_plan *plan, const all_plan_run *run,
                   gt_error *e)
{
    static const char *const names[] = {"jobs.txt", "job.sh", "assemble.sh", "submit.sh"};
    static const batch_file_writer writers[] = {put_jobs_txt, put_job_sh, put_assemble_sh, put_submit_sh};
    char folder[BATCH_PATH_MAX];
    batch_places places;
    const plan_text text = {stages, count, plan, run};
    snprintf(folder, sizeof folder, "%s/plan", run->output_dir);
    if (batch_places_find(plan->tasks, folder, &places, e) != 0)
        return -1;
    for (int i = 0; i < 4; ++i)
        if (batch_write_file(&places, names[i], writers[i], &text, e) != 0)
            return -1;
    return 0;
}
