/* LTC sphere lights beside Karis and Decima (issue 27, item 2;
 * sphere_light/sphere_light_study.h, sphere_ltc_result). */
#include <math.h>
#include <string.h>

#include "ltc/ltc_sphere.h"
#include "report/claim_thresholds.h"
#include "sphere_light/sphere_light_section_parts.h"

static void ltc_json(const sphere_light_result *r, cJSON *json)
{
    const sphere_ltc_result *l = &r->ltc;
    cJSON_AddNumberToObject(json, "table_size", l->table_size);
    cJSON_AddNumberToObject(json, "fit_seconds", l->fit_seconds);
    cJSON_AddNumberToObject(json, "mean_fit_error_total_variation", l->mean_fit_error);
    cJSON_AddNumberToObject(json, "max_fit_error_total_variation", l->max_fit_error);
    cJSON_AddNumberToObject(json, "held_out_mean_abs_log_error", l->held_out.mean_abs);
    cJSON_AddNumberToObject(json, "held_out_mean_abs_log_error_stderr", l->held_out.mean_abs_stderr);
    cJSON_AddNumberToObject(json, "held_out_rms_log_error", l->held_out.rms);
    cJSON *paired = cJSON_AddObjectToObject(json, "paired_gain_over");
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m) {
        cJSON *row = cJSON_AddObjectToObject(paired, r->fit.held_out[m].key);
        cJSON_AddNumberToObject(row, "mean", l->paired[m]);
        cJSON_AddNumberToObject(row, "stderr", l->paired_se[m]);
    }
    cJSON_AddNumberToObject(json, "ngon_sides", LTC_SPHERE_SIDES);
    cJSON_AddNumberToObject(json, "ngon_mean_abs_log_error", l->ngon_mean);
    cJSON_AddNumberToObject(json, "ngon_max_abs_log_error", l->ngon_max);
    cJSON_AddNumberToObject(json, "ns_per_pixel_karis", r->cost.ns_karis_full);
    cJSON_AddNumberToObject(json, "ns_per_pixel_decima", r->cost.ns_decima_full);
    cJSON_AddNumberToObject(json, "ns_per_pixel_ltc", r->cost.ns_ltc);
}

/* The paired gains as one sentence. */
static void paired_paragraph(report *doc, const sphere_light_result *r)
{
    const sphere_ltc_result *l = &r->ltc;
    report_paragraph(doc,
                     "Held out (the refit's %d configurations): LTC mean |log error| %.4f +- %.4f (RMS %.4f). Paired "
                     "over the configurations, another method's |log error| minus the LTC's (positive: the LTC is "
                     "closer): Karis %+.4f +- %.4f, Decima as published %+.4f +- %.4f, Decima refit %+.4f +- %.4f.",
                     r->fit_settings.test, l->held_out.mean_abs, l->held_out.mean_abs_stderr, l->held_out.rms,
                     l->paired[SPHERE_FIT_KARIS], l->paired_se[SPHERE_FIT_KARIS], l->paired[SPHERE_FIT_PUBLISHED],
                     l->paired_se[SPHERE_FIT_PUBLISHED], l->paired[SPHERE_FIT_REFIT], l->paired_se[SPHERE_FIT_REFIT]);
}

void sphere_ltc_section(report_context *ctx, const sphere_light_result *r, cJSON *summary)
{
    const sphere_ltc_result *l = &r->ltc;
    report *doc = ctx->doc;
    report_heading(doc, 3, "LTC sphere lights (Heitz et al. 2016; Heitz & Hill 2017)");
    report_paragraph(doc,
                     "gtlab fits the GGX LTC table itself (techniques/ltc/ltc_fit.h: Ceres, L2 distance to f_r (n.l) / E on "
                     "a fixed multiple-importance direction grid, warm-started along each row): %dx%d texels in "
                     "%.1f s; total-variation distance between the LTC and the normalised BRDF lobe per texel, mean "
                     "%.3f, worst %.3f (at grazing views). The sphere is the disk facing the shading point that "
                     "subtends its cap, integrated as an equal-area %d-gon through the clipped polygon integral; "
                     "its own error against a 1024-gon (the exact disk) on the held-out configurations, "
                     "|ln((8-gon + 0.01)/(exact + 0.01))|: mean %.2e, worst %.2e. Specular with the table's Fresnel term (F0 E + (1 - F0) B); the maps and scenes "
                     "above carry it as the column 'LTC'.",
                     l->table_size, l->table_size, l->fit_seconds, l->mean_fit_error, l->max_fit_error,
                     LTC_SPHERE_SIDES, l->ngon_mean, l->ngon_max);
    paired_paragraph(doc, r);
    report_paragraph(doc,
                     "Cost of the whole specular per pixel (C, one thread, configurations of the realistic "
                     "distribution): Karis %.1f ns, Decima %.1f ns, LTC %.1f ns.",
                     r->cost.ns_karis_full, r->cost.ns_decima_full, r->cost.ns_ltc);
    report_finding(doc, "LTC sphere lights",
                   "held-out mean |log error| %.3f (Karis %.3f, Decima %.3f, refit %.3f); %.0f ns per pixel against "
                   "Decima's %.0f.",
                   l->held_out.mean_abs, r->fit.held_out[SPHERE_FIT_KARIS].errors.mean_abs,
                   r->fit.held_out[SPHERE_FIT_PUBLISHED].errors.mean_abs,
                   r->fit.held_out[SPHERE_FIT_REFIT].errors.mean_abs, r->cost.ns_ltc, r->cost.ns_decima_full);
    ltc_json(r, cJSON_AddObjectToObject(summary, "ltc"));
}

/* |residual of a| - |residual of b| paired over the held-out
 * configurations, with its standard error; index SPHERE_FIT_MODELS is the LTC. */
static void paired_gap(const sphere_light_result *r, int a, int b, double *d, double *se)
{
    if (a < SPHERE_FIT_MODELS && b < SPHERE_FIT_MODELS)
        *d = r->fit.paired_abs[a][b], *se = r->fit.paired_abs_se[a][b];
    else if (a == SPHERE_FIT_MODELS)
        *d = -r->ltc.paired[b], *se = r->ltc.paired_se[b];
    else
        *d = r->ltc.paired[a], *se = r->ltc.paired_se[a];
}

static int label_index(const char *const *labels, int count, const char *label)
{
    for (int m = 0; m < count; ++m)
        if (!strcmp(labels[m], label))
            return m;
    return 0;
}

void sphere_ltc_headline(report *doc, const sphere_light_result *r)
{
    enum { METHODS = SPHERE_FIT_MODELS + 1 };
    const char *labels[METHODS];
    double errors[METHODS], d, se;
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m)
        labels[m] = r->fit.held_out[m].method, errors[m] = r->fit.held_out[m].errors.mean_abs;
    labels[SPHERE_FIT_MODELS] = "LTC", errors[SPHERE_FIT_MODELS] = r->ltc.held_out.mean_abs;
    report_headline h = {.topic = "GGX sphere lights", .measure = "held-out mean |log error|",
                         .significance = HEADLINE_NOT_COMPUTED, .margin = CLAIM_WEBER_FRACTION};
    if (headline_rank(&h, METHODS, labels, errors) != 0)
        return;
    paired_gap(r, label_index(labels, METHODS, h.runner_up), label_index(labels, METHODS, h.best), &d, &se);
    char over[64];
    snprintf(over, sizeof over, "paired over %d held-out configurations", r->fit_settings.test);
    headline_from_paired_cases(&h, d, se, r->fit_settings.test, over);
    report_add_headline(doc, &h);
}
