/* RMSE against wall time, plain and with the height-field control variate;
 * see ao_convergence.h. */
#include "ao/ao_convergence.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/progress.h"
#include "core/reference_schema.h"
#include "ao/ao_quantity.h"
#include "project/scene_list.h"

enum { SERIES_SEED = 1, REFERENCE_SEED = 7 };

ao_convergence_request ao_convergence_default_request(int threads)
{
    ao_convergence_request rq = {48, 48, threads, 16384, 4096, 0.01};
    return rq;
}

static int render_ao(const scene *s, const camera *cam, ao_control_variate cv, int spp, uint32_t seed, int threads,
                     image *out, double *seconds, gt_error *e)
{
    ao_render_settings ao = ao_render_settings_defaults();
    ao.control_variate = cv;
    reference_request req = {.quantity = QUANTITY_AO, .sampling = {.spp = spp, .seed = seed, .threads = threads},
                             .normals = NORMAL_SHADING, .settings = &ao.header};
    render_stats stats;
    double start = seconds_now();
    int rc = reference_render(s, s->name, cam, &req, out, &stats, e);
    *seconds = seconds_now() - start;
    return rc;
}

/* RMSE of ao.V against the reference over covered pixels. */
static double rmse_against(const image *img, const image *ref)
{
    const float *mask = image_channel_data(ref, CH_MASK), *r = image_channel_data(ref, CH_AO);
    const float *v = image_channel_data(img, CH_AO);
    double sum = 0.0;
    long n = 0;
    for (size_t i = 0; i < image_pixel_count(ref); ++i)
        if (mask[i] != 0.0f) {
            double d = (double)v[i] - r[i];
            sum += d * d, ++n;
        }
    return n ? sqrt(sum / n) : 0.0;
}

/* log-log interpolation of the time at which the RMSE crosses the target. */
static void time_to_target(const convergence_point *p, int count, double target, double *t, target_kind *kind)
{
    if (p[0].rmse <= target) {
        *t = p[0].seconds, *kind = TARGET_AT_FIRST;
        return;
    }
    for (int i = 1; i < count; ++i)
        if (p[i].rmse <= target) {
            double a = log(p[i - 1].rmse), b = log(p[i].rmse), f = b < a ? (a - log(target)) / (a - b) : 1.0;
            *t = exp(log(p[i - 1].seconds) + f * (log(p[i].seconds) - log(p[i - 1].seconds)));
            *kind = TARGET_INTERPOLATED;
            return;
        }
    const convergence_point *last = &p[count - 1];
    *t = last->seconds * (last->rmse / target) * (last->rmse / target);
    *kind = TARGET_EXTRAPOLATED;
}

static int run_series(const scene *s, const camera *cam, const image *ref, const ao_convergence_request *rq,
                      convergence_mode mode, ao_convergence_scene *out, gt_error *e)
{
    ao_control_variate cv = mode == CONVERGENCE_CV ? AO_CONTROL_VARIATE_HEIGHTFIELD : AO_CONTROL_VARIATE_NONE;
    int count = 0;
    for (int spp = AO_CONVERGENCE_FIRST_SPP; spp <= rq->max_spp && count < AO_CONVERGENCE_MAX_POINTS; spp *= 2) {
        convergence_point *p = &out->points[mode][count++];
        p->spp = spp;
        p->seconds = INFINITY;
        for (int pass = 0; pass < AO_CONVERGENCE_PASSES; ++pass) { /* the same bits each pass */
            image img;
            double seconds;
            if (render_ao(s, cam, cv, spp, SERIES_SEED, rq->threads, &img, &seconds, e) != 0)
                return -1;
            p->seconds = fmin(p->seconds, seconds);
            p->rmse = rmse_against(&img, ref);
            image_free(&img);
        }
        fprintf(stderr, "  %-16s %-5s %5d spp  %7.3f s  RMSE %.5f\n", out->scene, mode ? "cv" : "plain", spp,
                p->seconds, p->rmse);
        if (p->rmse < 0.5 * rq->target)
            break;
    }
    out->count[mode] = count;
    time_to_target(out->points[mode], count, rq->target, &out->time_to_target[mode], &out->kind[mode]);
    return 0;
}

static int measure_scene(const study_scene_entry *entry, const ao_convergence_request *rq, ao_convergence_scene *out,
                         gt_error *e)
{
    snprintf(out->scene, sizeof out->scene, "%s", entry->label);
    scene s;
    camera cam;
    if (study_scene_view(entry, rq->width, rq->height, &s, &cam, e) != 0)
        return -1;
    image ref;
    int rc = render_ao(&s, &cam, AO_CONTROL_VARIATE_HEIGHTFIELD, rq->reference_spp, REFERENCE_SEED, rq->threads, &ref,
                       &out->reference_seconds, e);
    if (rc == 0) {
        for (int mode = 0; mode < CONVERGENCE_MODES && rc == 0; ++mode)
            rc = run_series(&s, &cam, &ref, rq, (convergence_mode)mode, out, e);
        image_free(&ref);
    }
    scene_free(&s);
    out->speedup = out->time_to_target[CONVERGENCE_PLAIN] / out->time_to_target[CONVERGENCE_CV];
    return rc;
}

int ao_convergence_run(const ao_convergence_request *rq, ao_convergence_result *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    out->request = *rq;
    const int count = study_scene_count(NULL); /* the built-in study scenes */
    out->scene_count = count < AO_CONVERGENCE_MAX_SCENES ? count : AO_CONVERGENCE_MAX_SCENES;
    for (int i = 0; i < out->scene_count; ++i)
        if (measure_scene(study_scene_at(NULL, i), rq, &out->scenes[i], e) != 0)
            return -1;
    return 0;
}
