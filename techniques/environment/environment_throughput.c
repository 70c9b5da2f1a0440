#include "environment/environment_throughput.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "environment/environment_diffuse_integrator.h"
#include "scene/scene_loaders.h"

/* One render of `it`: its samples/s and rays/s, kept when better. */
static int time_render(const gbuffer *gb, const integrator *it, int spp, int threads, double *samples_per_s,
                       double *rays_per_s, gt_error *e)
{
    sampling_settings ss = {.spp = spp, .seed = 1, .threads = threads};
    mc_film film;
    render_stats stats;
    if (render_estimates(gb, it, &ss, &film, &stats, e) != 0)
        return -1;
    mc_film_free(&film);
    *samples_per_s = fmax(*samples_per_s, (double)stats.samples / stats.seconds);
    *rays_per_s = fmax(*rays_per_s, (double)stats.rays / stats.seconds);
    return 0;
}

/* The passes, alternating the two loops so that both see the same machine load. */
static int measure(const embree_scene *es, const gbuffer *gb, const multibounce_settings *settings,
                   const environment_light *light, int repeats, environment_throughput *out, gt_error *e)
{
    multibounce_plan white;
    environment_diffuse_plan lit;
    if (multibounce_plan_init(&white, settings, NORMAL_SHADING, e) != 0 ||
        environment_diffuse_plan_init(&lit, light, settings, NORMAL_SHADING, e) != 0)
        return -1;
    integrator reference = multibounce_integrator(es, &white), environment = environment_diffuse_integrator(es, &lit);
    for (int k = 0; k < repeats; ++k)
        if (time_render(gb, &reference, out->spp, out->threads, &out->multibounce_samples_per_s,
                        &out->multibounce_rays_per_s, e) != 0 ||
            time_render(gb, &environment, out->spp, out->threads, &out->environment_samples_per_s,
                        &out->environment_rays_per_s, e) != 0)
            return -1;
    out->ratio = out->environment_samples_per_s / out->multibounce_samples_per_s;
    return 0;
}

int environment_throughput_run(const scene *s, const camera *cam, const multibounce_settings *settings,
                               const environment_render_settings *environment, int spp, int threads, int repeats,
                               environment_throughput *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->threads = threads;
    out->spp = spp;
    environment_light light;
    if (environment_light_init(&light, environment, e) != 0)
        return -1;
    embree_scene es;
    if (embree_scene_build(s, &es, e) != 0) {
        environment_light_free(&light);
        return -1;
    }
    gbuffer gb;
    int rc = gbuffer_render(&es, cam, NORMAL_SHADING, threads, &gb, e);
    if (rc == 0) {
        rc = measure(&es, &gb, settings, &light, repeats, out, e);
        gbuffer_free(&gb);
    }
    embree_scene_release(&es);
    environment_light_free(&light);
    return rc;
}

static void print_table(FILE *out, const environment_bench_request *rq, const environment_throughput *r)
{
    fprintf(out, "scene %s, %dx%d, %d spp, albedo 0.5, %d bounces, %d threads, best of %d\n", rq->scene, rq->width,
            rq->height, rq->spp, rq->bounces, r->threads, rq->repeats);
    fprintf(out, "environment %s\n\n", rq->environment);
    fprintf(out, "%-34s %14s %14s\n", "", "samples/s", "rays/s");
    fprintf(out, "%-34s %14.4g %14.4g\n", "multibounce (white dome)", r->multibounce_samples_per_s,
            r->multibounce_rays_per_s);
    fprintf(out, "%-34s %14.4g %14.4g\n", "env-diffuse", r->environment_samples_per_s, r->environment_rays_per_s);
    fprintf(out, "\nratio env-diffuse / multibounce samples/s: %.3f (goal >= %g: %s)\n", r->ratio,
            ENVIRONMENT_THROUGHPUT_GOAL, r->ratio >= ENVIRONMENT_THROUGHPUT_GOAL ? "met" : "not met");
}

int environment_throughput_bench(FILE *out, const environment_bench_request *rq, gt_error *e)
{
    multibounce_settings albedo = {.albedo_count = 1, .albedos = {0.5f}, .bounces = rq->bounces};
    environment_render_settings light;
    environment_render_settings_default(&light, NULL); /* the light alone, no request */
    snprintf(light.environment, sizeof light.environment, "%s", rq->environment);
    scene s;
    camera cam;
    if (scene_load(rq->scene, &s, e) != 0)
        return -1;
    environment_throughput r;
    int rc = scene_choose_camera(&s, NULL, rq->width, rq->height, &cam, e);
    if (rc == 0)
        rc = environment_throughput_run(&s, &cam, &albedo, &light, rq->spp, rq->threads, rq->repeats, &r, e);
    scene_free(&s);
    if (rc == 0)
        print_table(out, rq, &r);
    return rc;
}
