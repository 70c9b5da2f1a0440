/* The data of the GTAO multi-bounce refit (multibounce/multibounce_fit.h) from
 * reference files: each `gtlab render multibounce` EXR read and its surface
 * pixels appended as samples (multibounce_data_add_image), then the samples
 * weighed so every scene and every albedo counts equally
 * (multibounce_data_weigh). Used by `gtlab fit multibounce`. */
#ifndef GTLAB_MULTIBOUNCE_MULTIBOUNCE_FIT_INPUT_H
#define GTLAB_MULTIBOUNCE_MULTIBOUNCE_FIT_INPUT_H

#include <stdio.h>

#include "core/error.h"
#include "multibounce/multibounce_fit.h"

/* Appends the samples of files[0..count) to d (initialised by the caller)
 * and weighs them. Returns 0, or -1 with e naming the file at fault. */
int multibounce_fit_input_load(const char *const *files, int count, multibounce_data *d, gt_error *e);

/* `gtlab fit multibounce`'s work: the files loaded and weighed, analysed,
 * the outputs written (`command_line` their provenance; out resolved by
 * multibounce_output_files_resolve) and the analysis printed to `report`.
 * Returns 0, or -1 with e naming the file at fault. */
int multibounce_fit_files(const char *const *files, int count, const char *command_line,
                          const multibounce_output_files *out, FILE *report, gt_error *e);

#endif
