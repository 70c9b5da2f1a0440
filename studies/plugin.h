/* C plug-ins (core/plugin_abi.h): a shared library loaded with dlopen, its
 * ABI version checked, its entry points found by their versioned names, and
 * applied exactly where gtlab applies its own function of the same quantity
 * (multibounce_apply_model for GTAOMultiBounce), so one scoring serves both. */
#ifndef GTLAB_STUDIES_PLUGIN_H
#define GTLAB_STUDIES_PLUGIN_H

#include <stddef.h>

#include "core/error.h"
#include "core/plugin_abi.h"

typedef struct {
    void *handle;
    gtlab_multibounce_v1_fn multibounce_v1; /* NULL: the plug-in has no multi-bounce */
} gtlab_plugin;

/* Loads `path` (a name without a slash: the file in the working folder if
 * there is one, else dlopen's search path). Returns 0, or -1 with
 * e = "<path>: <problem>": not loadable (dlerror's words), no
 * gtlab_plugin_abi (not a gtlab plug-in), another ABI version, no entry
 * point gtlab knows. */
int plugin_open(const char *path, gtlab_plugin *p, gt_error *e);
void plugin_close(gtlab_plugin *p);

/* V'_d = plug-in(V_d, albedo) at the n pixels with mask != 0, 0 in the
 * background: multibounce_apply_model's contract. Returns 0, or -1 with e
 * naming `what` (no multi-bounce entry point, out of memory, NaN). */
int plugin_apply_multibounce(const gtlab_plugin *p, const char *what, const float *visibility, const float *mask,
                             size_t n, float albedo, float *out, gt_error *e);

#endif
