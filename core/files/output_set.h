/* The files of one run appear together or not at all.
 *
 * Every gtlab output is written to a hidden temporary beside its destination
 * and renamed into place when complete (core/files/atomic_file.h): one file is
 * never half written. A verb that writes several files (an EXR and its
 * camera sidecar; a fit's JSON, C header and shaders) must also never leave
 * some of them after a failure. An output set does that:
 *
 *   output_set_begin();
 *   ... every atomic_file commit now renames the file into place (later steps
 *       of the run may read it) and remembers it; a file it replaces is kept
 *       as a hidden hard link "<dir>/.<name>.bak-<pid>" ...
 *   output_set_commit(e)  keeps them all (drops the backups), or
 *   output_set_abort()    removes every file of the set and puts back what
 *                         each replaced: the folder is as before the run.
 *
 * `gtlab` opens a set around every verb; `gtlab all` commits one per stage,
 * since later stages read earlier stages' files and a long run should keep
 * what finished.
 *
 * Interruption: output_set_install_signal_handlers() makes SIGINT, SIGTERM
 * and SIGHUP remove the run's temporaries, abort the open set and exit with
 * status 128 + signal (a signal the parent process ignores, as a shell does
 * SIGINT for a background job, stays ignored). The bookkeeping the handler reads is published with
 * atomic stores, and the handler calls only unlink, rename and _exit
 * (async-signal-safe). */
#ifndef GTLAB_CORE_FILES_OUTPUT_SET_H
#define GTLAB_CORE_FILES_OUTPUT_SET_H

#include "core/error.h"

/* Opens a set (a set already open is committed first). */
void output_set_begin(void);
/* Keeps every file of the open set and closes it; -1 with e if a backup
 * could not be removed (the outputs are in place all the same). */
int output_set_commit(gt_error *e);
/* Removes the open set's files, restores what they replaced, closes it. */
void output_set_abort(void);
/* Whether a set is open. */
int output_set_is_open(void);

void output_set_install_signal_handlers(void);
/* The line the handler writes to stderr before it exits (what was kept and
 * how to continue: "gtlab: interrupted: F.checkpoint.exr keeps ..."); NULL:
 * none. Copied (at most 1023 bytes); set from the main thread. */
void output_set_interrupt_note(const char *line);

/* For core/files/atomic_file.c. A temporary exists / no longer exists (the signal
 * handler removes those that exist). */
void output_set_temporary_created(const char *temp_path);
void output_set_temporary_gone(const char *temp_path);
/* Renames temp_path onto final_path; inside a set, first keeps an existing
 * final_path as a backup and records the file. Returns rename's result
 * (0, or -1 with errno). */
int output_set_rename_into_place(const char *temp_path, const char *final_path);

#endif
