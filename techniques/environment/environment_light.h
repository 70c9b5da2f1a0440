/* The light of the environment-lit references (`gtlab render env-diffuse`,
 * `env-specular`): an environment (core/optics/environment_map.h) chosen by name,
 * turned and scaled, with its sampler (core/optics/environment_sampler.h), the MIS
 * mixture weight c of BRDF sampling, and the film's scale exponent.
 *
 *   "white"  constant radiance 1 (the white dome); c = 1: BRDF sampling
 *            alone, which makes env-diffuse under it the multibounce
 *            reference bit for bit (docs/decisions.md)
 *   "sky"    the analytic sky (core/optics/sky_environment.h) on 1024 x 512
 *   "sun"    the synthetic sun, environment_sun_default()
 *   a path   an equirectangular image any format OIIO reads
 *
 * Other environments draw each direction from BRDF sampling with
 * probability c = 1/2, else from the environment's sampler (one-sample
 * balance heuristic); an environment of luminance 0 everywhere uses c = 1.
 *
 * The film's scale exponent E (core/statistics/mc_film.h) bounds a direct sample:
 * f cos / p_mix <= 1 / c for Lambert (L / albedo) and for GGX without
 * Fresnel (G2 / G1 <= 1), so |sample| <= L_max / c, and
 * E = ceil(log2(max(1, intensity L_max / c))): 0 for the white dome. */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_LIGHT_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_LIGHT_H

#include "core/optics/environment_map.h"
#include "core/optics/environment_sampler.h"
#include "multibounce/multibounce_integrator.h"
#include "raytracer/reference_quantity.h"

/* Blender's CC0 studio-light worlds (Debian's blender-data): what the
 * environment study renders under, by name, <name>.exr. */
#define ENVIRONMENT_BLENDER_WORLDS "/usr/share/blender/datafiles/studiolights/world/"

/* The settings of env-diffuse and env-specular, one struct for both
 * (reference_request.settings; the header names the one rendered). */
typedef struct {
    reference_settings header;
    char environment[ENVIRONMENT_NAME_MAX]; /* "white", "sky", "sun" or a file */
    float rotate_degrees, intensity;
    float f0; /* env-specular: grey F0 for every surface; < 0: the materials' */
    multibounce_settings multibounce; /* env-diffuse: albedos (one grey or the scene's), bounces */
    float roughness;                  /* env-specular: a roughness setting (core/roughness_setting.h) */
} environment_render_settings;

/* The defaults for quantity q (env-diffuse or env-specular, which the header
 * names): white, no rotation, intensity 1, the materials' F0. */
void environment_render_settings_default(environment_render_settings *s, reference_quantity q);

typedef struct {
    environment_map map;
    environment_sampler sampler;
    float brdf_fraction;  /* c */
    int scale_exponent;   /* E */
} environment_light;

/* Builds the light of the settings. Returns 0, or -1 with e naming the file
 * or environment. */
int environment_light_init(environment_light *light, const environment_render_settings *s, gt_error *e);
void environment_light_free(environment_light *light);

/* The radiance from unit world direction w. */
static inline void environment_light_radiance(const environment_light *light, vec3 w, float rgb[3])
{
    environment_map_radiance(&light->map, w, rgb);
}

/* The mixture density c p_brdf + (1 - c) p_env(w) for the BRDF's density
 * p_brdf at unit world direction w. */
double environment_light_mixture_pdf(const environment_light *light, double p_brdf, vec3 w);

#endif
