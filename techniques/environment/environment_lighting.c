/* The lighting precomputations of one environment, timed: see the header. */
#include "environment/environment_lighting.h"

#include <stdlib.h>
#include <string.h>

#include "core/progress.h"
#include "environment/environment_quality.h"

enum { CONSTANT_WIDTH = 256 }; /* blocks of 8 x 8 texels: 32 x 16 of them, as fine as a real map's */

environment_settings environment_default_settings(study_quality quality)
{
    environment_settings s = {.map_width = 64, .map_reduction = 3, .prefiltered_width = 256, .prefiltered_levels = 6,
                             .prefiltered_samples = environment_quality_of(quality)->prefiltered_samples};
    return s;
}

/* The environment's texels times its intensity (a constant: a 16 x 8 map of it). */
static float *texels_of(const environment_map *env, int *width, int *height)
{
    int constant = environment_map_is_constant(env);
    *width = constant ? CONSTANT_WIDTH : env->width, *height = constant ? CONSTANT_WIDTH / 2 : env->height;
    size_t n = (size_t)*width * *height;
    float *rgb = malloc(n * 3 * sizeof(float));
    if (!rgb)
        return NULL;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            rgb[i * 3 + c] = (constant ? env->constant[c] : env->rgb[i * 3 + c]) * env->intensity;
    return rgb;
}

static int build_all(const environment_equirect *view, const environment_settings *s, int threads,
                     environment_precomputed *p)
{
    double t0 = seconds_now();
    sh9_project_equirect(view, &p->sh);
    double t1 = seconds_now();
    if (irradiance_map_build(&p->map, view, s->map_width, s->map_reduction, threads) != 0)
        return -1;
    double t2 = seconds_now();
    if (prefiltered_radiance_build(&p->prefiltered, view, s->prefiltered_width, s->prefiltered_levels,
                                   s->prefiltered_samples, threads) != 0)
        return -1;
    double t3 = seconds_now();
    p->sh_seconds = t1 - t0, p->map_seconds = t2 - t1, p->prefiltered_seconds = t3 - t2;
    return 0;
}

int environment_precompute(const environment_map *env, const environment_settings *s, const dfg_lut *dfg, int threads,
                          environment_precomputed *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    int width, height;
    float *rgb = texels_of(env, &width, &height);
    if (!rgb)
        return gt_error_set(e, env->name, "out of memory");
    environment_equirect view = {width, height, rgb};
    int rc = build_all(&view, s, threads, out);
    free(rgb);
    if (rc != 0) {
        environment_precomputed_free(out);
        return gt_error_set(e, env->name, "out of memory building the lighting approximations");
    }
    out->multibounce = multibounce_model_jimenez2016();
    environment_lighting l = {&out->sh, &out->map, &out->prefiltered, dfg, &out->multibounce};
    out->lighting = l;
    return 0;
}

void environment_precomputed_free(environment_precomputed *p)
{
    irradiance_map_free(&p->map);
    prefiltered_radiance_free(&p->prefiltered);
}
