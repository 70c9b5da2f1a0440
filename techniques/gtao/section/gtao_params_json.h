/* GTAO's parameter fit (gtao_params.h) as JSON: the format of the
 * output of `gtlab fit gtao-params` and of the GTAO section's
 * gtao/params_fit.json. */
#ifndef GTLAB_GTAO_GTAO_PARAMS_JSON_H
#define GTLAB_GTAO_GTAO_PARAMS_JSON_H

#include <cjson/cJSON.h>

#include "gtao/gtao_params.h"

/* The fit as JSON: request, values, standard errors, start, scores. */
cJSON *gtao_fit_json(const gtao_fit_request *rq, const gtao_fit_result *r);

#endif
