#include "environment/environment_light.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

void environment_render_settings_default(environment_render_settings *s, reference_quantity q)
{
    memset(s, 0, sizeof *s);
    s->header.quantity = q;
    snprintf(s->environment, sizeof s->environment, "white");
    s->intensity = 1.0f;
    s->f0 = -1.0f;
}

/* Not a built-in and no such file (issue 41: the image library's own words
 * were passed on): the built-ins, and Blender's world of that name if there
 * is one. */
static int refuse_unknown_environment(const char *name, gt_error *e)
{
    char blender[512];
    snprintf(blender, sizeof blender, ENVIRONMENT_BLENDER_WORLDS "%.64s.exr", name);
    struct stat st;
    if (strchr(name, '/') == NULL && stat(blender, &st) == 0)
        return gt_error_set(e, "--environment", "'%s' is not white, sky or sun, nor a file; Blender's world of that "
                                                "name is %s", name, blender);
    if (strpbrk(name, "/.")) /* a path: the message names the file */
        return gt_error_set(e, name, "cannot open: no such file (an environment is white, sky, sun or an HDR image)");
    return gt_error_set(e, "--environment", "'%s' is not white, sky or sun, nor a file that exists", name);
}

static int load_named(environment_map *map, const char *name, gt_error *e)
{
    if (strcmp(name, "white") == 0) {
        const float one[3] = {1.0f, 1.0f, 1.0f};
        return environment_map_constant(map, "white", one, e);
    }
    if (strcmp(name, "sky") == 0)
        return environment_map_sky(map, e);
    if (strcmp(name, "sun") == 0) {
        environment_sun sun = environment_sun_default();
        return environment_map_sun(map, &sun, e);
    }
    struct stat st;
    if (stat(name, &st) != 0)
        return refuse_unknown_environment(name, e);
    return environment_map_load(map, name, e);
}

/* The largest radiance of any texel (or the constant), intensity included. */
static double largest_radiance(const environment_map *map)
{
    if (environment_map_is_constant(map))
        return fmax(map->constant[0], fmax(map->constant[1], map->constant[2])) * (double)map->intensity;
    double largest = 0.0;
    for (size_t i = 0; i < 3 * (size_t)map->width * (size_t)map->height; ++i)
        largest = fmax(largest, map->rgb[i]);
    return largest * (double)map->intensity;
}

int environment_light_init(environment_light *light, const environment_render_settings *s, gt_error *e)
{
    memset(light, 0, sizeof *light);
    if (load_named(&light->map, s->environment, e) != 0)
        return -1;
    if (environment_map_transform(&light->map, s->rotate_degrees, s->intensity, e) != 0 ||
        environment_sampler_init(&light->sampler, &light->map, e) != 0) {
        environment_map_free(&light->map);
        return -1;
    }
    int sampled = !environment_map_is_constant(&light->map) && light->sampler.usable;
    light->brdf_fraction = sampled ? 0.5f : 1.0f;
    double bound = fmax(1.0, largest_radiance(&light->map) / light->brdf_fraction);
    light->scale_exponent = (int)ceil(log2(bound));
    return 0;
}

void environment_light_free(environment_light *light)
{
    environment_sampler_free(&light->sampler);
    environment_map_free(&light->map);
}

double environment_light_mixture_pdf(const environment_light *light, double p_brdf, vec3 w)
{
    double c = light->brdf_fraction;
    if (c == 1.0)
        return p_brdf;
    return c * p_brdf + (1.0 - c) * environment_sampler_pdf(&light->sampler, w);
}
