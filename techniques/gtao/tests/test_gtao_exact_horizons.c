/* The paragraph on brute-force GTAO (gtao_section.h) from made-up scenes
 * (no study runs): an RMSE against the height-field reference within the
 * reference's noise says so and puts the converged presets' gap on their
 * steps; one above the noise by less than one 8-bit code value (the plane's
 * float rounding against a noiseless reference) is equal for a viewer, with
 * the same conclusion, or none when the converged presets have no gap
 * either; one above it by more says the tests do not explain it
 * and does not blame the steps; summary.json gets the figures and the
 * standing each time; a scene without the run gets neither. The
 * At-a-glance row ranks the real-time variants only: brute-force GTAO,
 * closest on every scene, is never its best row. A fit whose values end on
 * their range's edge says which and what it means; one inside says nothing. */
#include <math.h>
#include <string.h>

#include "gtao/gtao_section.h"
#include "tests/section_test.h"

/* A scene whose exact-horizon run is rmse from the height field, whose noise
 * is noise_rmse, and whose converged GTAO ultra is converged from it less the noise. */
static gtao_validation_scene made_up(double rmse, double noise_rmse, double converged, int with_run)
{
    gtao_validation_scene s = {.scene = "boxes", .variant_count = with_run};
    s.variants[0] = (ao_variant_row){.technique = AO_TECHNIQUE_GTAO, .preset = GTAO_PRESET_REFERENCE,
                                     .label = "GTAO exact horizons, 8 slices", .rmse_hf = rmse};
    double excess = rmse * rmse - noise_rmse * noise_rmse;
    s.split = (ao_error_split){.valid = 1, .converged_sampling_rmse = converged, .exact_valid = with_run,
                               .exact_rmse_hf = rmse,
                               .exact_sampling_rmse = excess > 0 ? sqrt(excess) : 0.0, .hf_noise_rmse = noise_rmse};
    return s;
}

static void check_statement(double rmse, double noise_rmse, double converged, const char *says, const char *never,
                            const char *standing)
{
    section_test t;
    section_test_begin(&t, "gtao_exact_horizons", NULL);
    cJSON *list = cJSON_AddArrayToObject(t.ctx.summary, "gtao_exact_horizons");
    gtao_validation_scene s = made_up(rmse, noise_rmse, converged, 1);
    gtao_exact_horizons_statement(&t.doc, list, &s);
    CHECK_MSG(strstr(t.doc.md, says) != NULL, "'%s' missing: %s", says, t.doc.md);
    CHECK_MSG(strstr(t.doc.md, never) == NULL, "'%s' said: %s", never, t.doc.md);
    const cJSON *o = cJSON_GetArrayItem(list, 0);
    CHECK(cJSON_GetArraySize(list) == 1 && cJSON_GetObjectItem(o, "rmse_vs_heightfield")->valuedouble == rmse);
    CHECK(cJSON_GetObjectItem(o, "heightfield_noise_rmse")->valuedouble == noise_rmse);
    CHECK(cJSON_IsTrue(cJSON_GetObjectItem(o, "within_noise")) == (strcmp(standing, "within the noise") == 0));
    CHECK_MSG(strcmp(cJSON_GetObjectItem(o, "standing")->valuestring, standing) == 0, "%s",
              cJSON_GetObjectItem(o, "standing")->valuestring);
    section_test_end(&t);
}

/* Three scenes where brute force is closest, HBAO next, GTAO medium last. */
static void test_headline_ranks_real_time(void)
{
    static gtao_validation_result r;
    r.scene_count = 3;
    for (int i = 0; i < 3; ++i) {
        gtao_validation_scene *s = &r.scenes[i];
        snprintf(s->scene, sizeof s->scene, "scene%d", i);
        s->variant_count = 3;
        s->variants[0] = (ao_variant_row){.technique = AO_TECHNIQUE_GTAO, .preset = GTAO_PRESET_REFERENCE,
                                          .label = "GTAO exact horizons, 8 slices", .rmse_3d = 0.01 + 0.001 * i};
        s->variants[1] = (ao_variant_row){.technique = AO_TECHNIQUE_HBAO, .preset = -1,
                                          .label = "HBAO 8x8, 1 frame", .rmse_3d = 0.05 + 0.002 * i};
        s->variants[2] = (ao_variant_row){.technique = AO_TECHNIQUE_GTAO, .preset = GTAO_PRESET_MEDIUM,
                                          .label = "GTAO medium, 1 frame", .rmse_3d = 0.08 + 0.001 * i};
    }
    section_test t;
    section_test_begin(&t, "gtao_headline", NULL);
    gtao_headline(&t.doc, &r);
    CHECK(t.doc.headline_count == 1);
    const report_headline *h = &t.doc.headlines[0];
    CHECK_MSG(strcmp(h->best, "HBAO 8x8, 1 frame") == 0 && strcmp(h->runner_up, "GTAO medium, 1 frame") == 0,
              "best %s, runner-up %s", h->best, h->runner_up);
    CHECK(fabs(h->best_error - 0.052) < 1e-12 && strstr(h->measure, "real-time variants"));
    section_test_end(&t);
}

static void test_fit_bounds(void)
{
    char text[512];
    gtao_fit_result r = {.value = {0.66, 0.0, 0.0}};
    gtao_fit_bound_explanation(&r, text, sizeof text);
    CHECK_MSG(strstr(text, " The falloff and the thickness end on the edge of the fit's range") == text &&
                  strstr(text, "no thickness heuristic") && strstr(text, "not an interval"),
              "%s", text);
    r.value[1] = 0.3;
    gtao_fit_bound_explanation(&r, text, sizeof text);
    CHECK_MSG(strstr(text, " The thickness ends on the edge") == text && strstr(text, "no thickness heuristic") &&
                  !strstr(text, "fade"),
              "%s", text);
    r.value[2] = 0.1;
    gtao_fit_bound_explanation(&r, text, sizeof text);
    CHECK_MSG(text[0] == '\0', "%s", text);
    r.value[0] = 2.0;
    gtao_fit_bound_explanation(&r, text, sizeof text);
    CHECK_MSG(strstr(text, " The radius ends on the edge") == text && !strstr(text, "heuristic"), "%s", text);
}

int main(void)
{
    test_headline_ranks_real_time();
    test_fit_bounds();
    const char *within = "within the noise", *invisible = "below one 8-bit code value", *unexplained = "unexplained";
    check_statement(0.03, 0.05, 0.1, "within the reference's own noise (RMSE 0.0500)", "do not explain", within);
    check_statement(0.03, 0.05, 0.1, "their horizon search's steps, not a difference", "do not explain", within);
    /* A noiseless reference (a plane: every sample agrees) and 0.0007 of rounding: invisible. */
    check_statement(0.0007, 0.0, 0.1, "0.0007 once the reference's noise (RMSE 0.0000) is taken out: less than one 8-bit",
                    "do not explain", invisible);
    check_statement(0.0007, 0.0, 0.1, "their horizon search's steps, not a difference", "as the tests prove", invisible);
    /* 0.05 above a noise of 0.03: 0.04 once the noise is taken out. */
    check_statement(0.05, 0.03, 0.1, "0.0400 once the reference's noise (RMSE 0.0300) is taken out", "within the",
                    unexplained);
    check_statement(0.05, 0.03, 0.1, "the tests do not explain", "horizon search's steps, not", unexplained);
    /* A plane: nothing to explain when converged GTAO ultra is as close. */
    check_statement(0.0007, 0.0, 0.0001, "there is no gap here to explain", "horizon search's steps", invisible);

    section_test t;
    section_test_begin(&t, "gtao_exact_horizons_none", NULL);
    cJSON *list = cJSON_AddArrayToObject(t.ctx.summary, "gtao_exact_horizons");
    gtao_validation_scene s = made_up(0.03, 0.05, 0.1, 0);
    size_t before = strlen(t.doc.md);
    gtao_exact_horizons_statement(&t.doc, list, &s);
    CHECK(strlen(t.doc.md) == before && cJSON_GetArraySize(list) == 0);
    section_test_end(&t);
    return check_report("gtao_exact_horizons");
}
