/* gtlab bench specular-occlusion: samples/s (and rays/s) of the specular-
 * occlusion reference loop at 64 spp, 1 thread and T threads, best of R. */
#include <math.h>
#include <stdio.h>

#include "cli/bench_specular_occlusion.h"
#include "raytracer/reference_render.h"

static int best_rate(const scene *s, const char *spec, const camera *cam, int threads, int repeats, double *samples,
                     double *rays, gt_error *e)
{
    reference_request req = {.quantity = QUANTITY_SPECULAR_OCCLUSION, .sampling = {.spp = 64, .seed = 1, .threads = threads},
                             .normals = NORMAL_SHADING, .max_distance = INFINITY, .roughness = 0.5f};
    *samples = *rays = 0.0;
    for (int r = 0; r < repeats; ++r) {
        image img;
        render_stats stats;
        if (reference_render(s, spec, cam, &req, &img, &stats, e) != 0)
            return -1;
        image_free(&img);
        if (stats.seconds > 0.0 && stats.samples / stats.seconds > *samples)
            *samples = stats.samples / stats.seconds, *rays = stats.rays / stats.seconds;
    }
    return 0;
}

int bench_specular_occlusion(const scene *s, const char *spec, const camera *cam, int threads, int repeats, gt_error *e)
{
    double samples[2], rays[2];
    if (best_rate(s, spec, cam, 1, repeats, &samples[0], &rays[0], e) != 0 ||
        best_rate(s, spec, cam, threads, repeats, &samples[1], &rays[1], e) != 0)
        return -1;
    printf("specular-occlusion reference on %s, %dx%d, 64 spp, roughness 0.5 (best of %d)\n", spec, cam->width,
           cam->height, repeats);
    printf("%-34s %14s %14s\n", "", "1 thread", "threads");
    printf("%-34s %14.3e %14.3e\n", "samples/s", samples[0], samples[1]);
    printf("%-34s %14.3e %14.3e\n", "rays/s (one ray per sample above)", rays[0], rays[1]);
    printf("%-34s %14s %14.3f\n", "speed-up threads / 1 thread", "", samples[1] / samples[0]);
    return 0;
}
