/* The albedos and bounce count of a diffuse path tracer
 * (raytracer/diffuse_path_wavefront.h), as `gtlab render multibounce` and
 * env-diffuse take them (--albedo, --bounces;
 * techniques/multibounce/multibounce_integrator.h parses and prints them):
 * several uniform grey albedos, or the scene's base colours, and the
 * inter-reflections after the first hit, or unlimited (Russian roulette,
 * ended after MULTIBOUNCE_PATH_LIMIT). The roulette decision at vertex d uses
 * the first coordinate of dimension pair MULTIBOUNCE_ROULETTE_PAIRS + d. */
#ifndef GTLAB_RAYTRACER_DIFFUSE_PATH_ALBEDOS_H
#define GTLAB_RAYTRACER_DIFFUSE_PATH_ALBEDOS_H

enum {
    MULTIBOUNCE_MAX_ALBEDOS = 32,
    MULTIBOUNCE_UNLIMITED = -1,
    MULTIBOUNCE_PATH_LIMIT = 1024,
    MULTIBOUNCE_ROULETTE_PAIRS = MULTIBOUNCE_PATH_LIMIT + 1
};

typedef struct {
    int scene_albedo;                       /* 1: the scene's base colours, coloured */
    int albedo_count;                       /* grey albedos (without scene_albedo) */
    float albedos[MULTIBOUNCE_MAX_ALBEDOS]; /* each in [0, 1], distinct */
    int bounces;                            /* inter-reflections >= 0, or MULTIBOUNCE_UNLIMITED */
} multibounce_settings;

#endif
