/* The main job split into tasks (issue 46 item 5): `gtlab all --plan --jobs
 * N -o DIR` for a batch scheduler, and `mpirun -n N gtlab all`.
 *
 * A stage reads only what the stage it `needs` wrote into DIR, and writes its
 * own folder, its figures and its part of the report (report/report_part.h).
 * So the stages fall into chains (ao -> gtao -> gtao-shortcuts, ao ->
 * screen-shaders, multibounce -> shader-scores; every other stage alone),
 * and chains run in any order, in any process, with the bits of one
 * process: nothing passes between them but files they do not share. The plan
 * gives each task whole chains, the longest first to the least loaded task
 * (longest-processing-time list scheduling), a stage's cost taken from its
 * part in DIR when an earlier run at the same quality left one (else the
 * mean of those known, else 1), and at most one task per chain:
 *
 *   task j:    gtlab all --stages <its chains> --parts-only -o DIR
 *   assemble:  gtlab all --assemble -o DIR (the report from every part)
 *
 * The plan's files are DIR/plan/{jobs.txt, job.sh, assemble.sh, submit.sh}
 * (core/files/batch_script.h). The tasks share DIR (a shared file system on
 * a cluster). The critical path is the costliest chain, today ao -> gtao
 * -> gtao-shortcuts (results/summary.json's stage_seconds). */
#ifndef GTLAB_CLI_ALL_PLAN_H
#define GTLAB_CLI_ALL_PLAN_H

#include "cli/technique.h"

enum { ALL_PLAN_STAGES_MAX = 64 };

/* The tasks of a plan: task[i] is stage i's task (-1: not run). */
typedef struct {
    int tasks;
    int task[ALL_PLAN_STAGES_MAX];
    double cost[ALL_PLAN_STAGES_MAX]; /* each task's estimated seconds */
} all_plan;

/* Splits the selected stages (stages[i], i < count) into at most `jobs`
 * tasks by chains; seconds[i] is stage i's known cost (NaN: unknown). */
void all_plan_make(const all_stage *const *stages, int count, const int *selected, const double *seconds, int jobs,
                   all_plan *plan);

/* What the tasks run: the options every task and the assembly share. */
typedef struct {
    const char *quality, *project, *stage_list, *output_dir;
} all_plan_run;

/* Writes DIR/plan's files for plan; 0, or -1 with e. */
int all_plan_write(const all_stage *const *stages, int count, const all_plan *plan, const all_plan_run *run,
                   gt_error *e);

#endif
