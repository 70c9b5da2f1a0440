/* gtlab fit gtao-params: GTAO's world radius (as a fraction of the camera's
 * distance to its target), falloff and thickness fitted to a folder of 3-D
 * ray-traced AO references (studies/gtao_params.h, fitters/gtao_params_fit.h),
 * scored before and after on held-out scenes; printed and written as JSON. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "report/gtao_params_json.h"
#include "core/atomic_file.h"

static const char *objective_name(int i) { return gtao_fit_objective_names[i]; }

static const cli_option options[] = {
    CLI_REQUIRED_STRING("refs", "DIR", "folder of AO references <scene>.exr with their G-buffer and\n"
                        "camera (e.g. the ao/ folder 'gtlab all' writes)"),
    CLI_STRING("train", "LIST", "scenes to fit on, comma-separated"),
    CLI_STRING("test", "LIST", "held-out scenes"),
    CLI_STRING("preset", "P", "GTAO preset"),
    CLI_CHOICE("objective", "O", objective_name, 2, "dssim (the sum over scenes of each scene's mean\n"
               "DSSIM) or rmse (per-pixel least squares)"),
    CLI_OUTPUT("F", 1, "fit JSON: values, standard errors, scores before and after"), CLI_END};
static const cli_command command = {
    "fit gtao-params",
    "Fits GTAO's radius (a fraction of each camera's distance to its target), falloff\n"
    "and thickness so GTAO matches 3-D ray-traced AO references (Ceres, over the\n"
    "training scenes, each scene's residuals weighted equally; derivatives by finite\n"
    "differences of 0.01 in each parameter), and reports RMSE and DSSIM before and\n"
    "after on the training and the held-out scenes.",
    options, NULL, NULL};

static void print_fit(const gtao_fit_request *rq, const gtao_fit_result *r)
{
    printf("gtao-params (%s preset, %s objective): %s after %d iterations\n", rq->preset,
           gtao_fit_objective_names[rq->objective], r->converged ? "converged" : "not converged", r->iterations);
    for (int k = 0; k < GTAO_FIT_PARAMS; ++k)
        printf("  %-28s %.4f +- %.4f (start %.4f)\n", gtao_fit_param_names[k], r->value[k],
               r->have_se ? r->se[k] : NAN, r->start[k]);
    for (int held_out = 0; held_out <= 1; ++held_out) {
        printf("%s scenes:\n", held_out ? "held-out" : "training");
        for (int i = 0; i < r->score_count; ++i)
            if (r->scores[i].held_out == held_out)
                printf("  %-16s RMSE %.4f -> %.4f   DSSIM %.4f -> %.4f\n", r->scores[i].scene, r->scores[i].rmse_before,
                       r->scores[i].rmse_after, r->scores[i].dssim_before, r->scores[i].dssim_after);
    }
}

int fit_gtao_params(int argc, char **argv)
{
    gtao_fit_request rq = {NULL, GTAO_FIT_DEFAULT_TRAIN, GTAO_FIT_DEFAULT_TEST, GTAO_FIT_DEFAULT_PRESET, GTAO_FIT_DSSIM};
    const char *output = NULL;
    int status;
    if (cli_options_parse(&command, (void *[]){&rq.refs_dir, &rq.train, &rq.test, &rq.preset, &rq.objective, &output},
                          argc, argv, &status) != 0)
        return status;
    gt_error e;
    static gtao_fit_result r;
    if (gtao_params_study(&rq, &r, &e) != 0)
        return cli_fail(&e);
    print_fit(&rq, &r);
    cJSON *root = gtao_fit_json(&rq, &r);
    char *text = cJSON_Print(root);
    status = text && atomic_write_text(output, text, &e) == 0 ? EXIT_OK : cli_fail(&e);
    free(text);
    cJSON_Delete(root);
    return status;
}
