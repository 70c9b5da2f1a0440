/* Writing a render's job plan (render_plan.h). */
#define _POSIX_C_SOURCE 200809L
#include "raytracer/render_plan.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/files/atomic_file.h"
#include "core/number_parse.h"

enum { PLAN_PATH_MAX = 4096, MAX_ARGS = 1024 };

/* The render as planned: its own arguments minus those the plan sets per
 * job (--spp, --sample-offset, --seed, -o/--output), and their values. */
typedef struct {
    const char *kept[MAX_ARGS];
    int kept_count;
    long spp, offset, seed;
    const char *output;
} planned_render;

/* Where everything lives: the folder, the working folder and gtlab. */
typedef struct {
    int jobs;
    const char *folder;
    char cwd[PLAN_PATH_MAX], gtlab[PLAN_PATH_MAX];
} plan_places;

static int read_value(planned_render *r, const char *option, const char *text, gt_error *e)
{
    if (strcmp(option, "--spp") == 0)
        return parse_whole_in(option, text, 1, 1 << 24, &r->spp, e);
    if (strcmp(option, "--sample-offset") == 0)
        return parse_whole_in(option, text, 0, 4294967295L, &r->offset, e);
    if (strcmp(option, "--seed") == 0)
        return parse_whole_in(option, text, 0, 4294967295L, &r->seed, e);
    r->output = text;
    return 0;
}

static int is_planned_option(const char *arg)
{
    static const char *const names[] = {"--spp", "--sample-offset", "--seed", "-o", "--output"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i)
        if (strcmp(arg, names[i]) == 0)
            return 1;
    return 0;
}

/* One argument of the render command at argv[*i] (moving past its value). */
static int read_argument(planned_render *r, int argc, char *const *argv, int *i, gt_error *e)
{
    const char *arg = argv[*i];
    if (strncmp(arg, "--target-", 9) == 0)
        return gt_error_set(e, arg, "adaptive parts do not merge (each pixel stops by its own samples): plan a "
                                    "fixed --spp");
    if (!is_planned_option(arg)) {
        if (r->kept_count == MAX_ARGS)
            return gt_error_set(e, "plan", "more than %d render arguments", MAX_ARGS);
        r->kept[r->kept_count++] = arg;
        return 0;
    }
    if (*i + 1 >= argc)
        return gt_error_set(e, arg, "needs a value");
    return read_value(r, arg, argv[++*i], e);
}

static int read_render(int jobs, int argc, char *const *argv, planned_render *r, gt_error *e)
{
    *r = (planned_render){.spp = 64, .offset = 0, .seed = 1}; /* gtlab render's defaults */
    if (argc < 2 || strcmp(argv[0], "render") != 0)
        return gt_error_set(e, "plan", "give the render to split after '--': gtlab plan --jobs N -o DIR -- render "
                                       "QUANTITY [options]");
    for (int i = 0; i < argc; ++i)
        if (read_argument(r, argc, argv, &i, e) != 0)
            return -1;
    if (!r->output)
        return gt_error_set(e, "plan", "the render needs -o/--output (the merged reference)");
    if (r->offset + r->spp > 4294967296L)
        return gt_error_set(e, "--sample-offset", "the block runs past sample index 2^32");
    if (jobs > r->spp)
        return gt_error_set(e, "--jobs", "%d jobs for %ld samples per pixel: every job needs one", jobs, r->spp);
    return 0;
}

/* The argument in single quotes, each ' written '\'' : the shell reads it back as is. */
static void put_quoted(FILE *out, const char *arg)
{
    fputc('\'', out);
    for (const char *p = arg; *p; ++p)
        *p == '\'' ? fputs("'\\''", out) : fputc(*p, out);
    fputc('\'', out);
}

/* Job j's samples: [first, first + count). */
static void job_block(const planned_render *r, int jobs, int j, long *first, long *count)
{
    long begin = r->spp * j / jobs, end = r->spp * (j + 1) / jobs;
    *first = r->offset + begin;
    *count = end - begin;
}

static void put_part_path(FILE *out, const plan_places *p, int j)
{
    char path[PLAN_PATH_MAX];
    snprintf(path, sizeof path, "%s/part-%d.exr", p->folder, j);
    put_quoted(out, path);
}

/* "gtlab render ... --spp n --sample-offset k --seed s -o DIR/part-j.exr":
 * gtlab by its path, or as "$GTLAB" in a script. */
static void put_job(FILE *out, const planned_render *r, const plan_places *p, int j, int in_script)
{
    long first, count;
    job_block(r, p->jobs, j, &first, &count);
    if (in_script)
        fputs("\"$GTLAB\"", out);
    else
        put_quoted(out, p->gtlab);
    for (int i = 0; i < r->kept_count; ++i)
        fputc(' ', out), put_quoted(out, r->kept[i]);
    fprintf(out, " --spp %ld --sample-offset %ld --seed %ld -o ", count, first, r->seed);
    put_part_path(out, p, j);
}

static void put_jobs_txt(FILE *out, const planned_render *r, const plan_places *p)
{
    for (int j = 0; j < p->jobs; ++j) {
        fputs("cd ", out);
        put_quoted(out, p->cwd);
        fputs(" && ", out);
        put_job(out, r, p, j, 0);
        fputc('\n', out);
    }
}

/* The script's common start: bash, strict, in the working folder, $GTLAB. */
static void put_script_start(FILE *out, const plan_places *p, const char *sbatch_lines)
{
    fprintf(out, "#!/bin/bash\n%sset -euo pipefail\ncd ", sbatch_lines);
    put_quoted(out, p->cwd);
    fputs("\nGTLAB=${GTLAB:-", out);
    put_quoted(out, p->gtlab);
    fputs("}\n", out);
}

static void put_job_sh(FILE *out, const planned_render *r, const plan_places *p)
{
    char lines[2 * PLAN_PATH_MAX + 256];
    snprintf(lines, sizeof lines,
             "#SBATCH --job-name=gtlab-render\n#SBATCH --array=0-%d\n#SBATCH --output=%s%s%s/job-%%a.log\n"
             "# Job index: $SLURM_ARRAY_TASK_ID, or the first argument (other schedulers).\n",
             p->jobs - 1, p->folder[0] == '/' ? "" : p->cwd, p->folder[0] == '/' ? "" : "/", p->folder);
    put_script_start(out, p, lines);
    fputs("task=${1:-${SLURM_ARRAY_TASK_ID:?give the job index (0..N-1)}}\ncase \"$task\" in\n", out);
    for (int j = 0; j < p->jobs; ++j) {
        fprintf(out, "  %d) exec ", j);
        put_job(out, r, p, j, 1);
        fputs(" ;;\n", out);
    }
    fprintf(out, "  *) echo \"job.sh: no job '$task' (0..%d)\" >&2; exit 1 ;;\nesac\n", p->jobs - 1);
}

static void put_merge_sh(FILE *out, const planned_render *r, const plan_places *p)
{
    put_script_start(out, p, "#SBATCH --job-name=gtlab-merge\n");
    fputs("exec \"$GTLAB\" merge", out);
    for (int j = 0; j < p->jobs; ++j)
        fputc(' ', out), put_part_path(out, p, j);
    fprintf(out, " --expect-blocks '%ld:%ld+%ld' -o ", r->seed, r->offset, r->spp);
    put_quoted(out, r->output);
    fputc('\n', out);
}

static void put_submit_sh(FILE *out, const planned_render *r, const plan_places *p)
{
    (void)r, (void)p;
    fputs("#!/bin/bash\n# The job array, then the merge once every job has succeeded.\nset -euo pipefail\n"
          "here=$(dirname \"$0\")\narray=$(sbatch --parsable \"$here/job.sh\")\n"
          "sbatch --dependency=afterok:\"${array%%;*}\" \"$here/merge.sh\"\n",
          out);
}

typedef void (*plan_writer)(FILE *, const planned_render *, const plan_places *);

/* Writes one file of the plan (atomically) from its writer. */
static int write_plan_file(const plan_places *p, const char *name, plan_writer writer, const planned_render *r,
                           gt_error *e)
{
    char path[PLAN_PATH_MAX], *text = NULL;
    size_t size = 0;
    snprintf(path, sizeof path, "%s/%s", p->folder, name);
    FILE *out = open_memstream(&text, &size);
    if (!out)
        return gt_error_set(e, path, "out of memory");
    writer(out, r, p);
    int rc = fclose(out) != 0 ? gt_error_set(e, path, "out of memory") : atomic_write_text(path, text, e);
    free(text);
    return rc;
}

static int find_places(int jobs, const char *folder, plan_places *p, gt_error *e)
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

int render_plan_write(int jobs, const char *folder, int argc, char *const *argv, gt_error *e)
{
    static const char *const names[] = {"jobs.txt", "job.sh", "merge.sh", "submit.sh"};
    static const plan_writer writers[] = {put_jobs_txt, put_job_sh, put_merge_sh, put_submit_sh};
    planned_render *r = malloc(sizeof *r);
    plan_places *p = malloc(sizeof *p);
    int rc = r && p ? 0 : gt_error_set(e, "plan", "out of memory");
    if (rc == 0)
        rc = read_render(jobs, argc, argv, r, e);
    if (rc == 0)
        rc = find_places(jobs, folder, p, e);
    for (int i = 0; i < 4 && rc == 0; ++i)
        rc = write_plan_file(p, names[i], writers[i], r, e);
    free(r);
    free(p);
    return rc;
}
