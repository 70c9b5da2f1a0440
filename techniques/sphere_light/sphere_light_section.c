/* Report section: GGX sphere lights (Decima, SIGGRAPH 2017; Karis 2013),
 * sphere_light/sphere_light_study.h rendered into the report: the accuracy of
 * GetNoHSquared against brute force, the refit of Decima's constants, error
 * maps of Karis, Decima and Decima refit against the parameter-space Monte
 * Carlo reference, scene renders, shadows and the cost of the Newton step. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sphere_light/sphere_light_section_parts.h"
#include "sphere_light/sphere_light_section.h"
#include "sphere_light/sphere_noh_figures.h"
#include "report/gnuplot_plot.h"
#include "report/report_table.h"
#include "sphere_light/sphere_light_fit_outputs.h"
#include "sphere_light/sphere_light_study.h"

#define COLUMNS(c) ((int)(sizeof c / sizeof c[0]))

/* ---- N.H maximisation ---- */

static void percent_or_dash(double share, int has_baseline, char *text, size_t size)
{
    snprintf(text, size, has_baseline ? "%.2f%%" : "-", 100.0 * share);
}

static void worse_cell(const void *row, char *text, size_t size)
{
    const sphere_noh_row *r = row;
    percent_or_dash(r->share_worse, r->has_baseline, text, size);
}

static void better_cell(const void *row, char *text, size_t size)
{
    const sphere_noh_row *r = row;
    percent_or_dash(r->share_better, r->has_baseline, text, size);
}

#define NOH_FIGURES                                                         \
    REPORT_STRING("method", "method", sphere_noh_row, method),              \
        REPORT_REAL("mean", "mean", "%.4g", sphere_noh_row, mean),          \
        REPORT_REAL("99th percentile", "p99", "%.4g", sphere_noh_row, p99), \
        REPORT_REAL("worst", "worst", "%.4g", sphere_noh_row, worst)

static const report_column noh_table[] = {
    NOH_FIGURES, REPORT_CELL("worse", worse_cell), REPORT_CELL("better", better_cell),
    REPORT_STRING("than", NULL, sphere_noh_row, baseline),
};
/* summary.json: Karis has no baseline to be worse than. */
static const report_column noh_json_karis[] = {NOH_FIGURES};
static const report_column noh_json_steps[] = {
    NOH_FIGURES,
    REPORT_REAL(NULL, "share_worse_than_baseline", NULL, sphere_noh_row, share_worse),
    REPORT_STRING(NULL, "baseline", sphere_noh_row, baseline),
};

static void report_noh(report_context *ctx, const sphere_noh_sweep *sw, const sphere_noh_stats *st, cJSON *json)
{
    report *doc = ctx->doc;
    const sphere_noh_row *r = st->rows;
    report_heading(doc, 3, "N.H maximisation (GetNoHSquared)");
    report_paragraph(doc,
                     "Shortfall of (N.H)^2 below its brute-force maximum over the light's rim (%d angles, refined "
                     "by golden-section search) on a %d^4 grid of n.v, light elevation and azimuth and angular "
                     "size (tan sigma 0.001 to 1); R inside the light in %ld of %ld configurations (all exact). "
                     "The Newton step is gtlab's derivation; the test suite checks it against finite differences "
                     "and the rotated light vector.",
                     sw->rim_steps, sw->nv_steps, st->r_inside, st->configurations);
    cJSON *list = cJSON_AddArrayToObject(json, "noh_shortfall");
    report_rows(doc, NULL, noh_table, COLUMNS(noh_table), r, sizeof *r, NOH_METHODS);
    report_rows(NULL, list, noh_json_karis, COLUMNS(noh_json_karis), r, sizeof *r, 1);
    report_rows(NULL, list, noh_json_steps, COLUMNS(noh_json_steps), r + 1, sizeof *r, NOH_METHODS - 1);
    const char *figs[2] = {"sphere_light/sphere_noh_map.png", "sphere_light/sphere_noh_error.png"};
    const char *caps[2] = {"Where one Newton step helps (blue) or hurts (red), and the share of worse configurations",
                           "Mean shortfall against n.v"};
    report_figures(doc, 2, figs, caps);
    report_finding(doc, "GetNoHSquared",
                   "one Newton step from Karis's point cuts the mean (N.H)^2 shortfall from %.4f to %.4f but is "
                   "worse in %.1f%% of configurations (guarded step: %.4f, worse in %.1f%%).",
                   r[NOH_KARIS].mean, r[NOH_STEP1].mean, 100.0 * r[NOH_STEP1].share_worse, r[NOH_GUARDED].mean,
                   100.0 * r[NOH_GUARDED].share_worse);
    report_paragraph(doc, "The step hurts at grazing view with the light far from the normal: there f''(0) > 0 "
                          "at Karis's point, so Newton's step heads for a minimum of (N.H)^2, and a second step "
                          "goes on towards it. Taking the step only where f''(0) < 0 (xDenom < 0: one comparison, "
                          "not in the talk) is the 'guarded' row.");
}

/* ---- The refit ---- */

static void constant_cell(const void *row, char *text, size_t size)
{
    const sphere_fit_constant *k = row;
    snprintf(text, size, "%.4g ± %.2g", k->value, k->stderr_);
}

static const report_column constant_table[] = {
    REPORT_STRING("constant", NULL, sphere_fit_constant, name),
    REPORT_CELL("refit ± standard error", constant_cell),
    REPORT_REAL("published", NULL, "%g", sphere_fit_constant, published),
};
static const report_column constant_json[] = {
    REPORT_REAL(NULL, "value", NULL, sphere_fit_constant, value),
    REPORT_REAL(NULL, "stderr", NULL, sphere_fit_constant, stderr_),
};

static void mean_abs_cell(const void *row, char *text, size_t size)
{
    const sphere_light_errors *x = &((const sphere_fit_errors_row *)row)->errors;
    snprintf(text, size, "%.4f ± %.4f", x->mean_abs, x->mean_abs_stderr);
}

static void rms_cell(const void *row, char *text, size_t size)
{
    const sphere_light_errors *x = &((const sphere_fit_errors_row *)row)->errors;
    snprintf(text, size, "%.4f ± %.4f", x->rms, x->rms_stderr);
}

static const report_column held_out_table[] = {
    REPORT_STRING("held-out", NULL, sphere_fit_errors_row, method),
    REPORT_CELL("mean abs error", mean_abs_cell),
    REPORT_CELL("RMS error", rms_cell),
    REPORT_RANKED(NULL, NULL, NULL, sphere_fit_errors_row, errors.mean_abs, REPORT_LOWEST_BEST),
};
static const report_column errors_json[] = {
    REPORT_REAL(NULL, "mean_abs_log_error", NULL, sphere_light_errors, mean_abs),
    REPORT_REAL(NULL, "mean_abs_log_error_stderr", NULL, sphere_light_errors, mean_abs_stderr),
    REPORT_REAL(NULL, "rms_log_error", NULL, sphere_light_errors, rms),
    REPORT_REAL(NULL, "rms_log_error_stderr", NULL, sphere_light_errors, rms_stderr),
};

static void report_fit(report_context *ctx, const sphere_fit_settings *fs, const sphere_fit_outcome *o, cJSON *json)
{
    report *doc = ctx->doc;
    report_heading(doc, 3, "Refit of Decima's radius reduction and normalisation");
    report_paragraph(doc,
                     "Ceres fit of EvaluateSphericalAreaGGX's constants (techniques/sphere_light/sphere_light.c's "
                     "own function, one Newton step, white specular) to %d Monte Carlo references (%u MIS samples each) drawn "
                     "from a realistic distribution (roughness 0.05-1, the sun's size to 30 deg, light mostly "
                     "near the mirror direction); errors on %d held-out configurations. Error = "
                     "ln((model + 0.01)/(reference + 0.01)), radiance per unit normal illuminance. Files: "
                     "fits/sphere_light.json, .h, .hlsl, .glsl.",
                     fs->train, fs->mc_samples, fs->test);
    report_rows(doc, NULL, constant_table, COLUMNS(constant_table), o->constants, sizeof o->constants[0],
                SPHERE_FIT_PARAMS);
    cJSON *values = cJSON_AddObjectToObject(json, "refit");
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j)
        report_object(values, o->constants[j].name, constant_json, COLUMNS(constant_json), &o->constants[j]);
    report_paragraph(doc,
                     "The cost is rugged in the radius reduction (the Newton step jumps, max() clamps the "
                     "radius): Levenberg-Marquardt from the published 0.25 stops in small local minima. So it is "
                     "profiled (held on a grid, the normalisation refitted at each point: coarse by 0.05, then "
                     "by 0.01 around the best); its value and standard error are the vertex and curvature of a "
                     "parabola through the fine points, and the normalisation is fitted with it held there. "
                     "With few configurations (the preview's) the radius reduction comes out low: rare "
                     "configurations with large errors pull it up, and the standard errors, which assume "
                     "independent residuals of one variance, do not show it (techniques/sphere_light/README.md).");
    const char *pf[1] = {"sphere_light/fit_profile.png"}, *pc[1] = {"Cost against the radius reduction (profile)"};
    report_figures(doc, 1, pf, pc);
    report_rows(doc, NULL, held_out_table, COLUMNS(held_out_table), o->held_out, sizeof o->held_out[0],
                SPHERE_FIT_MODELS);
    cJSON *held = cJSON_AddObjectToObject(json, "held_out");
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m)
        report_object(held, o->held_out[m].key, errors_json, COLUMNS(errors_json), &o->held_out[m].errors);
    report_finding(doc, "GGX sphere lights",
                   "held-out mean |log error| Karis %.3f, Decima as published %.3f, Decima refit %.3f "
                   "(radius reduction %.3g ± %.2g, published %g).",
                   o->held_out[SPHERE_FIT_KARIS].errors.mean_abs, o->held_out[SPHERE_FIT_PUBLISHED].errors.mean_abs,
                   o->held_out[SPHERE_FIT_REFIT].errors.mean_abs, o->constants[0].value, o->constants[0].stderr_,
                   o->constants[0].published);
}

/* The profile's plot, from DIR/fit_profile.csv. */
static int plot_profile(const char *dir, gt_error *e)
{
    char path[8192], commands[16384];
    snprintf(path, sizeof path, "%s/fit_profile.csv", dir);
    snprintf(commands, sizeof commands,
             "set datafile separator ','\nset xlabel 'radius reduction (published 0.25)'\n"
             "set ylabel 'cost: 1/2 sum of squared log errors'\nset key off\n"
             "set title 'Decima refit: cost with the radius reduction held, normalisation refitted'\n"
             "plot '%s' using 1:2 skip 1 with points pt 7\n",
             path);
    snprintf(path, sizeof path, "%s/fit_profile.png", dir);
    return gnuplot_render(commands, path, 700, 450, e);
}

/* ---- Error maps ---- */

/* The four methods side by side on a common colour scale, from DIR/<name>.csv. */
static int plot_map(const char *dir, const sphere_map_row *m, gt_error *e)
{
    char path[8192], commands[49152];
    snprintf(path, sizeof path, "%s/%s.csv", dir, m->name);
    snprintf(commands, sizeof commands,
             "set datafile separator ','\n"
             "set multiplot layout 1,4 title '%s: mean |ln((approx + 0.01)/(reference + 0.01))| near the highlight'\n"
             "set xlabel '%s'\nset ylabel 'angular radius (deg)'\nset logscale y\n"
             "set palette rgb 21,22,23\nset cbrange [0:1]\nset xrange [%g:%g]\nset yrange [%g:%g]\n"
             "set title 'Karis'\nplot '%s' using 1:2:3 with image notitle\n"
             "set title 'Decima (published)'\nplot '%s' using 1:2:4 with image notitle\n"
             "set title 'Decima refit'\nplot '%s' using 1:2:5 with image notitle\n"
             "set title 'LTC'\nplot '%s' using 1:2:6 with image notitle\n"
             "unset multiplot\n",
             m->title, m->xlabel, SPHERE_MAP_X_LO, SPHERE_MAP_X_HI, asin(SPHERE_MAP_SIN_LO) * 180.0 / M_PI,
             asin(SPHERE_MAP_SIN_HI) * 180.0 / M_PI, path, path, path, path);
    snprintf(path, sizeof path, "%s/%s.png", dir, m->name);
    return gnuplot_render(commands, path, 2000, 460, e);
}

static const report_column map_columns[] = {
    REPORT_STRING("map", NULL, sphere_map_row, title),
    REPORT_REAL("Karis", "Karis", "%.4f", sphere_map_row, karis),
    REPORT_REAL("Decima", "Decima", "%.4f", sphere_map_row, decima),
    REPORT_REAL("Decima refit", "Decima refit", "%.4f", sphere_map_row, refit),
    REPORT_REAL("LTC", "LTC", "%.4f", sphere_map_row, ltc),
};

static void report_maps(report_context *ctx, const sphere_light_result *r, cJSON *json)
{
    report_heading(ctx->doc, 3, "Error maps against the Monte Carlo reference");
    report_paragraph(ctx->doc, "Each cell: mean |ln((approx + 0.01)/(reference + 0.01))| over 8 light positions "
                               "at 0 to 2 (alpha + sigma) from the mirror direction; same colour scale (0 to 1) "
                               "in every map.");
    report_rows(ctx->doc, NULL, map_columns, COLUMNS(map_columns), r->maps, sizeof r->maps[0], SPHERE_MAPS);
    cJSON *maps_json = cJSON_AddObjectToObject(json, "error_maps");
    const char *figs[SPHERE_MAPS], *caps[SPHERE_MAPS];
    char fig_paths[SPHERE_MAPS][256];
    for (int k = 0; k < SPHERE_MAPS; ++k) {
        report_object(maps_json, r->maps[k].name, map_columns, COLUMNS(map_columns), &r->maps[k]);
        snprintf(fig_paths[k], sizeof fig_paths[k], "sphere_light/%s.png", r->maps[k].name);
        figs[k] = fig_paths[k], caps[k] = r->maps[k].title;
    }
    report_figures(ctx->doc, SPHERE_MAPS, figs, caps);
}

/* ---- Scenes and shadows ---- */

static const report_column scene_columns[] = {
    REPORT_STRING("scene", NULL, sphere_scene_row, title),
    REPORT_STRING(NULL, "scene", sphere_scene_row, name),
    REPORT_REAL("Karis", "karis", "%.4g", sphere_scene_row, karis),
    REPORT_REAL("Decima", "decima", "%.4g", sphere_scene_row, decima),
    REPORT_REAL("Decima refit", "decima_refit", "%.4g", sphere_scene_row, refit),
    REPORT_REAL("noise floor", "noise_floor_dssim", "%.2g", sphere_scene_row, noise_floor),
    REPORT_REAL("FLIP Karis", "karis_flip", "%.4f", sphere_scene_row, karis_flip),
    REPORT_REAL("FLIP Decima", "decima_flip", "%.4f", sphere_scene_row, decima_flip),
    REPORT_REAL("FLIP Decima refit", "decima_refit_flip", "%.4f", sphere_scene_row, refit_flip),
    REPORT_REAL("LTC", "ltc", "%.4g", sphere_scene_row, ltc),
    REPORT_REAL("FLIP LTC", "ltc_flip", "%.4f", sphere_scene_row, ltc_flip),
};

static void scene_figures(report *doc, const sphere_scene_row *s)
{
    enum { FIGS = 1 + 2 * SPHERE_SCENE_APPROX };
    char paths[FIGS][256];
    const char *figs[FIGS], *caps[FIGS] = {"reference", "Karis", "Decima", "Decima refit", "LTC",
                                           "|Karis - reference|", "|Decima - reference|", "|refit - reference|",
                                           "|LTC - reference|"};
    snprintf(paths[0], 256, "sphere_light/scene_%s_reference.png", s->name);
    for (int m = 0; m < SPHERE_SCENE_APPROX; ++m) {
        snprintf(paths[1 + m], 256, "sphere_light/scene_%s_%s.png", s->name, sphere_scene_approx_files[m]);
        snprintf(paths[1 + SPHERE_SCENE_APPROX + m], 256, "sphere_light/scene_%s_%s_error.png", s->name,
                 sphere_scene_approx_files[m]);
    }
    for (int j = 0; j < FIGS; ++j)
        figs[j] = paths[j];
    report_comparison(doc, FIGS, figs, caps, 1 + SPHERE_SCENE_APPROX, s->title);
    char flips[SPHERE_SCENE_APPROX][256];
    const char *flip_caps[SPHERE_SCENE_APPROX] = {"FLIP of Karis", "FLIP of Decima", "FLIP of the refit",
                                                  "FLIP of the LTC"};
    for (int m = 0; m < SPHERE_SCENE_APPROX; ++m) {
        snprintf(flips[m], 256, "sphere_light/scene_%s_%s_flip.png", s->name, sphere_scene_approx_files[m]);
        figs[m] = flips[m];
    }
    report_figures(doc, SPHERE_SCENE_APPROX, figs, flip_caps);
}

static const report_column shadow_json[] = {
    REPORT_REAL(NULL, "dssim_shadowed_vs_unshadowed", NULL, sphere_shadow_result, dssim),
    REPORT_REAL(NULL, "share_of_pixels_darkened_over_10_percent", NULL, sphere_shadow_result, share_darkened),
};

static void report_scenes(report_context *ctx, const sphere_light_result *r, cJSON *json)
{
    report *doc = ctx->doc;
    report_heading(doc, 3, "Scene renders: glossy floor at grazing view");
    report_paragraph(doc,
                     "A grey dielectric floor (albedo %.2f, roughness %.2f, F0 %.2f) seen from 0.5 units above it, "
                     "unshadowed. Reference: 'gtlab render sphere-light' (MIS over the light, Fresnel inside the "
                     "integral). Approximations evaluated per pixel from the reference's G-buffer, with the exact "
                     "Lambert part (Frostbite's illuminance) in all four, so they differ only in the specular. "
                     "DSSIM on linear radiance (green channel; the scenes are grey), and mean FLIP (HDR-FLIP where "
                     "the reference exceeds 1, its exposures the reference's; metrics/flip.h); previews and heatmaps "
                     "scaled by the reference's 99th percentile, FLIP maps on [0, 1].",
                     SPHERE_FLOOR_ALBEDO, SPHERE_FLOOR_ROUGHNESS, SPHERE_F0_DIELECTRIC);
    report_rows(doc, cJSON_AddArrayToObject(json, "scenes"), scene_columns, COLUMNS(scene_columns), r->scenes,
                sizeof r->scenes[0], SPHERE_SCENES);
    for (int k = 0; k < SPHERE_SCENES; ++k)
        scene_figures(doc, &r->scenes[k]);
    report_paragraph(doc,
                     "What none of the approximations models: the same reference with 'gtlab render sphere-light "
                     "--shadows' (one occlusion ray per light-carrying sample) on sphere-on-plane, light of radius "
                     "0.5 up and to the left. %.0f%% of the visible pixels lose more than a tenth of their light to "
                     "the sphere's shadow; DSSIM between the shadowed and the unshadowed reference %.4f. A renderer "
                     "must get that part from elsewhere (shadow maps, specular occlusion).",
                     100.0 * r->shadows.share_darkened, r->shadows.dssim);
    const char *figs[2] = {"sphere_light/scene_shadows_unshadowed.png", "sphere_light/scene_shadows_shadowed.png"};
    const char *caps[2] = {"unshadowed reference (what the approximations aim at)", "with --shadows"};
    report_figures(doc, 2, figs, caps);
    report_object(json, "shadows", shadow_json, COLUMNS(shadow_json), &r->shadows);
}

/* ---- Cost ---- */

static const report_column cost_json[] = {
    REPORT_INT(NULL, "instructions_karis", sphere_cost, instructions_karis),
    REPORT_INT(NULL, "instructions_decima", sphere_cost, instructions_decima),
    REPORT_REAL(NULL, "ns_per_call_karis", NULL, sphere_cost, ns_karis),
    REPORT_REAL(NULL, "ns_per_call_decima", NULL, sphere_cost, ns_decima),
};

static void report_cost(report_context *ctx, const sphere_cost *c, cJSON *json)
{
    report *doc = ctx->doc;
    report_heading(doc, 3, "Cost of the Newton step");
    report_paragraph(doc,
                     "x86-64 instructions of the two functions compiled in this gtlab (objdump of the binary; "
                     "-O3, scalar SSE, no calls inside) and nanoseconds per call over %ld configurations (one "
                     "thread, best of 3). The talk measured +87%% GPU cycles.",
                     c->count);
    const char *headers[4] = {"", "Karis", "Decima (1 step)", "increase"};
    report_table_begin(doc, 4, headers);
    char a[32], b[32], d[32];
    snprintf(a, sizeof a, "%d", c->instructions_karis);
    snprintf(b, sizeof b, "%d", c->instructions_decima);
    snprintf(d, sizeof d, "%+.0f%%",
             100.0 * (c->instructions_decima - c->instructions_karis) / c->instructions_karis);
    const char *r1[4] = {"instructions", a, b, c->instructions_karis > 0 ? d : "n/a"};
    report_table_row(doc, r1);
    snprintf(a, sizeof a, "%.2f", c->ns_karis);
    snprintf(b, sizeof b, "%.2f", c->ns_decima);
    snprintf(d, sizeof d, "%+.0f%%", 100.0 * (c->ns_decima - c->ns_karis) / c->ns_karis);
    const char *r2[4] = {"ns per call", a, b, d};
    report_table_row(doc, r2);
    report_table_end(doc);
    report_object(json, "cost", cost_json, COLUMNS(cost_json), c);
}

/* ---- The stage ---- */

static int write_files(report_context *ctx, const sphere_light_result *r, gt_error *e)
{
    char dir[4096], fits[4096], json_path[8192];
    if (study_make_dir(&ctx->study, SPHERE_LIGHT_DIR, dir, sizeof dir, e) != 0 ||
        study_make_dir(&ctx->study, "fits", fits, sizeof fits, e) != 0)
        return -1;
    snprintf(json_path, sizeof json_path, "%s/sphere_light.json", fits);
    if (sphere_noh_plots(dir, e) != 0 || sphere_fit_write(&r->fit_settings, &r->fit, json_path, e) != 0 ||
        plot_profile(dir, e) != 0)
        return -1;
    for (int k = 0; k < SPHERE_MAPS; ++k)
        if (plot_map(dir, &r->maps[k], e) != 0)
            return -1;
    return 0;
}

int sphere_light_section(report_context *ctx, const sphere_light_result *r, gt_error *e)
{
    if (write_files(ctx, r, e) != 0)
        return -1;
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "sphere_light");
    report_heading(ctx->doc, 2, "GGX sphere lights (Decima 2017, Karis 2013)");
    report_noh(ctx, &r->sweep, &r->noh, json);
    report_fit(ctx, &r->fit_settings, &r->fit, json);
    report_maps(ctx, r, json);
    report_scenes(ctx, r, json);
    report_cost(ctx, &r->cost, json);
    sphere_ltc_section(ctx, r, json);
    sphere_ltc_headline(ctx->doc, r);
    sphere_sun_section(ctx, &r->sun, json);
    sphere_terminator_section(ctx, &r->terminator, json);
    sphere_units_section(ctx, &r->units, json);
    return 0;
}
