/* `gtlab all` stage: GGX sphere lights (Decima, SIGGRAPH 2017; Karis 2013).
 * The accuracy of GetNoHSquared against brute force, the refit of Decima's
 * constants, error maps of Karis, Decima and Decima refit against the
 * parameter-space Monte Carlo reference over (n.v, angular size) and
 * roughness, and the cost of the Newton step. */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/all_stage_sphere_light.h"
#include "cli/bench_sphere_light.h"
#include "cli/check_sphere_noh.h"
#include "cli/fit_sphere_light.h"
#include "cli/gnuplot_plot.h"
#include "core/atomic_file.h"
#include "core/sobol.h"
#include "raytracer/sphere_light_reference.h"

#define METHODS 3
static const char *method_names[METHODS] = {"Karis", "Decima", "Decima refit"};

/* Light offsets from the mirror direction, in units of (alpha + sigma),
 * and their azimuths about R: the highlight and its surroundings. */
#define OFFSETS 8
static const double offset_delta[OFFSETS] = {0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0, 2.0};
static const double offset_psi[OFFSETS] = {0.0, 0.0, 1.5707963, 3.1415927, 0.0, 1.5707963, 3.1415927, 1.5707963};

typedef struct {
    const char *name, *title, *xlabel; /* file stem, plot title, x axis */
    int x_is_roughness;                /* x: roughness (else n.v) */
    double fixed;                      /* the other of roughness / n.v */
} error_map;

/* Mean |ln((model + 0.01)/(reference + 0.01))| of each method over the
 * offsets of one cell (x, sin_sigma). */
static void cell_errors(const error_map *m, double x, double sin_sigma, uint32_t samples, uint32_t seed,
                        const decima_sphere_constants *refit, double err[METHODS])
{
    double roughness = m->x_is_roughness ? x : m->fixed, n_dot_v = m->x_is_roughness ? m->fixed : x;
    const decima_sphere_constants published = decima_sphere_published();
    for (int k = 0; k < METHODS; ++k)
        err[k] = 0.0;
    for (int o = 0; o < OFFSETS; ++o) {
        double delta = offset_delta[o] * (roughness * roughness + asin(sin_sigma));
        sphere_light_config c = sphere_light_config_near_mirror(n_dot_v, delta, offset_psi[o], sin_sigma, roughness);
        sphere_light_estimate est;
        sphere_light_reference(&c, samples, hash_combine(seed, (uint32_t)o), &est);
        double e_perp = sphere_light_normal_illuminance(sin_sigma);
        sphere_light_sample s = {c.v, c.lc, (float)sin_sigma, (float)c.alpha, est.spec / e_perp,
                                 est.spec_stderr / e_perp};
        err[0] += fabs(sphere_light_residual(SPHERE_MODEL_KARIS, NULL, &s)) / OFFSETS;
        err[1] += fabs(sphere_light_residual(SPHERE_MODEL_DECIMA, &published, &s)) / OFFSETS;
        err[2] += fabs(sphere_light_residual(SPHERE_MODEL_DECIMA, refit, &s)) / OFFSETS;
    }
}

/* One map: a grid of cells, a CSV and a gnuplot figure of the three
 * methods side by side on a common colour scale. means[] receives each
 * method's mean over the map. */
static int run_map(const all_context *ctx, const char *dir, const error_map *m, int size, uint32_t samples,
                   const decima_sphere_constants *refit, double means[METHODS], gt_error *e)
{
    double *err = malloc((size_t)size * size * METHODS * sizeof *err);
    if (!err)
        return gt_error_set(e, dir, "out of memory");
    const double x_lo = m->x_is_roughness ? 0.05 : 0.05, x_hi = 1.0;
    const double s_lo = 0.00465, s_hi = 0.5;
#pragma omp parallel for schedule(dynamic, 1) num_threads(ctx->study.threads)
    for (int cell = 0; cell < size * size; ++cell) {
        int i = cell % size, j = cell / size;
        double x = x_lo + (x_hi - x_lo) * (i + 0.5) / size;
        double sin_sigma = s_lo * pow(s_hi / s_lo, (j + 0.5) / size);
        cell_errors(m, x, sin_sigma, samples, hash_combine(0x5f1e, (uint32_t)cell), refit, err + METHODS * cell);
    }
    char *text = NULL, path[8192];
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    if (!mem) {
        free(err);
        return gt_error_set(e, dir, "out of memory");
    }
    fprintf(mem, "%s,angular_radius_deg,karis,decima,decima_refit\n", m->x_is_roughness ? "roughness" : "n_dot_v");
    for (int k = 0; k < METHODS; ++k)
        means[k] = 0.0;
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            const double *c = err + METHODS * (j * size + i);
            double x = x_lo + (x_hi - x_lo) * (i + 0.5) / size;
            double sigma_deg = asin(s_lo * pow(s_hi / s_lo, (j + 0.5) / size)) * 180.0 / M_PI;
            fprintf(mem, "%.6g,%.6g,%.6g,%.6g,%.6g\n", x, sigma_deg, c[0], c[1], c[2]);
            for (int k = 0; k < METHODS; ++k)
                means[k] += c[k] / (size * size);
        }
        fprintf(mem, "\n");
    }
    fclose(mem);
    free(err);
    snprintf(path, sizeof path, "%s/%s.csv", dir, m->name);
    int rc = atomic_write_text(path, text, e);
    free(text);
    if (rc != 0)
        return -1;
    char commands[32768];
    snprintf(commands, sizeof commands,
             "set datafile separator ','\n"
             "set multiplot layout 1,3 title '%s: mean |ln((approx + 0.01)/(reference + 0.01))| near the highlight'\n"
             "set xlabel '%s'\nset ylabel 'angular radius (deg)'\nset logscale y\n"
             "set palette rgb 21,22,23\nset cbrange [0:1]\nset xrange [%g:%g]\nset yrange [%g:%g]\n"
             "set title 'Karis'\nplot '%s' using 1:2:3 with image notitle\n"
             "set title 'Decima (published)'\nplot '%s' using 1:2:4 with image notitle\n"
             "set title 'Decima refit'\nplot '%s' using 1:2:5 with image notitle\n"
             "unset multiplot\n",
             m->title, m->xlabel, x_lo, x_hi, asin(s_lo) * 180.0 / M_PI, asin(s_hi) * 180.0 / M_PI, path, path, path);
    snprintf(path, sizeof path, "%s/%s.png", dir, m->name);
    return gnuplot_render(commands, path, 1500, 460, e);
}

static void add_errors_row(report *doc, const char *name, const sphere_light_errors *x)
{
    char a[64], b[64];
    snprintf(a, sizeof a, "%.4f ± %.4f", x->mean_abs, x->mean_abs_stderr);
    snprintf(b, sizeof b, "%.4f ± %.4f", x->rms, x->rms_stderr);
    const char *cells[3] = {name, a, b};
    report_table_row(doc, cells);
}

static cJSON *errors_json(const sphere_light_errors *x)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "mean_abs_log_error", x->mean_abs);
    cJSON_AddNumberToObject(o, "mean_abs_log_error_stderr", x->mean_abs_stderr);
    cJSON_AddNumberToObject(o, "rms_log_error", x->rms);
    cJSON_AddNumberToObject(o, "rms_log_error_stderr", x->rms_stderr);
    return o;
}

static void report_noh(all_context *ctx, const sphere_noh_sweep *sw, const sphere_noh_stats *st, cJSON *json)
{
    report *doc = ctx->doc;
    report_heading(doc, 3, "N.H maximisation (GetNoHSquared)");
    report_paragraph(doc,
                     "Shortfall of (N.H)^2 below its brute-force maximum over the light's rim (%d angles, refined "
                     "by golden-section search) on a %d^4 grid of n.v, light elevation and azimuth and angular "
                     "size (tan sigma 0.001 to 1); R inside the light in %ld of %ld configurations (all exact). "
                     "The Newton step is gtlab's derivation; the test suite checks it against finite differences "
                     "and the rotated light vector.",
                     sw->rim_steps, sw->nv_steps, st->r_inside, st->configurations);
    const char *headers[7] = {"method", "mean", "99th percentile", "worst", "worse", "better", "than"};
    report_table_begin(doc, 7, headers);
    cJSON *arr = cJSON_AddArrayToObject(json, "noh_shortfall");
    for (int m = 0; m < NOH_METHODS; ++m) {
        char c[5][32];
        int base = sphere_noh_baseline[m];
        snprintf(c[0], 32, "%.4g", st->mean[m]);
        snprintf(c[1], 32, "%.4g", st->p99[m]);
        snprintf(c[2], 32, "%.4g", st->worst[m]);
        snprintf(c[3], 32, base >= 0 ? "%.2f%%" : "-", 100.0 * st->share_worse[m]);
        snprintf(c[4], 32, base >= 0 ? "%.2f%%" : "-", 100.0 * st->share_better[m]);
        const char *cells[7] = {sphere_noh_method_names[m], c[0], c[1], c[2], c[3], c[4],
                                base >= 0 ? sphere_noh_method_names[base] : "-"};
        report_table_row(doc, cells);
        cJSON *o = cJSON_CreateObject();
        cJSON_AddStringToObject(o, "method", sphere_noh_method_names[m]);
        cJSON_AddNumberToObject(o, "mean", st->mean[m]);
        cJSON_AddNumberToObject(o, "p99", st->p99[m]);
        cJSON_AddNumberToObject(o, "worst", st->worst[m]);
        if (base >= 0) {
            cJSON_AddNumberToObject(o, "share_worse_than_baseline", st->share_worse[m]);
            cJSON_AddStringToObject(o, "baseline", sphere_noh_method_names[base]);
        }
        cJSON_AddItemToArray(arr, o);
    }
    report_table_end(doc);
    const char *figs[2] = {"sphere_light/sphere_noh_map.png", "sphere_light/sphere_noh_error.png"};
    const char *caps[2] = {"Where one Newton step helps (blue) or hurts (red), and the share of worse configurations",
                           "Mean shortfall against n.v"};
    report_figures(doc, 2, figs, caps);
    report_finding(doc, "GetNoHSquared",
                   "one Newton step from Karis's point cuts the mean (N.H)^2 shortfall from %.4f to %.4f but is "
                   "worse in %.1f%% of configurations (guarded step: %.4f, worse in %.1f%%).",
                   st->mean[NOH_KARIS], st->mean[NOH_STEP1], 100.0 * st->share_worse[NOH_STEP1], st->mean[NOH_GUARDED],
                   100.0 * st->share_worse[NOH_GUARDED]);
    report_paragraph(doc, "The step hurts at grazing view with the light far from the normal: there f''(0) > 0 "
                          "at Karis's point, so Newton's step heads for a minimum of (N.H)^2, and a second step "
                          "goes on towards it. Taking the step only where f''(0) < 0 (xDenom < 0: one comparison, "
                          "not in the talk) is the 'guarded' row.");
}

static void report_fit(all_context *ctx, const sphere_fit_settings *fs, const sphere_fit_outcome *o, cJSON *json)
{
    report *doc = ctx->doc;
    report_heading(doc, 3, "Refit of Decima's radius reduction and normalisation");
    report_paragraph(doc,
                     "Ceres fit of EvaluateSphericalAreaGGX's constants (realtime/sphere_light.c's own function, "
                     "one Newton step, white specular) to %d Monte Carlo references (%u MIS samples each) drawn "
                     "from a realistic distribution (roughness 0.05-1, the sun's size to 30 deg, light mostly "
                     "near the mirror direction); errors on %d held-out configurations. Error = "
                     "ln((model + 0.01)/(reference + 0.01)), radiance per unit normal illuminance. Files: "
                     "fits/sphere_light.json, .h, .hlsl, .glsl.",
                     fs->train, fs->mc_samples, fs->test);
    const char *headers[3] = {"constant", "refit ± standard error", "published"};
    report_table_begin(doc, 3, headers);
    const char *names[3] = {"radius_reduction", "norm_scale", "norm_alpha"};
    const decima_sphere_constants pub = decima_sphere_published();
    const double pub_v[3] = {pub.radius_reduction, pub.norm_scale, pub.norm_alpha};
    cJSON *vals = cJSON_AddObjectToObject(json, "refit");
    for (int j = 0; j < 3; ++j) {
        char a[64], b[32];
        snprintf(a, sizeof a, "%.4g ± %.2g", o->fit.value[j], o->fit.stderr_[j]);
        snprintf(b, sizeof b, "%g", pub_v[j]);
        const char *cells[3] = {names[j], a, b};
        report_table_row(doc, cells);
        cJSON *p = cJSON_AddObjectToObject(vals, names[j]);
        cJSON_AddNumberToObject(p, "value", o->fit.value[j]);
        cJSON_AddNumberToObject(p, "stderr", o->fit.stderr_[j]);
    }
    report_table_end(doc);
    report_paragraph(doc,
                     "The cost is rugged in the radius reduction (the Newton step jumps, max() clamps the "
                     "radius): Levenberg-Marquardt from the published 0.25 stops in small local minima. So it is "
                     "profiled (held on a grid, the normalisation refitted at each point: coarse by 0.05, then "
                     "by 0.01 around the best); its value and standard error are the vertex and curvature of a "
                     "parabola through the fine points, and the normalisation is fitted with it held there. "
                     "With few configurations (the preview's) the radius reduction comes out low: rare "
                     "configurations with large errors pull it up, and the standard errors, which assume "
                     "independent residuals of one variance, do not show it (docs/decisions.md).");
    const char *pf[1] = {"sphere_light/fit_profile.png"}, *pc[1] = {"Cost against the radius reduction (profile)"};
    report_figures(doc, 1, pf, pc);
    const char *h2[3] = {"held-out", "mean abs error", "RMS error"};
    report_table_begin(doc, 3, h2);
    add_errors_row(doc, "Karis", &o->karis);
    add_errors_row(doc, "Decima (published)", &o->published);
    add_errors_row(doc, "Decima refit", &o->refit);
    report_table_end(doc);
    cJSON *held = cJSON_AddObjectToObject(json, "held_out");
    cJSON_AddItemToObject(held, "karis", errors_json(&o->karis));
    cJSON_AddItemToObject(held, "decima_published", errors_json(&o->published));
    cJSON_AddItemToObject(held, "decima_refit", errors_json(&o->refit));
    report_finding(doc, "GGX sphere lights",
                   "held-out mean |log error| Karis %.3f, Decima as published %.3f, Decima refit %.3f "
                   "(radius reduction %.3g ± %.2g, published %g).",
                   o->karis.mean_abs, o->published.mean_abs, o->refit.mean_abs, o->fit.value[0], o->fit.stderr_[0],
                   pub.radius_reduction);
}

/* The profile as CSV and a plot. */
static int write_profile(const char *dir, const sphere_fit_outcome *o, gt_error *e)
{
    char text[4096], path[8192], commands[16384];
    int len = snprintf(text, sizeof text, "radius_reduction,cost\n");
    for (int k = 0; k < SPHERE_FIT_PROFILE; ++k)
        len += snprintf(text + len, sizeof text - (size_t)len, "%.6g,%.9g\n", o->fit.profile_reduction[k],
                        o->fit.profile_cost[k]);
    snprintf(path, sizeof path, "%s/fit_profile.csv", dir);
    if (atomic_write_text(path, text, e) != 0)
        return -1;
    snprintf(commands, sizeof commands,
             "set datafile separator ','\nset xlabel 'radius reduction (published 0.25)'\n"
             "set ylabel 'cost: 1/2 sum of squared log errors'\nset key off\n"
             "set title 'Decima refit: cost with the radius reduction held, normalisation refitted'\n"
             "plot '%s' using 1:2 skip 1 with points pt 7\n",
             path);
    snprintf(path, sizeof path, "%s/fit_profile.png", dir);
    return gnuplot_render(commands, path, 700, 450, e);
}

static void report_cost(all_context *ctx, const sphere_cost *c, cJSON *json)
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
    snprintf(a, sizeof a, "%d", c->instructions[0]);
    snprintf(b, sizeof b, "%d", c->instructions[1]);
    snprintf(d, sizeof d, "%+.0f%%", 100.0 * (c->instructions[1] - c->instructions[0]) / c->instructions[0]);
    const char *r1[4] = {"instructions", a, b, c->instructions[0] > 0 ? d : "n/a"};
    report_table_row(doc, r1);
    snprintf(a, sizeof a, "%.2f", c->ns_per_call[0]);
    snprintf(b, sizeof b, "%.2f", c->ns_per_call[1]);
    snprintf(d, sizeof d, "%+.0f%%", 100.0 * (c->ns_per_call[1] - c->ns_per_call[0]) / c->ns_per_call[0]);
    const char *r2[4] = {"ns per call", a, b, d};
    report_table_row(doc, r2);
    report_table_end(doc);
    cJSON *o = cJSON_AddObjectToObject(json, "cost");
    cJSON_AddNumberToObject(o, "instructions_karis", c->instructions[0]);
    cJSON_AddNumberToObject(o, "instructions_decima", c->instructions[1]);
    cJSON_AddNumberToObject(o, "ns_per_call_karis", c->ns_per_call[0]);
    cJSON_AddNumberToObject(o, "ns_per_call_decima", c->ns_per_call[1]);
}

int all_stage_sphere_light(all_context *ctx, gt_error *e)
{
    const int preview = ctx->study.quality == QUALITY_PREVIEW;
    char dir[4096], fits[4096], json_path[8192];
    if (study_make_dir(&ctx->study, "sphere_light", dir, sizeof dir, e) != 0 || study_make_dir(&ctx->study, "fits", fits, sizeof fits, e) != 0)
        return -1;
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "sphere_light");
    report_heading(ctx->doc, 2, "GGX sphere lights (Decima 2017, Karis 2013)");

    sphere_noh_sweep sweep = {preview ? 10 : 16, preview ? 10 : 16, preview ? 10 : 16, preview ? 10 : 16, 256};
    sphere_noh_stats st;
    if (sphere_noh_sweep_run(&sweep, dir, &st, e) != 0)
        return -1;
    report_noh(ctx, &sweep, &st, json);

    sphere_fit_settings fs = {preview ? 1500 : 20000, preview ? 800 : 10000, preview ? 512u : 1024u, 1u, ctx->study.threads};
    sphere_fit_outcome fo;
    snprintf(json_path, sizeof json_path, "%s/sphere_light.json", fits);
    if (sphere_fit_run(&fs, json_path, &fo, e) != 0 || write_profile(dir, &fo, e) != 0)
        return -1;
    report_fit(ctx, &fs, &fo, json);

    const error_map maps[4] = {
        {"errors_nv_size_r015", "roughness 0.15", "n.v", 0, 0.15},
        {"errors_nv_size_r04", "roughness 0.4", "n.v", 0, 0.4},
        {"errors_nv_size_r07", "roughness 0.7", "n.v", 0, 0.7},
        {"errors_roughness_size_nv03", "n.v = 0.3", "roughness", 1, 0.3},
    };
    report_heading(ctx->doc, 3, "Error maps against the Monte Carlo reference");
    report_paragraph(ctx->doc, "Each cell: mean |ln((approx + 0.01)/(reference + 0.01))| over 8 light positions "
                               "at 0 to 2 (alpha + sigma) from the mirror direction; same colour scale (0 to 1) "
                               "in every map.");
    const char *headers[4] = {"map", "Karis", "Decima", "Decima refit"};
    const char *figs[4], *caps[4];
    char fig_paths[4][256];
    report_table_begin(ctx->doc, 4, headers);
    cJSON *maps_json = cJSON_AddObjectToObject(json, "error_maps");
    for (int k = 0; k < 4; ++k) {
        double means[METHODS];
        if (run_map(ctx, dir, &maps[k], preview ? 16 : 40, preview ? 256u : 1024u, &fo.fit.constants, means, e) != 0)
            return -1;
        char c[METHODS][32];
        cJSON *m = cJSON_AddObjectToObject(maps_json, maps[k].name);
        for (int j = 0; j < METHODS; ++j) {
            snprintf(c[j], 32, "%.4f", means[j]);
            cJSON_AddNumberToObject(m, method_names[j], means[j]);
        }
        const char *cells[4] = {maps[k].title, c[0], c[1], c[2]};
        report_table_row(ctx->doc, cells);
        snprintf(fig_paths[k], sizeof fig_paths[k], "sphere_light/%s.png", maps[k].name);
        figs[k] = fig_paths[k], caps[k] = maps[k].title;
    }
    report_table_end(ctx->doc);
    report_figures(ctx->doc, 4, figs, caps);

    if (all_stage_sphere_light_scenes(ctx, dir, &fo.fit.constants, json, e) != 0)
        return -1;

    sphere_cost cost;
    sphere_cost_measure(preview ? 1L << 20 : 1L << 22, 3, &cost);
    report_cost(ctx, &cost, json);
    return 0;
}
