/* The sun regime of Decima's sphere light (issue 26, item 9;
 * sphere_light/sphere_light_study.h, sphere_sun_result). */

#include "report/claim_thresholds.h"
#include "report/claims_table.h"
#include "sphere_light/sphere_light_section_parts.h"

static const claim_record kSun = {
    .talk = "de Carpentier & Ishiyama 2017 (Decima)", .seed = "000", .section = "GGX spherical area light",
    .quote = "here you see the sun's reflection with and without the N.H maximization. And as you can see, it works "
             "quite nicely, as it gets you a more natural looking reflection at low angles.",
    .setting = "the sun's reflection in Horizon Zero Dawn (screenshots, 1080p) seen at low angles: a sun-sized "
               "spherical light on smooth to moderately rough GGX surfaces, Karis's point against one Newton step",
    .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "per-pixel radiance of configurations drawn from that regime (a 0.27 degree disc, n.v 0.02 to "
                    "0.3, roughness 0.05 to 0.3, the disc's centre 1 to 4 radii from the mirror direction) instead "
                    "of screenshots: the claim is about each pixel's shading, which does not depend on the image's "
                    "resolution",
    .reading = "with the talk's Newton step Decima's radiance is visibly closer to the Monte Carlo reference than with "
               "Karis's point, on the sun at grazing angles (mean |log error|, paired over configurations)",
    .form = CLAIM_BETTER, .margin = CLAIM_WEBER_FRACTION,
    .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = "the talk's comparison (with against without the maximization), by more than a 1% change of "
                 "luminance (CLAIM_WEBER_FRACTION)"};

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
    claims_table_add(ctx->claims, &kSun, -s->gain, s->gain_se,
                     "mean |ln((model + 0.01)/(reference + 0.01))| with the Newton step minus with Karis's point, "
                     "paired over %d configurations of the sun at grazing views", s->configurations);
}
