#include "studies/plugin.h"

#include <dlfcn.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "core/input_file.h"

/* dlsym's void * as a function pointer (POSIX guarantees the conversion). */
static void *symbol(void *handle, const char *name)
{
    dlerror();
    return dlsym(handle, name);
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
     * hang (core/input_file.h). */
    if ((load != path || (strchr(path, '/') && access(path, F_OK) == 0)) && input_file_check(path, NULL, e) != 0)
        return -1;
    p->handle = dlopen(load, RTLD_NOW | RTLD_LOCAL);
    if (!p->handle) {
        const char *why = dlerror();
        return gt_error_set(e, path, "cannot load the plug-in: %s", why ? why : "dlopen failed");
    }
    gtlab_plugin_abi_fn abi;
    *(void **)&abi = symbol(p->handle, GTLAB_PLUGIN_ABI_SYMBOL);
    int rc = !abi ? gt_error_set(e, path, "not a gtlab plug-in: no %s() (core/plugin_abi.h)", GTLAB_PLUGIN_ABI_SYMBOL)
             : abi() != GTLAB_PLUGIN_ABI
                 ? gt_error_set(e, path, "built for plug-in ABI %d; this gtlab loads ABI %d", abi(), GTLAB_PLUGIN_ABI)
                 : 0;
    if (rc == 0) {
        *(void **)&p->multibounce_v1 = symbol(p->handle, GTLAB_MULTIBOUNCE_V1_SYMBOL);
        *(void **)&p->specular_occlusion_v1 = symbol(p->handle, GTLAB_SPECULAR_OCCLUSION_V1_SYMBOL);
        if (!p->multibounce_v1 && !p->specular_occlusion_v1)
            rc = gt_error_set(e, path, "exports no entry point gtlab knows (%s, %s)", GTLAB_MULTIBOUNCE_V1_SYMBOL,
                              GTLAB_SPECULAR_OCCLUSION_V1_SYMBOL);
    }
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

/* The plug-in's out kept inside the mask, 0 outside; -1 with e at a NaN inside. */
static int masked(const char *what, const float *mask, size_t n, float *out, gt_error *e)
{
    for (size_t i = 0; i < n; ++i) {
        if (isnan(out[i]) && mask[i] != 0.0f)
            return gt_error_set(e, what, "the plug-in returned NaN at sample %zu", i);
        out[i] = mask[i] != 0.0f ? out[i] : 0.0f;
    }
    return 0;
}

int plugin_apply_multibounce(const gtlab_plugin *p, const char *what, const float *visibility, const float *mask,
                             size_t n, float albedo, float *out, gt_error *e)
{
    if (!p->multibounce_v1)
        return gt_error_set(e, what, "the plug-in has no %s", GTLAB_MULTIBOUNCE_V1_SYMBOL);
    float *rho = calloc(n ? n : 1, sizeof *rho);
    if (!rho)
        return gt_error_set(e, what, "out of memory");
    for (size_t i = 0; i < n; ++i)
        rho[i] = albedo;
    p->multibounce_v1(visibility, rho, out, n);
    free(rho);
    return masked(what, mask, n, out, e);
}

int plugin_apply_specular_occlusion(const gtlab_plugin *p, const char *what, const so_pixel_inputs *in, float *out,
                                    gt_error *e)
{
    if (!p->specular_occlusion_v1)
        return gt_error_set(e, what, "the plug-in has no %s", GTLAB_SPECULAR_OCCLUSION_V1_SYMBOL);
    size_t n = (size_t)in->width * (size_t)in->height;
    p->specular_occlusion_v1(in->ao_cosine, in->beta, in->roughness, in->n_dot_v, out, n);
    return masked(what, in->mask, n, out, e);
}
