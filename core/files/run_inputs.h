/* The files one run reads, so that none of them is ever an output.
 *
 * `gtlab fit multibounce --data mb.exr -o mb.exr` would replace the data
 * with the fit's JSON; `gtlab render ao --camera cam.json -o cam.json` the
 * camera with an EXR. The same file can be spelled many ways (`./x`,
 * `a/../x`, a symbolic link, a hard link), so inputs are kept by identity
 * (st_dev, st_ino of the file a path resolves to), not by name:
 *
 *   run_inputs_note(path, "--data")   an input of this run (cli/cli_options.c
 *                                     notes every option value and argument
 *                                     that names an existing file, except
 *                                     outputs; the project reader the files a
 *                                     project names)
 *   run_inputs_check_output(path, e)  -1 when path is one of them
 *
 * core/files/atomic_file.c asks before it creates any output's temporary, so no
 * writer can replace a noted input even if a verb forgot to check a
 * sidecar; the verbs check their outputs and sidecars before any work, so
 * the refusal comes first, as one line:
 *   gtlab: mb.exr: is also an input of this run (--data ./mb.exr); refusing to overwrite it
 *
 * Noting happens while the run is set up (one thread); checks may come from
 * any thread. Folders are not noted (an output folder may hold inputs). */
#ifndef GTLAB_CORE_FILES_RUN_INPUTS_H
#define GTLAB_CORE_FILES_RUN_INPUTS_H

#include "core/error.h"

/* Remembers the file `path` names, if it exists and is not a folder;
 * given_as says how the user gave it ("--data", "p.json: scenes[0].gltf"),
 * or NULL for a positional argument. */
void run_inputs_note(const char *path, const char *given_as);

/* Notes every file directly inside the folder `dir` (an input that is a
 * folder of files, e.g. `gtlab fit gtao-params --refs DIR`). */
void run_inputs_note_folder(const char *dir, const char *given_as);

/* 0 when `path` does not exist or is no noted input; otherwise -1 with
 * e = "<path>: is also an input of this run (<given as> <its path>);
 * refusing to overwrite it". */
int run_inputs_check_output(const char *path, gt_error *e);

/* 0 when no noted input lies inside the folder `dir` (at any depth, by
 * resolved path); otherwise -1 with e naming the input and the folder
 * (`what` says what gtlab writes there, e.g. "the stage ao writes here"). */
int run_inputs_check_folder(const char *dir, const char *what, gt_error *e);

/* Forgets every noted input (tests; one process running several verbs). */
void run_inputs_forget(void);

#endif
