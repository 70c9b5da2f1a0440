/* Decima's sphere light near the terminator (issue 26, item 8;
 * sphere_light/sphere_light_study.h, sphere_terminator_result). */

#include "report/claims_table.h"
#include "sphere_light/sphere_light_section_parts.h"

static const claim_record kTerminator = {
    .talk = "de Carpentier & Ishiyama 2017 (Decima)", .seed = "000", .section = "Appendix: Spherical Area Lighting",
    .quote = "This leads to zero intensity when the CENTER of the area light is on the horizon, which strictly "
             "speaking isn't correct, but it does prevent shadow acne at the terminator, which is more important to us.",
    .setting = "the appendix's EvaluateSphericalAreaGGX(): N.L of the light's centre, unadjusted for its size, "
               "where a sphere light's cap straddles a shaded surface's horizon (the terminator), in shadowed scenes",
    .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "unshadowed configurations with the cap straddling the horizon (elevation within one angular "
                    "radius): the concession is about each pixel's value near the terminator, not the image; the "
                    "acne it prevents needs a shadow map and is not measured",
    .reading = "a concession: how far the published form falls below the reference where the light's cap straddles "
               "the horizon (mean log error; negative: too dark), measured without a verdict",
    .form = CLAIM_ASSUMPTION};

static void terminator_json(const sphere_terminator_result *t, cJSON *json)
{
    cJSON_AddNumberToObject(json, "configurations", t->configurations);
    cJSON_AddNumberToObject(json, "samples", t->samples);
    cJSON_AddNumberToObject(json, "share_centre_below", t->share_centre_below);
    cJSON_AddNumberToObject(json, "talk_mean_residual", t->talk_signed);
    cJSON_AddNumberToObject(json, "talk_mean_residual_stderr", t->talk_signed_se);
    cJSON_AddNumberToObject(json, "talk_mean_abs_residual", t->talk_abs);
    cJSON_AddNumberToObject(json, "talk_mean_abs_residual_stderr", t->talk_abs_se);
    cJSON_AddNumberToObject(json, "mended_mean_abs_residual", t->fixed_abs);
    cJSON_AddNumberToObject(json, "mended_mean_abs_residual_stderr", t->fixed_abs_se);
    cJSON_AddNumberToObject(json, "gain", t->gain);
    cJSON_AddNumberToObject(json, "gain_stderr", t->gain_se);
    cJSON_AddNumberToObject(json, "talk_above_mean_abs_residual", t->above_abs);
    cJSON_AddNumberToObject(json, "talk_above_mean_abs_residual_stderr", t->above_abs_se);
}

void sphere_terminator_section(report_context *ctx, const sphere_terminator_result *t, cJSON *summary)
{
    report_heading(ctx->doc, 3, "Near the terminator");
    report_paragraph(ctx->doc,
                     "The talk: \"N.L is not adjusted ... zero intensity when the centre of the area light is on the "
                     "horizon\". %d configurations with the light's centre where its cap straddles the horizon "
                     "(elevation uniform in [-sigma, sigma], %.0f%% of them with the centre below it, where the "
                     "published form returns 0), on the reflection's side, references of %u MIS samples; residual "
                     "ln((model + 0.01)/(reference + 0.01)) as in the fit. Published Decima: mean residual %+.3f +- "
                     "%.3f (negative: too dark), mean |residual| %.3f +- %.3f, against %.3f +- %.3f just above the "
                     "band (elevation sigma to 3 sigma). Mended (not the talk's: saturate(N.L) replaced by the cap's "
                     "horizon-clipped form factor, Frostbite's illuminanceSphereOrDisk / (pi sin^2 sigma), the "
                     "talk's value wherever the whole cap is above the horizon): mean |residual| %.3f +- %.3f, a "
                     "gain of %.3f +- %.3f paired over the configurations. The talk keeps the error on purpose: it \"does prevent "
                     "shadow acne at the terminator, which is more important to us\"; acne needs a shadow map, which "
                     "these unshadowed configurations do not have, so that side of the trade is not measured here.",
                     t->configurations, 100.0 * t->share_centre_below, t->samples, t->talk_signed, t->talk_signed_se,
                     t->talk_abs, t->talk_abs_se, t->above_abs, t->above_abs_se, t->fixed_abs, t->fixed_abs_se, t->gain,
                     t->gain_se);
    terminator_json(t, cJSON_AddObjectToObject(summary, "terminator"));
    claims_table_add(ctx->claims, &kTerminator, t->talk_signed, t->talk_signed_se,
                     "mean ln((approx + 0.01)/(reference + 0.01)) of the published form over %d lights whose cap "
                     "straddles the horizon (negative: too dark; mean |residual| %.3f, %.3f just above the band)",
                     t->configurations, t->talk_abs, t->above_abs);
}
