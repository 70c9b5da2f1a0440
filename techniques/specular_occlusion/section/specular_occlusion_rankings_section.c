/* The rankings the GTSO talk states, with their significance (issue 26,
 * items 2 and 3): each a paired difference over the scenes
 * (specular_occlusion/specular_occlusion_study.h, so_rankings), a row of a table, of
 * summary.json and of the claims table. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>

#include "specular_occlusion/specular_occlusion_section_parts.h"

#define CONE "cone/cone (exact caps, cos a_s = 2^(-3.32193 alpha^2))"

/* One line of the table: what is compared, where, and the difference in
 * each setting (the offset of the so_paired_difference in so_ranking_setting). */
typedef struct {
    const char *key, *comparison, *scope;
    size_t offset;
} ranking_line;

static const so_paired_difference *difference(const so_ranking_setting *s, const ranking_line *l)
{
    return (const so_paired_difference *)((const char *)s + l->offset);
}

static const char *significance(const so_paired_difference *d)
{
    if (isnan(d->standard_error))
        return "too few scenes";
    return fabs(d->mean) > CLAIM_Z * d->standard_error ? "significant" : "not significant";
}

static void add_line(report *doc, cJSON *json, const so_rankings *k, const ranking_line *l)
{
    char text[SO_SETTINGS][48];
    const char *cells[2 + 2 * SO_SETTINGS] = {l->comparison, l->scope};
    cJSON *o = cJSON_AddObjectToObject(json, l->key);
    for (int i = 0; i < SO_SETTINGS; ++i) {
        const so_paired_difference *d = difference(&k->settings[i], l);
        snprintf(text[i], sizeof text[i], "%+.5f +- %.5f", d->mean, d->standard_error);
        cells[2 + 2 * i] = text[i], cells[3 + 2 * i] = significance(d);
        cJSON *setting = cJSON_AddObjectToObject(o, k->settings[i].name);
        cJSON_AddNumberToObject(setting, "mean", d->mean);
        cJSON_AddNumberToObject(setting, "standard_error", d->standard_error);
        cJSON_AddNumberToObject(setting, "scenes", d->cases);
    }
    report_table_row(doc, cells);
}

#define AT(field) offsetof(so_ranking_setting, field)

static void rankings_table(report *doc, const so_rankings *k, cJSON *json)
{
    static const char *const headers[6] = {"a minus b", "where", "talk's setting (Phong)", "at 95%", "GTSO (GGX f_r)",
                                           "at 95%"};
    static const ranking_line lines[] = {
        {"cone_minus_ao", "cone/cone - AO as V_s", "DSSIM, all pixels", AT(cone_minus_ao)},
        {"cone_minus_lagarde", "cone/cone - Lagarde 2014", "DSSIM, all pixels", AT(cone_minus_lagarde)},
        {"lobe_minus_cone_silhouette", "cone/lobe LUT 32^3 - cone/cone", "DSSIM, silhouette",
         AT(lobe_minus_cone[SO_REGION_SILHOUETTE])},
        {"lobe_minus_cone_interior", "cone/lobe LUT 32^3 - cone/cone", "DSSIM, interior",
         AT(lobe_minus_cone[SO_REGION_INTERIOR])},
        {"lobe_minus_cone_bias_silhouette", "cone/lobe LUT 32^3 - cone/cone", "signed error, silhouette",
         AT(lobe_minus_cone_bias[SO_REGION_SILHOUETTE])},
        {"lobe_minus_cone_bias_interior", "cone/lobe LUT 32^3 - cone/cone", "signed error, interior",
         AT(lobe_minus_cone_bias[SO_REGION_INTERIOR])},
        {"talk_minus_drobot_r025", "talk's cone - Drobot 2014", "DSSIM at r = 0.25 (Phong p = 510)",
         AT(talk_minus_drobot[0])},
        {"talk_minus_drobot_r05", "talk's cone - Drobot 2014", "DSSIM at r = 0.5 (p = 30)", AT(talk_minus_drobot[1])},
        {"talk_minus_drobot_r08", "talk's cone - Drobot 2014", "DSSIM at r = 0.8 (p = 2.9)", AT(talk_minus_drobot[2])},
    };
    report_table_begin(doc, 6, headers);
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; ++i)
        add_line(doc, json, k, &lines[i]);
    report_table_end(doc);
}

/* The talk's comparisons, each "a matches the reference more closely than
 * b" past a visible margin: the talk's own comparison, on its Phong setting,
 * in gtlab's scenes. */
#define SO_CLOSER_QUOTE "Note that while not perfect, the cone/cone intersection technique more closely matches our reference."
#define SO_SILHOUETTE_QUOTE                                                                                           \
    "Note how it substantially improves on the overdarkening that we were getting near the silhouette of the "     \
    "character."
#define SO_DROBOT_QUOTE                                                                                               \
    "We found our approach to be very similar to [Drobot2014c], but more accurate for smaller gloss values"
#define SO_DSSIM_MARGIN "the DSSIM of a just noticeable difference (CLAIM_DSSIM_JUST_NOTICEABLE, SSIM 0.95)"

static const claim_record kConeOverAo = {
    .talk = SO_TALK, .seed = "001", .section = "Final Specular Visibility Calculation", .quote = SO_CLOSER_QUOTE,
    .setting = SO_SETTING, .setting_match = CLAIM_SETTING_GTLAB, .setting_note = SO_SETTING_NOTE,
    .reading = "cone/cone's V_s is closer (DSSIM) to the Phong reference than AO used as V_s, by a visible margin.",
    .form = CLAIM_BETTER, .margin = CLAIM_DSSIM_JUST_NOTICEABLE, .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = SO_DSSIM_MARGIN};

static const claim_record kConeOverLagarde = {
    .talk = SO_TALK, .seed = "001", .section = "Final Specular Visibility Calculation", .quote = SO_CLOSER_QUOTE,
    .setting = SO_SETTING, .setting_match = CLAIM_SETTING_GTLAB, .setting_note = SO_SETTING_NOTE,
    .reading = "cone/cone's V_s is closer (DSSIM) to the Phong reference than Lagarde 2014's, by a visible margin.",
    .form = CLAIM_BETTER, .margin = CLAIM_DSSIM_JUST_NOTICEABLE, .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = SO_DSSIM_MARGIN};

static const claim_record kLobeSilhouette = {
    .talk = SO_TALK, .seed = "001", .section = "Intersection with Accurate Reflection Lobes",
    .quote = SO_SILHOUETTE_QUOTE, .setting = SO_SETTING, .setting_match = CLAIM_SETTING_GTLAB,
    .setting_note = SO_SETTING_NOTE "; the silhouette region: surface pixels within 3 pixels of the background or "
                    "of a depth jump",
    .reading = "Near silhouettes the cone/lobe table's V_s is closer (DSSIM) to the Phong reference than cone/cone's, "
               "by a visible margin.",
    .form = CLAIM_BETTER, .margin = CLAIM_DSSIM_JUST_NOTICEABLE, .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = SO_DSSIM_MARGIN};

static const claim_record kLobeDarkening = {
    .talk = SO_TALK, .seed = "001", .section = "Intersection with Accurate Reflection Lobes",
    .quote = SO_SILHOUETTE_QUOTE, .setting = SO_SETTING, .setting_match = CLAIM_SETTING_GTLAB,
    .setting_note = SO_SETTING_NOTE "; the silhouette region: surface pixels within 3 pixels of the background or "
                    "of a depth jump",
    .reading = "Near silhouettes the cone/lobe table darkens V_s less than cone/cone (its mean signed error against "
               "the Phong reference is higher), by more than a code value.",
    .form = CLAIM_BETTER, .margin = CLAIM_ONE_CODE_VALUE_8BIT, .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = "one code value of an 8-bit specular-occlusion target (CLAIM_ONE_CODE_VALUE_8BIT)"};

static const claim_record kDrobotRough = {
    .talk = SO_TALK, .seed = "001", .section = "Calculating Aperture From Gloss", .quote = SO_DROBOT_QUOTE,
    .setting = SO_SETTING, .setting_match = CLAIM_SETTING_GTLAB, .setting_note = SO_SETTING_NOTE,
    .reading = "At a small gloss (roughness 0.8, Phong p = 2.9) cone/cone with the talk's gloss-to-aperture mapping "
               "is closer (DSSIM) to the Phong reference than with Drobot 2014's, by a visible margin.",
    .form = CLAIM_BETTER, .margin = CLAIM_DSSIM_JUST_NOTICEABLE, .tolerance_source = CLAIM_TOLERANCE_TALK_COMPARISON,
    .tolerance = SO_DSSIM_MARGIN};

static const claim_record kDrobotGlossy = {
    .talk = SO_TALK, .seed = "001", .section = "Calculating Aperture From Gloss", .quote = SO_DROBOT_QUOTE,
    .setting = SO_SETTING, .setting_match = CLAIM_SETTING_GTLAB, .setting_note = SO_SETTING_NOTE,
    .reading = "At a large gloss (roughness 0.25, Phong p = 510) cone/cone with the talk's mapping and with Drobot "
               "2014's are equally close (DSSIM) to the Phong reference, within a just-noticeable difference either "
               "way.",
    .form = CLAIM_RANGE, .low = -CLAIM_DSSIM_JUST_NOTICEABLE, .high = CLAIM_DSSIM_JUST_NOTICEABLE,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY, .tolerance = SO_DSSIM_MARGIN " either way"};

static const claim_record kCapsEquivalent = {
    .talk = SO_TALK, .seed = "001", .section = "Intersection Calculation",
    .quote = "[Mazonka2012] and [TV01]: ... Mathematically equivalent",
    .setting = "the solid angle of the intersection of two spherical caps, for the cone/cone V_s",
    .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "a property of two formulas, evaluated on a grid of cap configurations: no image, scene or "
                    "resolution enters",
    .reading = "The cap intersections of Tovchigrechko-Vakser 2001 and Mazonka 2012 give the same solid angle for "
               "every configuration.",
    .form = CLAIM_RANGE, .low = -INFINITY, .high = 1e-12, .tolerance_source = CLAIM_TOLERANCE_CLAIM_NUMBER,
    .tolerance = "equivalent: equal up to the rounding of double-precision arithmetic (1e-12 sr)"};

static void add_claim(report_context *ctx, const claim_record *record, const char *quantity,
                      const so_paired_difference *d, double sign)
{
    claims_table_add(ctx->claims, record, sign * d->mean, d->standard_error,
                     "%s; Phong V_s and Phong lobes, as the talk compared; s.e. over %d scenes", quantity, d->cases);
}

/* The claims, judged in the talk's own setting. */
static void rankings_claims(report_context *ctx, const so_ranking_setting *t)
{
    const int last = SO_STUDY_ROUGHNESSES - 1;
    add_claim(ctx, &kConeOverAo, "DSSIM of " CONE " minus AO's, paired over the scenes", &t->cone_minus_ao, 1.0);
    add_claim(ctx, &kConeOverLagarde, "DSSIM of " CONE " minus Lagarde's, paired over the scenes",
              &t->cone_minus_lagarde, 1.0);
    add_claim(ctx, &kLobeSilhouette,
              "DSSIM of the cone/lobe LUT 32^3 minus cone/cone's, window centres within 3 pixels of a silhouette, "
              "paired over the scenes",
              &t->lobe_minus_cone[SO_REGION_SILHOUETTE], 1.0);
    add_claim(ctx, &kLobeDarkening,
              "darkening (minus the mean signed error against the reference) of the cone/lobe LUT 32^3 minus "
              "cone/cone's, pixels within 3 pixels of a silhouette, paired over the scenes",
              &t->lobe_minus_cone_bias[SO_REGION_SILHOUETTE], -1.0);
    add_claim(ctx, &kDrobotRough,
              "DSSIM of cone/cone with the talk's cone minus with Drobot's at r = 0.8 (Phong p = 2.9), paired over "
              "the scenes",
              &t->talk_minus_drobot[last], 1.0);
    add_claim(ctx, &kDrobotGlossy,
              "DSSIM of cone/cone with the talk's cone minus with Drobot's at r = 0.25 (p = 510), paired over the "
              "scenes",
              &t->talk_minus_drobot[0], 1.0);
}

static void conclude(report *doc, const so_rankings *k)
{
    for (int i = 0; i < SO_SETTINGS; ++i) {
        const so_ranking_setting *s = &k->settings[i];
        const so_region_score *cs = &s->cone[SO_REGION_SILHOUETTE], *ls = &s->lobe_score[SO_REGION_SILHOUETTE];
        const so_region_score *ci = &s->cone[SO_REGION_INTERIOR], *li = &s->lobe_score[SO_REGION_INTERIOR];
        report_paragraph(doc,
                         "Against %s (cone/lobe with the %s lobe): near silhouettes cone/cone's mean signed error is "
                         "%+.4f and cone/lobe's %+.4f (DSSIM %.4f and %.4f); in the interior %+.4f and %+.4f (DSSIM "
                         "%.4f and %.4f). Negative is too dark.",
                         s->reference, s->lobe, cs->bias, ls->bias, cs->dssim, ls->dssim, ci->bias, li->bias, ci->dssim,
                         li->dssim);
    }
}

void so_rankings_section(report_context *ctx, const so_study_result *r, cJSON *summary)
{
    const so_rankings *k = &r->rankings;
    cJSON *json = cJSON_AddObjectToObject(summary, "rankings");
    report_heading(ctx->doc, 3, "The talk's rankings, with their significance");
    report_paragraph(ctx->doc,
                     "Each row is a mean over the scenes of variant a's score minus variant b's (negative: a is "
                     "closer to the reference), +- its standard error from the spread over the scenes (each scene's "
                     "mean over the three roughnesses; the pixels and roughnesses of one scene are not independent, "
                     "the scenes are). The talk's setting is its own (\"all the previous comparisons were done using "
                     "Phong\"): the Phong V_s as reference and the Phong lobe in the cone/lobe table; GTSO's is the "
                     "GGX f_r of the rest of this section. cone/cone is " CONE ". The silhouette region (%.0f%% of "
                     "the surface pixels) holds the surface pixels within %d pixels of the background or of a jump "
                     "in view distance of more than %.0f%%; the interior, the rest. The talk's images show a character's "
                     "silhouettes against a background; the built-in scenes are other geometry, so a verdict here "
                     "speaks for them, not for its images.",
                     100.0 * k->silhouette_fraction, SO_SILHOUETTE_RADIUS, 100.0 * SO_SILHOUETTE_JUMP);
    rankings_table(ctx->doc, k, json);
    cJSON_AddNumberToObject(json, "silhouette_fraction", k->silhouette_fraction);
    conclude(ctx->doc, k);
    rankings_claims(ctx, &k->settings[SO_SETTING_TALK]);
    report_paragraph(ctx->doc,
                     "The cap intersection by Tovchigrechko and Vakser 2001 (the Gauss-Bonnet form gtlab uses) and by "
                     "Mazonka 2012 (two cones cut by a plane), which the talk calls \"mathematically equivalent\": "
                     "largest difference %.2g sr over %ld crossing configurations of a 97^3 grid (caps up to pi - 0.05).",
                     r->caps_max_difference, r->caps_configurations);
    cJSON_AddNumberToObject(json, "caps_max_difference", r->caps_max_difference);
    claims_table_add(ctx->claims, &kCapsEquivalent, r->caps_max_difference, 0.0,
                     "largest difference of the two in steradians over the %ld crossing configurations of a 97^3 "
                     "grid, exact figure",
                     r->caps_configurations);
}
