/* C plug-ins (core/plugin_abi.h): a shared library loaded with dlopen, its
 * ABI version checked, its entry points found by their versioned names, and
 * applied exactly where gtlab applies its own function of the same quantity
 * (multibounce_apply_model for GTAOMultiBounce, so_approx_evaluate for
 * specular occlusion), so one scoring serves both. */
#ifndef GTLAB_STUDIES_PLUGIN_H
#define GTLAB_STUDIES_PLUGIN_H

#include <stddef.h>

#include "core/error.h"
#include "core/plugin_abi.h"
#include "realtime/specular_occlusion_screen.h"

typedef struct {
    void *handle;
    gtlab_multibounce_v1_fn multibounce_v1; /* NULL: the plug-in has no multi-bounce */
    gtlab_specular_occlusion_v1_fn specular_occlusion_v1; /* NULL: no specular occlusion */
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

/* V_s = plug-in(cosine AO, beta, roughness, n.v) at every pixel of `in`, 0
 * outside its mask: so_approx_evaluate's contract. Returns 0, or -1 with e
 * naming `what` (no specular-occlusion entry point, NaN in the mask). */
int plugin_apply_specular_occlusion(const gtlab_plugin *p, const char *what, const so_pixel_inputs *in, float *out,
                                    gt_error *e);

#endif
