#define _POSIX_C_SOURCE 200809L
#include "core/files/atomic_file.h"

#include "core/files/output_set.h"
#include "core/files/run_inputs.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Why the temporary beside `path` could not be made, in words: a missing
 * folder is named (issue 41: "No such file or directory" alone left the
 * user guessing which), as is a path through a file; otherwise errno's. */
static int refuse_unwritable(const char *path, int dir_len, int err, gt_error *e)
{
    char folder[ATOMIC_PATH_MAX];
    snprintf(folder, sizeof folder, "%.*s", dir_len > 1 ? dir_len - 1 : dir_len, dir_len ? path : ".");
    struct stat st;
    if (err == ENOENT && stat(folder, &st) != 0)
        return gt_error_set(e, path, "cannot write: the folder %s does not exist (gtlab does not create it)", folder);
    if (err == ENOTDIR)
        return gt_error_set(e, path, "cannot write: a part of %s is a file, not a folder", folder);
    return gt_error_set(e, path, "cannot write: %s", strerror(err));
}

int atomic_file_begin(atomic_file *f, const char *path, gt_error *e)
{
    if (!path || !*path)
        return gt_error_set(e, "gtlab", "no output path given");
    if (strlen(path) + 32 >= ATOMIC_PATH_MAX)
        return gt_error_set(e, path, "path too long");
    if (run_inputs_check_output(path, e) != 0)
        return -1;
    struct stat st;
    int exists = stat(path, &st) == 0;
    if (exists && S_ISDIR(st.st_mode))
        return gt_error_set(e, path, "cannot write: is a folder");
    if (exists && !S_ISREG(st.st_mode))
        return gt_error_set(e, path, "cannot write: exists and is not a regular file (a device, pipe or socket); "
                                     "gtlab replaces only regular files");
    strcpy(f->final_path, path);
    const char *slash = strrchr(path, '/');
    int dir_len = slash ? (int)(slash - path + 1) : 0;
    snprintf(f->temp_path, sizeof f->temp_path, "%.*s.%s.tmp-%ld", dir_len, path, path + dir_len, (long)getpid());
    int fd = open(f->temp_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0)
        return refuse_unwritable(path, dir_len, errno, e);
    close(fd);
    output_set_temporary_created(f->temp_path);
    return 0;
}

int atomic_file_commit(atomic_file *f, gt_error *e)
{
    if (run_inputs_check_output(f->final_path, e) != 0) {
        atomic_file_abort(f);
        return -1;
    }
    if (output_set_rename_into_place(f->temp_path, f->final_path) != 0) {
        int err = errno;
        atomic_file_abort(f);
        return gt_error_set(e, f->final_path, "cannot write: %s", strerror(err));
    }
    output_set_temporary_gone(f->temp_path);
    f->temp_path[0] = '\0';
    return 0;
}

void atomic_file_abort(atomic_file *f)
{
    if (f->temp_path[0]) {
        unlink(f->temp_path);
        output_set_temporary_gone(f->temp_path);
    }
    f->temp_path[0] = '\0';
}

int atomic_file_check_writable(const char *path, gt_error *e)
{
    atomic_file f;
    if (atomic_file_begin(&f, path, e) != 0)
        return -1;
    atomic_file_abort(&f);
    return 0;
}

FILE *atomic_file_open(atomic_file *f, const char *path, const char *mode, gt_error *e)
{
    if (atomic_file_begin(f, path, e) != 0)
        return NULL;
    FILE *out = fopen(f->temp_path, mode);
    if (!out) {
        gt_error_set(e, path, "cannot write: %s", strerror(errno));
        atomic_file_abort(f);
    }
    return out;
}

int atomic_file_close(atomic_file *f, FILE *out, gt_error *e)
{
    int err = ferror(out) ? errno : 0; /* the failed write's errno (ENOSPC, EFBIG, ...), as it was left */
    int failed = ferror(out);
    errno = 0;
    if (fclose(out) != 0) {
        failed = 1;
        err = err ? err : errno;
    }
    if (failed) {
        atomic_file_abort(f);
        return gt_error_set(e, f->final_path, "write failed: %s", err ? strerror(err) : "an I/O error (disk full?)");
    }
    return atomic_file_commit(f, e);
}

int atomic_write_bytes(const char *path, const void *data, size_t size, gt_error *e)
{
    atomic_file f;
    FILE *out = atomic_file_open(&f, path, "wb", e);
    if (!out)
        return -1;
    fwrite(data, 1, size, out);
    return atomic_file_close(&f, out, e);
}

int atomic_write_text(const char *path, const char *text, gt_error *e)
{
    return atomic_write_bytes(path, text, strlen(text), e);
}
