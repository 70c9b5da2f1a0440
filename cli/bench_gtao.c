/* gtlab bench gtao: GTAO at 1920x1080 in the talk's configuration (seeds/001,
 * "Achieving the Performance Target": half resolution, 1 direction per pixel,
 * 8 samples per direction, spatial and temporal denoisers), and the cost per
 * pixel of every preset next to the brute-force reference's and the
 * height-field Monte Carlo reference's, measured in one run. */
#include <getopt.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "studies/gbuffer_input.h"
#include "cli/cli.h"
#include "core/progress.h"
#include "raytracer/reference_render.h"
#include "realtime/gtao.h"
#include "scene/scene_loaders.h"

static void print_help(void)
{
    printf("usage: gtlab bench gtao [--scene S] [--threads T] [--repeats R]\n"
           "\n"
           "Measures, on one scene and camera:\n"
           "  talk's configuration  GTAO for a 1920x1080 frame at half resolution (960x540):\n"
           "                        1 direction per pixel, 8 samples per direction (4 per side),\n"
           "                        the 4x4 spatio-temporal pattern, fast acos/sqrt, the 4x4\n"
           "                        bilateral denoiser and the temporal accumulation, per frame\n"
           "                        (averaged over the 24-frame cycle), on 1 and T threads\n"
           "  presets               ns per pixel of one frame of each preset (low .. ultra and the\n"
           "                        brute-force reference) and of the height-field Monte Carlo\n"
           "                        reference at 64 spp, on a 240x136 image of the same view\n"
           "Each figure is the best of R passes (default 3).\n"
           "\n"
           "  --scene S      builtin:NAME or a glTF file (default builtin:menger)\n"
           "  --threads T    threads (default: all cores)\n"
           "  --repeats R    passes per figure (default 3)\n");
}

typedef struct {
    image img;
    ss_gbuffer g;
    camera cam;
} bench_gbuffer;

static int render_gbuffer(const scene *s, int width, int height, int threads, bench_gbuffer *b, gt_error *e)
{
    if (scene_choose_camera(s, NULL, width, height, &b->cam, e) != 0)
        return -1;
    reference_request req = {.quantity = QUANTITY_GBUFFER, .sampling = {.threads = threads}, .normals = NORMAL_SHADING};
    render_stats stats;
    if (reference_render(s, s->name, &b->cam, &req, &b->img, &stats, e) != 0)
        return -1;
    return ss_gbuffer_from_image(&b->img, s->name, approx_ss_camera(&b->cam), &b->g, e);
}

/* Best seconds per frame of p over `repeats` passes. */
static double seconds_per_frame(const bench_gbuffer *b, const gtao_params *p, int repeats, float *ao)
{
    double best = 1e30;
    for (int r = 0; r < repeats; ++r) {
        double t0 = seconds_now();
        gtao_render(&b->g, p, ao, NULL);
        double t = (seconds_now() - t0) / p->frames;
        best = t < best ? t : best;
    }
    return best;
}

static float bench_radius(const camera *cam) { return 0.25f * v3_length(v3_sub(cam->target, cam->position)); }

int bench_gtao(int argc, char **argv)
{
    static const struct option longs[] = {{"scene", required_argument, 0, 's'},
                                          {"threads", required_argument, 0, 't'},
                                          {"repeats", required_argument, 0, 'r'},
                                          {"help", no_argument, 0, 'h'},
                                          {0, 0, 0, 0}};
    const char *spec = "builtin:menger";
    long threads = omp_get_num_procs(), repeats = 3;
    int c;
    while ((c = getopt_long(argc, argv, "h", longs, NULL)) != -1) {
        switch (c) {
        case 's': spec = optarg; break;
        case 't': if (cli_parse_int("--threads", optarg, 1, 1024, &threads)) return EXIT_USER_ERROR; break;
        case 'r': if (cli_parse_int("--repeats", optarg, 1, 100, &repeats)) return EXIT_USER_ERROR; break;
        case 'h': print_help(); return EXIT_OK;
        default: return cli_usage_error("bench gtao");
        }
    }
    gt_error e;
    scene s;
    if (scene_load(spec, &s, &e) != 0)
        return cli_fail(&e);
    bench_gbuffer half = {0}, small = {0};
    int status = EXIT_OK;
    float *ao = malloc(sizeof *ao * 960 * 540);
    if (!ao || render_gbuffer(&s, 960, 540, (int)threads, &half, &e) != 0 ||
        render_gbuffer(&s, 240, 136, (int)threads, &small, &e) != 0) {
        status = ao ? cli_fail(&e) : EXIT_INTERNAL_ERROR;
        goto done;
    }
    gtao_params talk;
    gtao_preset("medium", &talk);
    talk.radius = bench_radius(&half.cam);
    talk.frames = 24;
    char settings[512];
    gtao_params_text(&talk, settings, sizeof settings);
    printf("scene %s; GTAO at 960x540 (1920x1080 at half resolution): %s\n\n", spec, settings);
    printf("%-44s %12s %12s\n", "per frame (GTAO + denoisers)", "1 thread", "threads");
    omp_set_num_threads(1);
    double one = seconds_per_frame(&half, &talk, (int)repeats, ao);
    omp_set_num_threads((int)threads);
    double many = seconds_per_frame(&half, &talk, (int)repeats, ao);
    printf("%-44s %9.2f ms %9.2f ms   (%ld threads)\n\n", "talk's configuration", 1e3 * one, 1e3 * many, threads);

    printf("cost per pixel, one frame on %dx%d, %ld threads:\n", small.g.width, small.g.height, threads);
    double reference_ns = 0, ns[8];
    int count = 0;
    for (int i = 0; gtao_preset_names[i]; ++i, ++count) {
        gtao_params p;
        gtao_preset(gtao_preset_names[i], &p);
        p.radius = bench_radius(&small.cam);
        ns[i] = 1e9 * seconds_per_frame(&small, &p, (int)repeats, ao) / ((double)small.g.width * small.g.height);
        if (strcmp(gtao_preset_names[i], "reference") == 0)
            reference_ns = ns[i];
    }
    for (int i = 0; i < count; ++i)
        printf("  GTAO %-12s %12.1f ns/pixel   %8.4f of the brute-force reference\n", gtao_preset_names[i], ns[i],
               ns[i] / reference_ns);
    reference_request req = {.quantity = QUANTITY_HEIGHTFIELD_AO, .sampling = {.spp = 64, .seed = 1, .threads = (int)threads},
                             .normals = NORMAL_SHADING, .max_distance = INFINITY};
    image hf;
    render_stats stats;
    double t0 = seconds_now();
    if (reference_render(&s, spec, &small.cam, &req, &hf, &stats, &e) != 0) {
        status = cli_fail(&e);
        goto done;
    }
    double hf_ns = 1e9 * (seconds_now() - t0) / ((double)small.g.width * small.g.height);
    image_free(&hf);
    printf("  height-field MC, 64 spp %8.1f ns/pixel   %8.4f of the brute-force reference\n", hf_ns,
           hf_ns / reference_ns);
done:
    free(ao);
    image_free(&half.img);
    image_free(&small.img);
    scene_free(&s);
    return status;
}
