/* The sun regime of Decima's sphere light (issue 26, item 9;
 * studies/sphere_light.h, sphere_sun_result). */
#include <math.h>

#include "report/claims_table.h"
#include "report/sphere_light_section_parts.h"

static void sun_json(const sphere_sun_result *s, cJSON *json)
{
    cJSON_AddNumberToObject(json, "configurations", s->configurations);
    cJSON_AddNumberToObject(json, "samples", s->samples);
    cJSON_AddNumberToObject(json, "noh_shortfall_karis", s->shortfall_karis);
    cJSON_AddNumberToObject(json, "noh_shortfall_one_step", s->shortfall_step);
    cJSON_AddNumberToObject(json, "noh_shortfall_gain", s->shortfall_gain);
    cJSON_AddNumberToObject(json, "noh_shortfall_gain_stderr", s->shortfall_gain_se);
    cJSON_AddNumberToObject(json, "mean_abs_residual_karis_point", s->abs_karis);
    cJSON_AddNumberToObject(json, "mean_abs_residual_one_step", s->abs_step);
    cJSON_AddNumberToObject(json, "residual_gain", s->gain);
    cJSON_AddNumberToObject(json, "residual_gain_stderr", s->gain_se);
}

void sphere_sun_section(report_context *ctx, const sphere_sun_result *s, cJSON *summary)
{
    report_heading(ctx->doc, 3, "The sun at grazing angles");
    report_paragraph(ctx->doc,
                     "The talk shows \"the sun's reflection with and without the N.H maximization\". %d "
                     "configurations of a sun-sized disc (0.27 degrees) seen at grazing angles (n.v 0.02 to 0.3), "
                     "its centre 1 to 4 angular radii from the mirror direction, roughness 0.05 to 0.3; references of "
                     "%u MIS samples. (N.H)^2 below the rim's maximum: %.2e +- %.1e at Karis's point, %.2e +- %.1e "
                     "after the talk's Newton step (a gain of %.2e +- %.1e, paired). Decima's radiance, mean "
                     "|residual| as in the fit: %.3f +- %.3f with Karis's point, %.3f +- %.3f with the step (a gain "
                     "of %.3f +- %.3f, paired). Where R falls inside the disc both return exactly 1 (tested).",
                     s->configurations, s->samples, s->shortfall_karis, s->shortfall_karis_se, s->shortfall_step,
                     s->shortfall_step_se, s->shortfall_gain, s->shortfall_gain_se, s->abs_karis, s->abs_karis_se,
                     s->abs_step, s->abs_step_se, s->gain, s->gain_se);
    sun_json(s, cJSON_AddObjectToObject(summary, "sun"));
    claims_table_add_unreviewed_figure(ctx->claims, "de Carpentier 2017 (Decima), GGX spherical area light",
                            "the N.H maximisation improves the sun's reflection (shown at low angles)",
                            "mean absolute radiance residual with Karis's point minus with the talk's Newton step, "
                            "sun-sized disc at grazing views, paired over configurations; holds above 0",
                            s->gain, s->gain_se, 0.0, INFINITY);
}
