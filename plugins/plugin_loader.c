/* C plug-ins for any quantity (plugins/plugin_loader.h). */
#include "plugins/plugin_loader.h"

#include <dlfcn.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "core/files/input_file.h"

/* dlsym's void * as a function pointer (POSIX guarantees the conversion). */
static void *lookup(void *handle, const char *name)
{
    dlerror();
    return dlsym(handle, name);
}

static const char *const kKnown[] = GTLAB_PLUGIN_ENTRY_POINTS;
enum { KNOWN = (int)(sizeof kKnown / sizeof kKnown[0]) };

static int exports_one_known(const gtlab_plugin *p)
{
    for (int k = 0; k < KNOWN; ++k)
        if (lookup(p->handle, kKnown[k]))
            return 1;
    return 0;
}

/* "a, b, ...": the entry points gtlab knows, for the error. */
static const char *known_names(char *names, size_t size)
{
    names[0] = '\0';
    for (int k = 0; k < KNOWN; ++k)
        snprintf(names + strlen(names), size - strlen(names), "%s%s", k ? ", " : "", kKnown[k]);
    return names;
}

int plugin_open(const char *path, gtlab_plugin *p, gt_error *e)
{
    memset(p, 0, sizeof *p);
    char local[4096]; /* a file in the working folder, not a library on dlopen's search path */
    const char *load = path;
    if (!strchr(path, '/') && access(path, F_OK) == 0) {
        snprintf(local, sizeof local, "./%s", path);
        load = local;
    }
    /* A file that exists (not a library on the search path; a missing one
     * gets dlopen's message) must be a regular one: dlopen of a FIFO would
     * hang (core/files/input_file.h). */
    if ((load != path || (strchr(path, '/') && access(path, F_OK) == 0)) && input_file_check(path, NULL, e) != 0)
        return -1;
    p->handle = dlopen(load, RTLD_NOW | RTLD_LOCAL);
    if (!p->handle) {
        const char *why = dlerror();
        return gt_error_set(e, path, "cannot load the plug-in: %s", why ? why : "dlopen failed");
    }
    gtlab_plugin_abi_fn abi;
    *(void **)&abi = lookup(p->handle, GTLAB_PLUGIN_ABI_SYMBOL);
    int rc = !abi ? gt_error_set(e, path, "not a gtlab plug-in: no %s() (core/plugin_abi.h)", GTLAB_PLUGIN_ABI_SYMBOL)
             : abi() != GTLAB_PLUGIN_ABI
                 ? gt_error_set(e, path, "built for plug-in ABI %d; this gtlab loads ABI %d", abi(), GTLAB_PLUGIN_ABI)
                 : 0;
    char names[512];
    if (rc == 0 && !exports_one_known(p))
        rc = gt_error_set(e, path, "exports no entry point gtlab knows (%s)", known_names(names, sizeof names));
    if (rc != 0)
        plugin_close(p);
    return rc;
}

void plugin_close(gtlab_plugin *p)
{
    if (p->handle)
        dlclose(p->handle);
    memset(p, 0, sizeof *p);
}

int plugin_exports(const gtlab_plugin *p, const char *symbol) { return lookup(p->handle, symbol) != NULL; }

/* The plug-in's out kept inside the mask, 0 outside; -1 with e at a NaN or
 * an infinity inside. */
static int masked(const char *what, const float *mask, size_t n, float *out, gt_error *e)
{
    for (size_t i = 0; i < n; ++i) {
        if (!isfinite(out[i]) && mask[i] != 0.0f)
            return gt_error_set(e, what, "the plug-in returned %s at sample %zu", isnan(out[i]) ? "NaN" : "infinity", i);
        out[i] = mask[i] != 0.0f ? out[i] : 0.0f;
    }
    return 0;
}

/* The entry point on the n samples of in (its arrays). */
static void call(void *entry, int inputs, const float *const in[], size_t n, float *out)
{
    if (inputs == 2) {
        gtlab_plugin_fn2 f;
        *(void **)&f = entry;
        f(in[0], in[1], out, n);
    } else {
        gtlab_plugin_fn4 f;
        *(void **)&f = entry;
        f(in[0], in[1], in[2], in[3], out, n);
    }
}

int plugin_apply(const gtlab_plugin *p, const char *symbol, int inputs, const float *const planes[],
                 const float constants[], const float *mask, size_t n, float *out, const char *what, gt_error *e)
{
    void *entry = lookup(p->handle, symbol);
    if (!entry)
        return gt_error_set(e, what, "the plug-in has no %s", symbol);
    if (inputs != 2 && inputs != 4)
        return gt_error_set(e, what, "%s: %d inputs; plug-in entry points take 2 or 4", symbol, inputs);
    const float *in[GTLAB_PLUGIN_MAX_INPUTS];
    float *repeated[GTLAB_PLUGIN_MAX_INPUTS] = {0};
    int rc = 0;
    for (int k = 0; k < inputs && rc == 0; ++k) {
        in[k] = planes[k];
        if (planes[k])
            continue;
        if (!(repeated[k] = malloc((n ? n : 1) * sizeof *repeated[k])))
            rc = gt_error_set(e, what, "out of memory");
        for (size_t i = 0; rc == 0 && i < n; ++i)
            repeated[k][i] = constants[k];
        in[k] = repeated[k];
    }
    if (rc == 0)
        call(entry, inputs, in, n, out);
    for (int k = 0; k < inputs; ++k)
        free(repeated[k]);
    return rc != 0 ? rc : masked(what, mask, n, out, e);
}
