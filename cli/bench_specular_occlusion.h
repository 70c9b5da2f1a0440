/* gtlab bench specular-occlusion: the specular-occlusion reference's
 * samples/s at 64 spp, 1 thread and `threads`, best of `repeats`; printed. */
#ifndef GTLAB_CLI_BENCH_SPECULAR_OCCLUSION_H
#define GTLAB_CLI_BENCH_SPECULAR_OCCLUSION_H

#include "scene/camera.h"
#include "scene/scene.h"

int bench_specular_occlusion(const scene *s, const char *spec, const camera *cam, int threads, int repeats, gt_error *e);

#endif
