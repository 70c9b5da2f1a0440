/* A batch plan's files (batch_script.h). */
#define _POSIX_C_SOURCE 200809L
#include "core/files/batch_script.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files/atomic_file.h"

int batch_places_find(int jobs, const char *folder, batch_places *p, gt_error *e)
{
    p->jobs = jobs;
    p->folder = folder;
    ssize_t n = readlink("/proc/self/exe", p->gtlab, sizeof p->gtlab - 1);
    if (!getcwd(p->cwd, sizeof p->cwd) || n <= 0)
        return gt_error_set(e, "plan", "cannot resolve the working folder or gtlab's own path");
    p->gtlab[n] = '\0';
    if (mkdir(folder, 0777) != 0 && errno != EEXIST)
        return gt_error_set(e, folder, "cannot create the folder: %s", strerror(errno));
    return 0;
}

void batch_put_quoted(FILE *out, const char *arg)
{
    fputc('\'', out);
    for (const char *p = arg; *p; ++p)
        *p == '\'' ? fputs("'\\''", out) : fputc(*p, out);
    fputc('\'', out);
}

void batch_put_gtlab(FILE *out, const batch_places *p, int in_script)
{
    if (in_script)
        fputs("\"$GTLAB\"", out);
    else
        batch_put_quoted(out, p->gtlab);
}

void batch_put_script_start(FILE *out, const batch_places *p, const char *sbatch_lines)
{
    fprintf(out, "#!/bin/bash\n%sset -euo pipefail\ncd ", sbatch_lines);
    batch_put_quoted(out, p->cwd);
    fputs("\nGTLAB=${GTLAB:-", out);
    batch_put_quoted(out, p->gtlab);
    fputs("}\n", out);
}

void batch_put_jobs_txt(FILE *out, const batch_places *p, batch_job_writer job, const void *plan)
{
    for (int j = 0; j < p->jobs; ++j) {
        fputs("cd ", out);
        batch_put_quoted(out, p->cwd);
        fputs(" && ", out);
        batch_put_gtlab(out, p, 0);
        job(out, plan, p, j);
        fputc('\n', out);
    }
}

void batch_put_job_sh(FILE *out, const batch_places *p, const char *job_name, batch_job_writer job, const void *plan)
{
    char lines[2 * BATCH_PATH_MAX + 256];
    snprintf(lines, sizeof lines,
             "#SBATCH --job-name=%s\n#SBATCH --array=0-%d\n#SBATCH --output=%s%s%s/job-%%a.log\n"
             "# Job index: $SLURM_ARRAY_TASK_ID, or the first argument (other schedulers).\n",
             job_name, p->jobs - 1, p->folder[0] == '/' ? "" : p->cwd, p->folder[0] == '/' ? "" : "/", p->folder);
    batch_put_script_start(out, p, lines);
    fputs("task=${1:-${SLURM_ARRAY_TASK_ID:?give the job index (0..N-1)}}\ncase \"$task\" in\n", out);
    for (int j = 0; j < p->jobs; ++j) {
        fprintf(out, "  %d) exec ", j);
        batch_put_gtlab(out, p, 1);
        job(out, plan, p, j);
        fputs(" ;;\n", out);
    }
    fprintf(out, "  *) echo \"job.sh: no job '$task' (0..%d)\" >&2; exit 1 ;;\nesac\n", p->jobs - 1);
}

void batch_put_submit_sh(FILE *out, const char *last_script, const char *what)
{
    fprintf(out,
            "#!/bin/bash\n# The job array, then the %s once every job has succeeded.\nset -euo pipefail\n"
            "here=$(dirname \"$0\")\narray=$(sbatch --parsable \"$here/job.sh\")\n"
            "sbatch --dependency=afterok:\"${array%%%%;*}\" \"$here/%s\"\n",
            what, last_script);
}

int batch_write_file(const batch_places *p, const char *name, batch_file_writer writer, const void *plan,
                     gt_error *e)
{
    char path[BATCH_PATH_MAX + 64], *text = NULL;
    size_t size = 0;
    snprintf(path, sizeof path, "%s/%s", p->folder, name);
    FILE *out = open_memstream(&text, &size);
    if (!out)
        return gt_error_set(e, path, "out of memory");
    writer(out, plan, p);
    int rc = fclose(out) != 0 ? gt_error_set(e, path, "out of memory") : atomic_write_text(path, text, e);
    free(text);
    return rc;
}
