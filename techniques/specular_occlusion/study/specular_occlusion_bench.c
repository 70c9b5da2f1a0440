/* The specular-occlusion reference's throughput; see specular_occlusion_bench.h. */
#include "specular_occlusion/specular_occlusion_bench.h"

#include <math.h>
#include <string.h>

#include "specular_occlusion/specular_occlusion_quantity.h"
#include "project/study_context.h"

/* The best samples/s over `repeats` renders, and the rays/s of that render. */
static int best_rate(const scene *s, const char *spec, const camera *cam, int threads, int repeats, double *samples,
                     double *rays, gt_error *e)
{
    specular_occlusion_render_settings so =
        specular_occlusion_render_settings_make(SPECOCC_BENCH_ROUGHNESS, ENVIRONMENT_WHITE);
    reference_request req = {.quantity = QUANTITY_SPECULAR_OCCLUSION,
                             .sampling = {.spp = SPECOCC_BENCH_SPP, .seed = 1, .threads = threads},
                             .normals = NORMAL_SHADING, .settings = &so.header};
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

int specular_occlusion_bench_run(const char *spec, int width, int height, int threads, int repeats,
                                 specular_occlusion_bench_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    scene s;
    camera cam;
    if (study_load_view(spec, width, height, &s, &cam, e) != 0)
        return -1;
    out->width = cam.width;
    out->height = cam.height;
    int rc = best_rate(&s, spec, &cam, 1, repeats, &out->samples_per_s[0], &out->rays_per_s[0], e);
    if (rc == 0)
        rc = best_rate(&s, spec, &cam, threads, repeats, &out->samples_per_s[1], &out->rays_per_s[1], e);
    scene_free(&s);
    return rc;
}
