/* C plug-ins (core/plugin_abi.h) for any quantity: a shared library loaded
 * with dlopen, its ABI version checked, an entry point found by its
 * versioned name and applied to a quantity's inputs at the masked pixels,
 * as gtlab applies its own function of that quantity, so one scorer
 * (scoring/function_score.h) serves every quantity. The loader knows no
 * quantity: the caller names the entry point and its inputs. */
#ifndef GTLAB_PLUGINS_PLUGIN_LOADER_H
#define GTLAB_PLUGINS_PLUGIN_LOADER_H

#include <stddef.h>

#include "core/error.h"
#include "core/plugin_abi.h"

typedef struct {
    void *handle;
} gtlab_plugin;

/* Loads `path` (a name without a slash: the file in the working folder if
 * there is one, else dlopen's search path). Returns 0, or -1 with
 * e = "<path>: <problem>": not loadable (dlerror's words), no
 * gtlab_plugin_abi (not a gtlab plug-in), another ABI version, none of the
 * entry points gtlab knows (GTLAB_PLUGIN_ENTRY_POINTS). */
int plugin_open(const char *path, gtlab_plugin *p, gt_error *e);
void plugin_close(gtlab_plugin *p);

/* Whether the plug-in exports the entry point `symbol`. */
int plugin_exports(const gtlab_plugin *p, const char *symbol);

/* out = symbol(inputs...) at the n pixels with mask != 0, 0 elsewhere: its
 * argument k is the array planes[k], or constants[k] repeated where
 * planes[k] is NULL; `inputs` is 2 or 4 (core/plugin_abi.h's shapes).
 * Returns 0, or -1 with e naming `what` (no such entry point, out of
 * memory, NaN at a masked pixel). */
int plugin_apply(const gtlab_plugin *p, const char *symbol, int inputs, const float *const planes[],
                 const float constants[], const float *mask, size_t n, float *out, const char *what, gt_error *e);

#endif
