/* Outputs appear whole or not at all: every writer writes to a temporary file
 * beside the destination and renames it into place when complete (rename is
 * atomic within a folder on POSIX). The temporary name is
 * "<dir>/.<name>.tmp-<pid>" so a crash leaves only a hidden file, and an
 * interruption by a signal none (core/files/output_set.h: the files of one run are
 * also kept or removed together). An existing destination that is not a
 * regular file (a device such as /dev/null, a pipe, a socket) is refused,
 * never replaced, and so is an input of the run (core/files/run_inputs.h): an
 * output that is the same file as one of the run's inputs, under whatever
 * name or link. */
#ifndef GTLAB_CORE_FILES_ATOMIC_FILE_H
#define GTLAB_CORE_FILES_ATOMIC_FILE_H

#include <stdio.h>

#include "core/error.h"

#define ATOMIC_PATH_MAX 4096

typedef struct {
    char final_path[ATOMIC_PATH_MAX];
    char temp_path[ATOMIC_PATH_MAX];
} atomic_file;

/* Chooses the temporary name and checks that it can be created (so an
 * unwritable destination fails before any long computation). Returns 0 or -1
 * with e = "<path>: <problem>". */
int atomic_file_begin(atomic_file *f, const char *path, gt_error *e);
/* Renames the finished temporary file onto the destination. */
int atomic_file_commit(atomic_file *f, gt_error *e);
/* Removes the temporary file (after a failure). Safe to call twice. */
void atomic_file_abort(atomic_file *f);

/* Checks, without leaving anything behind, that `path` could be written. */
int atomic_file_check_writable(const char *path, gt_error *e);

/* A stream on a fresh temporary file for `path` (mode "w" or "wb"), or NULL
 * with e. Finish with atomic_file_close, which commits when every write and
 * the close succeeded and aborts otherwise. */
FILE *atomic_file_open(atomic_file *f, const char *path, const char *mode, gt_error *e);
int atomic_file_close(atomic_file *f, FILE *out, gt_error *e);

/* Writes a whole file atomically. */
int atomic_write_bytes(const char *path, const void *data, size_t size, gt_error *e);
int atomic_write_text(const char *path, const char *text, gt_error *e);

#endif
