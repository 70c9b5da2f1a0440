/* The volumetric-light ray-march; see volumetric_light_raymarch.h. */
#include "volumetric_light/volumetric_light_raymarch.h"

#include <math.h>
#include <string.h>

#include "realtime/dither_patterns.h"

static const char *const noise_names[RAYMARCH_NOISE_COUNT] = {"none", "white", "bayer", "ign", "blue"};
static const double golden = 0.61803398874989484820; /* (sqrt 5 - 1) / 2 */

const char *raymarch_noise_name(raymarch_noise n)
{
    return n >= 0 && n < RAYMARCH_NOISE_COUNT ? noise_names[n] : "unknown";
}

int raymarch_noise_parse(const char *name, raymarch_noise *n)
{
    for (int i = 0; i < RAYMARCH_NOISE_COUNT; ++i)
        if (strcmp(name, noise_names[i]) == 0) {
            *n = (raymarch_noise)i;
            return 0;
        }
    return -1;
}

double raymarch_offset(raymarch_noise n, const blue_noise_texture *blue, int frame, int x, int y)
{
    static const dither_pattern patterns[RAYMARCH_NOISE_COUNT] = {DITHER_PATTERN_WHITE, DITHER_PATTERN_WHITE,
                                                                  DITHER_PATTERN_BAYER, DITHER_PATTERN_IGN,
                                                                  DITHER_PATTERN_BLUE};
    if (n == RAYMARCH_NOISE_NONE)
        return 0.0;
    if (n == RAYMARCH_NOISE_WHITE)
        return dither_pattern_value(DITHER_PATTERN_WHITE, NULL, (uint64_t)frame, x, y);
    double v = dither_pattern_value(patterns[n], blue, 0, x, y) + golden * frame;
    return v - floor(v);
}

double raymarch_ray(const raymarch_lighting *l, vec3 o, vec3 w, double distance, int steps, double xi)
{
    double t0, t1;
    if (!(distance > 0.0) || steps < 1 ||
        volumetric_cone_interval(l->light, l->light->cos_outer, o, w, 0.0, distance, &t0, &t1) != 0)
        return 0.0;
    double delta = (t1 - t0) / steps, sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        double t = t0 + (i + xi) * delta, j = volumetric_inscatter_density(l->light, l->medium, o, w, t);
        vec3 x = v3((float)(o.x + t * w.x), (float)(o.y + t * w.y), (float)(o.z + t * w.z));
        if (j > 0.0 && l->shadows)
            j *= shadow_map_visibility(l->shadows, x);
        else if (j > 0.0 && l->cube)
            j *= shadow_cube_visibility(l->cube, x);
        sum += j;
    }
    return delta * sum;
}

void raymarch_image(const raymarch_lighting *l, const raymarch_view *view, int steps, raymarch_noise noise,
                    const blue_noise_texture *blue, int frame, int threads, float *out)
{
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : 1)
    for (int y = 0; y < view->height; ++y)
        for (int x = 0; x < view->width; ++x) {
            long p = (long)y * view->width + x;
            vec3 w = v3_load(&view->dir[3 * p]);
            double xi = raymarch_offset(noise, blue, frame, x, y);
            out[p] = (float)raymarch_ray(l, view->eye, w, view->distance[p], steps, xi);
        }
}
