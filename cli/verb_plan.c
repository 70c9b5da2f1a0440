/* gtlab plan: one render split into jobs for a batch scheduler (raytracer/render_plan.h). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "raytracer/render_plan.h"

static const cli_option options[] = {CLI_INT("jobs", "N", 1, 65536, "jobs (disjoint blocks of the samples)"),
                                     CLI_OUTPUT_DIR, CLI_END};
static const cli_command command = {
    "plan",
    "Splits one 'gtlab render' into N jobs over disjoint --sample-offset blocks of\n"
    "its samples. DIR gets jobs.txt (one shell line a job, for any scheduler),\n"
    "job.sh (a Slurm array: sbatch --array; elsewhere 'bash job.sh INDEX'),\n"
    "merge.sh (gtlab merge of the parts, refusing parts of other renders and\n"
    "missing ones) and submit.sh (the array, then the merge). The merged\n"
    "reference is bit-identical to the render in one process.",
    options, "-- render QUANTITY [render options]", NULL};

int verb_plan(int argc, char **argv)
{
    long jobs = 0;
    const char *dir = NULL;
    cli_arguments render;
    int status;
    if (cli_options_parse(&command, (void *[]){&jobs, &dir, &render}, argc, argv, &status) != 0)
        return status;
    if (jobs < 1)
        return cli_failf("plan", "--jobs N is required");
    gt_error e;
    if (render_plan_write((int)jobs, dir, render.count, render.values, &e) != 0)
        return cli_fail(&e);
    printf("%s: %ld jobs (jobs.txt, job.sh), merge.sh; 'bash %s/submit.sh' submits them to Slurm\n", dir, jobs, dir);
    return EXIT_OK;
}
