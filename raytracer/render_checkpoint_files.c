/* Where a render's checkpoints live (render_checkpoint_files.h). */
#define _POSIX_C_SOURCE 200809L
#include "raytracer/render_checkpoint_files.h"

#include <dirent.h>
#include <stdio.h>
#include <string.h>

#include "raytracer/distributed_render.h"

/* The output's path without ".exr": the checkpoints' common stem. */
static int stem_length(const char *output_path)
{
    size_t n = strlen(output_path);
    return n >= 4 && strcmp(output_path + n - 4, ".exr") == 0 ? (int)n - 4 : (int)n;
}

void render_checkpoint_path(const char *output_path, char *out, int out_size)
{
    render_share share = distributed_share();
    int stem = stem_length(output_path);
    if (share.ranks == 1)
        snprintf(out, (size_t)out_size, "%.*s.checkpoint.exr", stem, output_path);
    else
        snprintf(out, (size_t)out_size, "%.*s.checkpoint.rank%d-of-%d.exr", stem, output_path, share.rank,
                 share.ranks);
}

/* The number of processes that wrote the checkpoint named `rest` (what
 * follows "<stem>.checkpoint."): 1 for "exr", N for "rank<r>-of-<N>.exr";
 * 0 when it is not one of ours. */
static int processes_of(const char *rest)
{
    int rank, ranks, end = 0;
    if (strcmp(rest, "exr") == 0)
        return 1;
    if (sscanf(rest, "rank%d-of-%d.exr%n", &rank, &ranks, &end) == 2 && end > 0 && rest[end] == '\0' &&
        rank >= 0 && rank < ranks)
        return ranks;
    return 0;
}

/* The first (by name) checkpoint in `dir` of the stem `base` written by
 * another number of processes than `ranks`, into found (else ""); returns
 * that number, or 0. */
static int other_count_checkpoint(const char *dir, const char *base, int ranks, char *found, size_t size)
{
    char prefix[1024];
    size_t n = (size_t)snprintf(prefix, sizeof prefix, "%s.checkpoint.", base);
    int found_count = 0;
    found[0] = '\0';
    DIR *d = opendir(dir);
    for (struct dirent *entry; d && (entry = readdir(d)) != NULL;) {
        const char *name = entry->d_name;
        int count = strncmp(name, prefix, n) == 0 ? processes_of(name + n) : 0;
        if (count != 0 && count != ranks && (found[0] == '\0' || strcmp(name, found) < 0))
            snprintf(found, size, "%s", name), found_count = count;
    }
    if (d)
        closedir(d);
    return found_count;
}

/* The refusal of `found` (in the output's folder, dir_length characters of
 * output_path), a checkpoint of a run on `count` processes. */
static int refuse_other_count(const char *output_path, int dir_length, const char *found, int count, int ranks,
                              gt_error *e)
{
    char path[4096], how[64];
    snprintf(path, sizeof path, "%.*s%s", dir_length, output_path, found);
    if (count == 1)
        snprintf(how, sizeof how, "one process (no mpirun)");
    else
        snprintf(how, sizeof how, "mpirun -n %d", count);
    return gt_error_set(e, path, "a checkpoint of this output from a run on %d process(es), this one has %d: "
                                 "resume it with %s, or remove it", count, ranks, how);
}

int render_checkpoint_prepare(const char *output_path, int resume, char *out, int out_size, gt_error *e)
{
    render_checkpoint_path(output_path, out, out_size);
    if (!resume)
        return 0;
    const char *slash = strrchr(output_path, '/'), *name = slash ? slash + 1 : output_path;
    const int dir_length = slash ? (int)(name - output_path) : 0, ranks = distributed_share().ranks;
    char dir[4096], base[1024], found[1024];
    snprintf(dir, sizeof dir, "%.*s", dir_length ? dir_length : 1, dir_length ? output_path : ".");
    snprintf(base, sizeof base, "%.*s", stem_length(name), name);
    int count = other_count_checkpoint(dir, base, ranks, found, sizeof found);
    return count == 0 ? 0 : refuse_other_count(output_path, dir_length, found, count, ranks, e);
}

void render_checkpoint_finish(const char *checkpoint_path, int written)
{
    if (distributed_all(written))
        remove(checkpoint_path); /* the render is whole: its checkpoint has served */
}
