/* The data of the GTAO multi-bounce refit (fitters/fit_multibounce.h) from
 * reference files: each `gtlab render multibounce` EXR read and its surface
 * pixels appended as samples (multibounce_data_add_image), then the samples
 * weighed so every scene and every albedo counts equally
 * (multibounce_data_weigh). Used by `gtlab fit multibounce`. */
#ifndef GTLAB_STUDIES_MULTIBOUNCE_FIT_INPUT_H
#define GTLAB_STUDIES_MULTIBOUNCE_FIT_INPUT_H

#include "core/error.h"
#include "fitters/fit_multibounce.h"

/* Appends the samples of files[0..count) to d (initialised by the caller)
 * and weighs them. Returns 0, or -1 with e naming the file at fault. */
int multibounce_fit_input_load(const char *const *files, int count, multibounce_data *d, gt_error *e);

#endif
