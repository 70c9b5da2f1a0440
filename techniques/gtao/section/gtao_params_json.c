/* GTAO's parameter fit as JSON; see gtao_params_json.h. */
#include "gtao/gtao_params_json.h"

static cJSON *scores_json(const gtao_fit_result *r, int held_out)
{
    cJSON *list = cJSON_CreateArray();
    for (int i = 0; i < r->score_count; ++i) {
        const gtao_fit_score *x = &r->scores[i];
        if (x->held_out != held_out)
            continue;
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "scene", x->scene);
        cJSON_AddNumberToObject(o, "rmse_before", x->rmse_before);
        cJSON_AddNumberToObject(o, "rmse_after", x->rmse_after);
        cJSON_AddNumberToObject(o, "dssim_before", x->dssim_before);
        cJSON_AddNumberToObject(o, "dssim_after", x->dssim_after);
        cJSON_AddItemToArray(list, o);
    }
    return list;
}

cJSON *gtao_fit_json(const gtao_fit_request *rq, const gtao_fit_result *r)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(root, "problem", "gtao-params");
    cJSON_AddStringToObject(root, "preset", rq->preset);
    cJSON_AddStringToObject(root, "objective", gtao_fit_objective_names[rq->objective]);
    cJSON_AddStringToObject(root, "train", rq->train);
    cJSON_AddStringToObject(root, "test", rq->test);
    cJSON *values = cJSON_AddObjectToObject(root, "values"), *errors = cJSON_AddObjectToObject(root, "standard_errors");
    cJSON *starts = cJSON_AddObjectToObject(root, "start");
    for (int k = 0; k < GTAO_FIT_PARAMS; ++k) {
        cJSON_AddNumberToObject(values, gtao_fit_param_names[k], r->value[k]);
        if (r->have_se)
            cJSON_AddNumberToObject(errors, gtao_fit_param_names[k], r->se[k]);
        else
            cJSON_AddNullToObject(errors, gtao_fit_param_names[k]);
        cJSON_AddNumberToObject(starts, gtao_fit_param_names[k], r->start[k]);
    }
    cJSON_AddBoolToObject(root, "converged", r->converged);
    cJSON_AddNumberToObject(root, "iterations", r->iterations);
    cJSON_AddNumberToObject(root, "objective_per_scene", r->objective_per_scene);
    cJSON_AddItemToObject(root, "train_scores", scores_json(r, 0));
    cJSON_AddItemToObject(root, "test_scores", scores_json(r, 1));
    return root;
}
