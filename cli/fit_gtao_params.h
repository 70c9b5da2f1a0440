/* `gtlab fit gtao-params` (studies/gtao_params.h) and its result as JSON,
 * the format of its output file and of the `gtao` stage's params_fit.json. */
#ifndef GTLAB_CLI_FIT_GTAO_PARAMS_H
#define GTLAB_CLI_FIT_GTAO_PARAMS_H

#include <cjson/cJSON.h>

#include "studies/gtao_params.h"

/* The fit as JSON: request, values, standard errors, start, scores. */
cJSON *gtao_fit_json(const gtao_fit_request *rq, const gtao_fit_result *r);

#endif
