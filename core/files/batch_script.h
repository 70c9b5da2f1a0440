/* The files of a batch plan (`gtlab plan` for one render,
 * raytracer/render_plan.h; `gtlab all --plan` for the main job, cli/all_plan.h):
 * N jobs for any scheduler, then one last step once all have succeeded.
 *
 *   jobs.txt   one shell line a job ("cd CWD && gtlab ..."), for any
 *              scheduler or `parallel`;
 *   job.sh     a Slurm array script (#SBATCH --array=0-(N-1), a log per job
 *              in the plan's folder); it runs job $SLURM_ARRAY_TASK_ID, or
 *              the index given as its argument (PBS_ARRAY_INDEX,
 *              LSB_JOBINDEX - 1, SGE_TASK_ID - 1, ...);
 *   LAST.sh    the last step (the plan writes it with batch_put_script_start);
 *   submit.sh  `sbatch --parsable job.sh`, then LAST.sh with
 *              --dependency=afterok on the array.
 *
 * Every job changes to the folder the plan was made in first, so relative
 * paths stay relative to it, and runs the gtlab that made the plan (by its
 * absolute path; $GTLAB overrides it in the scripts). */
#ifndef GTLAB_CORE_FILES_BATCH_SCRIPT_H
#define GTLAB_CORE_FILES_BATCH_SCRIPT_H

#include <stdio.h>

#include "core/error.h"

enum { BATCH_PATH_MAX = 4096 };

/* Where a plan lives: its jobs, its folder, the working folder and gtlab. */
typedef struct {
    int jobs;
    const char *folder;
    char cwd[BATCH_PATH_MAX], gtlab[BATCH_PATH_MAX];
} batch_places;

/* Job j's command after gtlab (see batch_put_gtlab): its arguments. */
typedef void (*batch_job_writer)(FILE *out, const void *plan, const batch_places *p, int job);
/* A whole file of the plan. */
typedef void (*batch_file_writer)(FILE *out, const void *plan, const batch_places *p);

/* Fills p (the working folder, gtlab's own path) and makes the folder. */
int batch_places_find(int jobs, const char *folder, batch_places *p, gt_error *e);
/* The argument in single quotes, each ' written '\'' : the shell reads it back as is. */
void batch_put_quoted(FILE *out, const char *arg);
/* gtlab by its path, or as "$GTLAB" in a script. */
void batch_put_gtlab(FILE *out, const batch_places *p, int in_script);
/* A script's start: bash, #SBATCH lines, strict, in the working folder, $GTLAB. */
void batch_put_script_start(FILE *out, const batch_places *p, const char *sbatch_lines);
/* jobs.txt. */
void batch_put_jobs_txt(FILE *out, const batch_places *p, batch_job_writer job, const void *plan);
/* job.sh, the array named job_name ("gtlab-render"). */
void batch_put_job_sh(FILE *out, const batch_places *p, const char *job_name, batch_job_writer job, const void *plan);
/* submit.sh: the array, then last_script ("merge.sh"), which makes `what`. */
void batch_put_submit_sh(FILE *out, const char *last_script, const char *what);
/* Writes folder/name atomically from its writer. */
int batch_write_file(const batch_places *p, const char *name, batch_file_writer writer, const void *plan,
                     gt_error *e);

#endif
