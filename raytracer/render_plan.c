/* Writing a render's job plan (render_plan.h). */
#define _POSIX_C_SOURCE 200809L
#include "raytracer/render_plan.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/batch_script.h"
#include "core/number_parse.h"

enum { MAX_ARGS = 1024 };

/* The render as planned: its own arguments minus those the plan sets per
 * job (--spp, --sample-offset, --seed, -o/--output), and their values. */
typedef struct {
    const char *kept[MAX_ARGS];
    int kept_count;
    long spp, offset, seed;
    const char *output;
} planned_render;

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

/* Job j's samples: [first, first + count). */
static void job_block(const planned_render *r, int jobs, int j, long *first, long *count)
{
    long begin = r->spp * j / jobs, end = r->spp * (j + 1) / jobs;
    *first = r->offset + begin;
    *count = end - begin;
}

static void put_part_path(FILE *out, const batch_places *p, int j)
{
    char path[BATCH_PATH_MAX + 32];
    snprintf(path, sizeof path, "%s/part-%d.exr", p->folder, j);
    batch_put_quoted(out, path);
}

/* Job j's arguments: "render ... --spp n --sample-offset k --seed s -o DIR/part-j.exr". */
static void put_job(FILE *out, const void *plan, const batch_places *p, int j)
{
    const planned_render *r = plan;
    long first, count;
    job_block(r, p->jobs, j, &first, &count);
    for (int i = 0; i < r->kept_count; ++i)
        fputc(' ', out), batch_put_quoted(out, r->kept[i]);
    fprintf(out, " --spp %ld --sample-offset %ld --seed %ld -o ", count, first, r->seed);
    put_part_path(out, p, j);
}

static void put_jobs_txt(FILE *out, const void *plan, const batch_places *p)
{
    batch_put_jobs_txt(out, p, put_job, plan);
}

static void put_job_sh(FILE *out, const void *plan, const batch_places *p)
{
    batch_put_job_sh(out, p, "gtlab-render", put_job, plan);
}

static void put_merge_sh(FILE *out, const void *plan, const batch_places *p)
{
    const planned_render *r = plan;
    batch_put_script_start(out, p, "#SBATCH --job-name=gtlab-merge\n");
    fputs("exec \"$GTLAB\" merge", out);
    for (int j = 0; j < p->jobs; ++j)
        fputc(' ', out), put_part_path(out, p, j);
    fprintf(out, " --expect-blocks '%ld:%ld+%ld' -o ", r->seed, r->offset, r->spp);
    batch_put_quoted(out, r->output);
    fputc('\n', out);
}

static void put_submit_sh(FILE *out, const void *plan, const batch_places *p)
{
    (void)plan, (void)p;
    batch_put_submit_sh(out, "merge.sh", "merge");
}

int render_plan_write(int jobs, const char *folder, int argc, char *const *argv, gt_error *e)
{
    static const char *const names[] = {"jobs.txt", "job.sh", "merge.sh", "submit.sh"};
    static const batch_file_writer writers[] = {put_jobs_txt, put_job_sh, put_merge_sh, put_submit_sh};
    planned_render *r = malloc(sizeof *r);
    batch_places *p = malloc(sizeof *p);
    int rc = r && p ? 0 : gt_error_set(e, "plan", "out of memory");
    if (rc == 0)
        rc = read_render(jobs, argc, argv, r, e);
    if (rc == 0)
        rc = batch_places_find(jobs, folder, p, e);
    for (int i = 0; i < 4 && rc == 0; ++i)
        rc = batch_write_file(p, names[i], writers[i], r, e);
    free(r);
    free(p);
    return rc;
}
