/* Throughput of the environment-lit diffuse reference for `gtlab bench
 * env-diffuse` (issue 28's performance goal: at least 0.7x the white-dome
 * multibounce reference's samples/s on the same scene): the two loops on
 * the same G-buffer, grey albedo and bounces, at the same spp, each the
 * best of `repeats` passes, and their ratio. */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_THROUGHPUT_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_THROUGHPUT_H

#include <stdio.h>

#include "core/error.h"
#include "environment/environment_light.h"
#include "multibounce/multibounce_integrator.h"
#include "scene/scene.h"

/* Issue 28's goal for the ratio below. */
#define ENVIRONMENT_THROUGHPUT_GOAL 0.7

typedef struct {
    int threads, spp;
    double multibounce_samples_per_s, environment_samples_per_s; /* best of the passes */
    double multibounce_rays_per_s, environment_rays_per_s;
    double ratio; /* environment / multibounce samples/s */
} environment_throughput;

/* settings: one grey albedo and the bounces (shared by both loops);
 * environment: the light of env-diffuse. Returns 0, or -1 with e. */
int environment_throughput_run(const scene *s, const camera *cam, const multibounce_settings *settings,
                               const environment_render_settings *environment, int spp, int threads, int repeats,
                               environment_throughput *out, gt_error *e);

/* `gtlab bench env-diffuse`: the scene (builtin:NAME or a glTF file) from
 * its default camera at width x height, grey albedo 0.5, the environment
 * (white, sky, sun or an image file), run as above and printed to out as a
 * table with the ratio and whether it meets the goal. Returns 0, or -1 with e. */
typedef struct {
    const char *scene, *environment;
    int width, height, spp, bounces, threads, repeats;
} environment_bench_request;
int environment_throughput_bench(FILE *out, const environment_bench_request *rq, gt_error *e);

#endif
