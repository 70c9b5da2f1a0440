/* The GTAO parameter fit on a folder of AO references; see gtao_params.h. */
#include "gtao/gtao_params.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/reference_schema.h"
#include "gtao/gtao.h"
#include "project/gbuffer_input.h"

/* The references of one list of scenes, loaded. */
typedef struct {
    int count;
    char names[GTAO_FIT_MAX_SCENES][64];
    approx_input in[GTAO_FIT_MAX_SCENES];
    gtao_fit_scene scenes[GTAO_FIT_MAX_SCENES];
} loaded_scenes;

/* <dir>/<name>.exr as a scene of the fit. */
static int load_scene(const char *dir, const char *name, loaded_scenes *l, gt_error *e)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.exr", dir, name);
    approx_input *in = &l->in[l->count];
    if (approx_load(path, NULL, in, e) != 0)
        return -1;
    ++l->count;
    const float *ao = image_channel_data(&in->img, CH_AO);
    if (!ao)
        return gt_error_set(e, path, "not an AO reference: no ao.V");
    snprintf(l->names[l->count - 1], sizeof l->names[0], "%s", name);
    l->scenes[l->count - 1] = (gtao_fit_scene){l->names[l->count - 1], &in->g, ao,
                                               v3_length(v3_sub(in->cam.target, in->cam.position))};
    return 0;
}

/* Every scene of the comma-separated list. */
static int load_scenes(const char *dir, const char *list, loaded_scenes *l, gt_error *e)
{
    char copy[1024];
    snprintf(copy, sizeof copy, "%s", list);
    l->count = 0;
    for (char *tok = strtok(copy, ","); tok; tok = strtok(NULL, ",")) {
        if (l->count == GTAO_FIT_MAX_SCENES)
            return gt_error_set(e, list, "at most %d scenes", GTAO_FIT_MAX_SCENES);
        if (load_scene(dir, tok, l, e) != 0)
            return -1;
    }
    return l->count ? 0 : gt_error_set(e, list, "no scene named");
}

static void free_scenes(loaded_scenes *l)
{
    for (int i = 0; i < l->count; ++i)
        approx_input_free(&l->in[i]);
    l->count = 0;
}

int gtao_params_study(const gtao_fit_request *rq, gtao_fit_result *out, gt_error *e)
{
    gtao_params unused;
    if (gtao_preset(rq->preset, &unused) != 0) /* before any file is read */
        return gt_error_set(e, "--preset", "unknown preset '%s'", rq->preset);
    static loaded_scenes train, test;
    int rc = -1;
    if (load_scenes(rq->refs_dir, rq->train, &train, e) == 0 && load_scenes(rq->refs_dir, rq->test, &test, e) == 0) {
        gtao_fit_problem problem = {train.scenes, train.count, test.scenes, test.count, rq->preset, rq->objective};
        rc = gtao_params_fit(&problem, out, e);
    }
    free_scenes(&train);
    free_scenes(&test);
    return rc;
}

void gtao_params_print(FILE *f, const gtao_fit_request *rq, const gtao_fit_result *r)
{
    fprintf(f, "gtao-params (%s preset, %s objective): %s after %d iterations\n", rq->preset,
            gtao_fit_objective_names[rq->objective], r->converged ? "converged" : "not converged", r->iterations);
    for (int k = 0; k < GTAO_FIT_PARAMS; ++k)
        fprintf(f, "  %-28s %.4f +- %.4f (start %.4f)\n", gtao_fit_param_names[k], r->value[k],
                r->have_se ? r->se[k] : NAN, r->start[k]);
    for (int held_out = 0; held_out <= 1; ++held_out) {
        fprintf(f, "%s scenes:\n", held_out ? "held-out" : "training");
        for (int i = 0; i < r->score_count; ++i)
            if (r->scores[i].held_out == held_out)
                fprintf(f, "  %-16s RMSE %.4f -> %.4f   DSSIM %.4f -> %.4f\n", r->scores[i].scene,
                        r->scores[i].rmse_before, r->scores[i].rmse_after, r->scores[i].dssim_before,
                        r->scores[i].dssim_after);
    }
}
