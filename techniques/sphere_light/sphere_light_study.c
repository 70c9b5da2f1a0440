/* The sphere-light study (sphere_light/sphere_light_study.h): the refit, the error
 * maps, the cost of the Newton step and the whole stage. The N.H sweep is in
 * sphere_light_noh.c, the scene renders in sphere_light_scenes.c, the
 * configurations and their references in sphere_light_samples.c. */
#define _GNU_SOURCE
#include "sphere_light/sphere_light_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/files/atomic_file.h"
#include "core/optics/ggx.h"
#include "core/progress.h"
#include "core/sampling/sobol.h"
#include "ltc/ltc_fit.h"
#include "ltc/ltc_sphere.h"
#include "ltc/ltc_study.h"
#include "sphere_light/sphere_light_quality.h"
#include "sphere_light/sphere_light_reference.h"
#include "sphere_light/sphere_light.h"

/* ---- The refit ---- */

/* count configurations from index first, with their references. */
static int make_samples(uint32_t seed, uint32_t first, int count, uint32_t mc_samples, int threads,
                        sphere_light_sample **out, gt_error *e)
{
    sphere_light_sample *s = malloc((size_t)count * sizeof *s);
    if (!s)
        return gt_error_set(e, "fit sphere-light", "out of memory");
    progress bar;
    progress_begin(&bar, "sphere-light references", count);
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads)
    for (int i = 0; i < count; ++i) {
        sphere_light_config c = sphere_light_realistic_config(seed, first + (uint32_t)i);
        s[i] = sphere_light_reference_sample(&c, mc_samples, hash_combine(seed ^ 0x9e3779b9u, first + (uint32_t)i));
        progress_advance(&bar, 1);
    }
    progress_end(&bar);
    *out = s;
    return 0;
}

/* The constants beside the talk's, and the three models on the held-out set. */
static void tabulate_fit(const sphere_light_sample *test, int count, const decima_sphere_constants *published,
                         sphere_fit_outcome *o)
{
    static const char *const names[SPHERE_FIT_PARAMS] = {"radius_reduction", "norm_scale", "norm_alpha"};
    const double pub[SPHERE_FIT_PARAMS] = {published->radius_reduction, published->norm_scale,
                                           published->norm_alpha};
    for (int j = 0; j < SPHERE_FIT_PARAMS; ++j)
        o->constants[j] = (sphere_fit_constant){names[j], o->fit.value[j], o->fit.stderr_[j], pub[j]};
    static const char *const methods[SPHERE_FIT_MODELS] = {"Karis", "Decima (published)", "Decima refit"};
    static const char *const keys[SPHERE_FIT_MODELS] = {"karis", "decima_published", "decima_refit"};
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m)
        o->held_out[m].method = methods[m], o->held_out[m].key = keys[m];
    const sphere_light_model model[SPHERE_FIT_MODELS] = {SPHERE_MODEL_KARIS, SPHERE_MODEL_DECIMA, SPHERE_MODEL_DECIMA};
    const decima_sphere_constants *k[SPHERE_FIT_MODELS] = {NULL, published, &o->fit.constants};
    for (int m = 0; m < SPHERE_FIT_MODELS; ++m) {
        sphere_light_measure(model[m], k[m], test, (size_t)count, &o->held_out[m].errors);
        for (int n = 0; n < SPHERE_FIT_MODELS; ++n)
            sphere_light_paired_abs(model[m], k[m], model[n], k[n], test, (size_t)count, &o->paired_abs[m][n],
                                    &o->paired_abs_se[m][n]);
    }
    double rel = 0.0;
    for (int i = 0; i < count; ++i)
        rel += test[i].reference_stderr / (test[i].reference + SPHERE_FIT_FLOOR);
    o->mean_reference_rel_stderr = rel / count;
}

int sphere_fit_study(const sphere_fit_settings *s, sphere_fit_outcome *out, gt_error *e)
{
    double t0 = seconds_now();
    sphere_light_sample *train = NULL, *test = NULL;
    int rc = -1;
    decima_sphere_constants start = decima_sphere_published();
    if (make_samples(s->seed, 0, s->train, s->mc_samples, s->threads, &train, e) == 0 &&
        make_samples(s->seed, (uint32_t)s->train, s->test, s->mc_samples, s->threads, &test, e) == 0 &&
        sphere_light_fit(train, (size_t)s->train, &start, s->threads, &out->fit, e) == 0) {
        tabulate_fit(test, s->test, &start, out);
        out->seconds = seconds_now() - t0;
        rc = 0;
    }
    free(train), free(test);
    return rc;
}

int sphere_fit_held_out_samples(const sphere_fit_settings *s, sphere_light_sample **out, gt_error *e)
{
    return make_samples(s->seed, (uint32_t)s->train, s->test, s->mc_samples, s->threads, out, e);
}

/* The profile over the radius reduction: DIR/fit_profile.csv. */
static int write_profile(const char *dir, const sphere_fit_outcome *o, gt_error *e)
{
    char text[4096], path[8192];
    int len = snprintf(text, sizeof text, "radius_reduction,cost\n");
    for (int k = 0; k < SPHERE_FIT_PROFILE; ++k)
        len += snprintf(text + len, sizeof text - (size_t)len, "%.6g,%.9g\n", o->fit.profile_reduction[k],
                        o->fit.profile_cost[k]);
    snprintf(path, sizeof path, "%s/fit_profile.csv", dir);
    return atomic_write_text(path, text, e);
}

/* ---- Error maps ---- */

/* Light offsets from the mirror direction, in units of (alpha + sigma),
 * and their azimuths about R: the highlight and its surroundings. */
static const double offset_delta[SPHERE_MAP_OFFSETS] = {0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0, 2.0};
static const double offset_psi[SPHERE_MAP_OFFSETS] = {0.0,       0.0, 1.5707963, 3.1415927,
                                                      0.0,       1.5707963, 3.1415927, 1.5707963};

enum { MAP_METHODS = 4 };

/* Mean |ln((model + 0.01)/(reference + 0.01))| of each method over the
 * offsets of one cell (x, sin_sigma). */
static void cell_errors(const sphere_map_row *m, double x, double sin_sigma, uint32_t samples, uint32_t seed,
                        const decima_sphere_constants *refit, const ltc_table *ltc, double err[MAP_METHODS])
{
    double roughness = m->x_is_roughness ? x : m->fixed, n_dot_v = m->x_is_roughness ? m->fixed : x;
    const decima_sphere_constants published = decima_sphere_published();
    for (int k = 0; k < MAP_METHODS; ++k)
        err[k] = 0.0;
    for (int o = 0; o < SPHERE_MAP_OFFSETS; ++o) {
        double delta = offset_delta[o] * (ggx_alpha(roughness) + asin(sin_sigma));
        sphere_light_config c = sphere_light_config_near_mirror(n_dot_v, delta, offset_psi[o], sin_sigma, roughness);
        sphere_light_sample s = sphere_light_reference_sample(&c, samples, hash_combine(seed, (uint32_t)o));
        err[0] += fabs(sphere_light_residual(SPHERE_MODEL_KARIS, NULL, &s)) / SPHERE_MAP_OFFSETS;
        err[1] += fabs(sphere_light_residual(SPHERE_MODEL_DECIMA, &published, &s)) / SPHERE_MAP_OFFSETS;
        err[2] += fabs(sphere_light_residual(SPHERE_MODEL_DECIMA, refit, &s)) / SPHERE_MAP_OFFSETS;
        err[3] += fabs(sphere_ltc_residual(ltc, &s)) / SPHERE_MAP_OFFSETS;
    }
}

static double map_x(int i, int size) { return SPHERE_MAP_X_LO + (SPHERE_MAP_X_HI - SPHERE_MAP_X_LO) * (i + 0.5) / size; }

static double map_sin_sigma(int j, int size)
{
    return SPHERE_MAP_SIN_LO * pow(SPHERE_MAP_SIN_HI / SPHERE_MAP_SIN_LO, (j + 0.5) / size);
}

/* The cells as CSV (a blank line between rows, for gnuplot) and each
 * method's mean over the map. */
static int write_map(const char *path, sphere_map_row *m, const double *err, int size, gt_error *e)
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    if (!mem)
        return gt_error_set(e, path, "out of memory");
    fprintf(mem, "%s,angular_radius_deg,karis,decima,decima_refit,ltc\n",
            m->x_is_roughness ? "roughness" : "n_dot_v");
    double means[MAP_METHODS] = {0.0, 0.0, 0.0, 0.0};
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            const double *c = err + MAP_METHODS * (j * size + i);
            double sigma_deg = asin(map_sin_sigma(j, size)) * 180.0 / M_PI;
            fprintf(mem, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", map_x(i, size), sigma_deg, c[0], c[1], c[2], c[3]);
            for (int k = 0; k < MAP_METHODS; ++k)
                means[k] += c[k] / (size * size);
        }
        fprintf(mem, "\n");
    }
    fclose(mem);
    m->karis = means[0], m->decima = means[1], m->refit = means[2], m->ltc = means[3];
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

/* One map: DIR/<name>.csv and the means. */
static int run_map(const study_context *ctx, const char *dir, sphere_map_row *m, int size, uint32_t samples,
                   const decima_sphere_constants *refit, const ltc_table *ltc, gt_error *e)
{
    double *err = malloc((size_t)size * size * MAP_METHODS * sizeof *err);
    if (!err)
        return gt_error_set(e, dir, "out of memory");
#pragma omp parallel for schedule(dynamic, 1) num_threads(ctx->threads)
    for (int cell = 0; cell < size * size; ++cell)
        cell_errors(m, map_x(cell % size, size), map_sin_sigma(cell / size, size), samples,
                    hash_combine(0x5f1e, (uint32_t)cell), refit, ltc, err + MAP_METHODS * cell);
    char path[8192];
    snprintf(path, sizeof path, "%s/%s.csv", dir, m->name);
    int rc = write_map(path, m, err, size, e);
    free(err);
    return rc;
}

static const sphere_map_row map_definitions[SPHERE_MAPS] = {
    {"errors_nv_size_r015", "roughness 0.15", "n.v", 0, 0.15, 0, 0, 0, 0},
    {"errors_nv_size_r04", "roughness 0.4", "n.v", 0, 0.4, 0, 0, 0, 0},
    {"errors_nv_size_r07", "roughness 0.7", "n.v", 0, 0.7, 0, 0, 0, 0},
    {"errors_roughness_size_nv03", "n.v = 0.3", "roughness", 1, 0.3, 0, 0, 0, 0},
};

/* ---- The cost of the Newton step ---- */

typedef float (*noh_fn)(float, float, float, float);

/* Counts the instructions (and calls) of `symbol` in the running binary. */
static void count_instructions(const char *symbol, int *instructions, int *calls)
{
    char command[512];
    snprintf(command, sizeof command, "objdump -d --no-show-raw-insn --disassemble=%s /proc/%ld/exe 2>/dev/null",
             symbol, (long)getpid());
    *instructions = -1, *calls = 0;
    FILE *p = popen(command, "r");
    if (!p)
        return;
    char line[512];
    int n = 0;
    while (fgets(line, sizeof line, p)) {
        /* Instruction lines: "  401a2b:\tmnemonic operands". */
        char *colon = strchr(line, ':');
        if (line[0] != ' ' || !colon || colon[1] != '\t')
            continue;
        ++n;
        *calls += strstr(colon, "call") != NULL;
    }
    if (pclose(p) == 0 && n > 0)
        *instructions = n;
}

typedef struct {
    float radius_tan, n_dot_l, n_dot_v, v_dot_l;
} noh_input;

/* Configurations as in the N.H sweep, drawn at random. */
static void make_inputs(noh_input *in, long count)
{
    for (long i = 0; i < count; ++i) {
        double u[4];
        for (int k = 0; k < 4; ++k)
            u[k] = hash_combine(hash_combine(0xbe4c, (uint32_t)i), (uint32_t)k) * 0x1p-32;
        double n_dot_v = 0.02 + 0.98 * u[0], cos_l = u[1], phi = M_PI * u[2];
        double sin_v = sqrt(1.0 - n_dot_v * n_dot_v), sin_l = sqrt(1.0 - cos_l * cos_l);
        in[i].radius_tan = (float)pow(10.0, -3.0 + 3.0 * u[3]);
        in[i].n_dot_l = (float)cos_l, in[i].n_dot_v = (float)n_dot_v;
        in[i].v_dot_l = (float)(sin_v * sin_l * cos(phi) + n_dot_v * cos_l);
    }
}

static double time_function(noh_fn f, const noh_input *in, long count, int repeats, volatile float *sink)
{
    double best = INFINITY;
    for (int r = 0; r < repeats; ++r) {
        double t0 = seconds_now();
        float sum = 0.0f;
        for (long i = 0; i < count; ++i)
            sum += f(in[i].radius_tan, in[i].n_dot_l, in[i].n_dot_v, in[i].v_dot_l);
        best = fmin(best, seconds_now() - t0);
        *sink = sum;
    }
    return 1e9 * best / count;
}

/* The whole specular per pixel, from local vectors, as each method's
 * shader would run it; sphere_specular_fn's signature (F0 = 1). */
static float karis_full(const void *user, vec3 v, vec3 lc, float sin_sigma, float roughness, float f0)
{
    (void)user, (void)f0;
    return karis_sphere_ggx(v, lc, sin_sigma, roughness * roughness);
}

static float decima_full(const void *user, vec3 v, vec3 lc, float sin_sigma, float roughness, float f0)
{
    (void)f0;
    return decima_sphere_ggx_local(v, lc, sin_sigma, roughness * roughness, user, 1);
}

static float ltc_full(const void *user, vec3 v, vec3 lc, float sin_sigma, float roughness, float f0)
{
    (void)f0;
    return ltc_sphere_ggx(user, v, lc, sin_sigma, roughness);
}

typedef struct {
    vec3 v, lc;
    float sin_sigma, roughness;
} spec_input;

/* Configurations of the realistic distribution. */
static void make_spec_inputs(spec_input *in, long count)
{
    for (long i = 0; i < count; ++i) {
        sphere_light_config c = sphere_light_realistic_config(0x7c05, (uint32_t)i);
        in[i] = (spec_input){c.v, c.lc, (float)c.sin_sigma, (float)sqrt(c.alpha)};
    }
}

static double time_specular(sphere_specular_fn f, const void *user, const spec_input *in, long count, int repeats,
                            volatile float *sink)
{
    double best = INFINITY;
    for (int r = 0; r < repeats; ++r) {
        double t0 = seconds_now();
        float sum = 0.0f;
        for (long i = 0; i < count; ++i)
            sum += f(user, in[i].v, in[i].lc, in[i].sin_sigma, in[i].roughness, 1.0f);
        best = fmin(best, seconds_now() - t0);
        *sink = sum;
    }
    return 1e9 * best / count;
}

/* Karis, Decima and the LTC (a 16^2 table: the lookup's cost does not
 * depend on the size) on count / 8 configurations. */
static void time_full_specular(long count, int repeats, sphere_cost *out, volatile float *sink)
{
    out->ns_karis_full = out->ns_decima_full = out->ns_ltc = NAN;
    count = count / 8 > 1 ? count / 8 : 1;
    spec_input *in = malloc((size_t)count * sizeof *in);
    ltc_table t;
    gt_error e;
    if (in && ltc_fit_table(&t, 16, 1, &e) == 0) {
        const decima_sphere_constants published = decima_sphere_published();
        make_spec_inputs(in, count);
        out->ns_karis_full = time_specular(karis_full, NULL, in, count, repeats, sink);
        out->ns_decima_full = time_specular(decima_full, &published, in, count, repeats, sink);
        out->ns_ltc = time_specular(ltc_full, &t, in, count, repeats, sink);
        ltc_table_free(&t);
    }
    free(in);
}

void sphere_cost_print(FILE *out, const sphere_cost *cost, long count, int repeats)
{
    fprintf(out, "GetNoHSquared, %ld configurations (R inside the light in %.1f%%), best of %d passes\n", count,
            100.0 * cost->share_early_out, repeats);
    fprintf(out, "%-24s %14s %14s\n", "", "Karis", "Decima (+1 step)");
    if (cost->instructions_karis > 0 && cost->instructions_decima > 0)
        fprintf(out, "%-24s %14d %14d   %+.0f%% (calls inside: %d, %d)\n", "x86-64 instructions",
                cost->instructions_karis, cost->instructions_decima,
                100.0 * (cost->instructions_decima - cost->instructions_karis) / cost->instructions_karis,
                cost->calls_karis, cost->calls_decima);
    else
        fprintf(out, "%-24s %14s %14s   (objdump not found)\n", "x86-64 instructions", "n/a", "n/a");
    fprintf(out, "%-24s %14.2f %14.2f   %+.0f%%\n", "ns per call", cost->ns_karis, cost->ns_decima,
            100.0 * (cost->ns_decima - cost->ns_karis) / cost->ns_karis);
    fprintf(out, "the talk: +87%% GPU cycles\n");
    fprintf(out, "%-24s %14.2f %14.2f %14.2f (LTC, 16^2 table, 8-gon)\n", "ns per pixel, specular",
            cost->ns_karis_full, cost->ns_decima_full, cost->ns_ltc);
}

void sphere_cost_study(long count, int repeats, sphere_cost *out)
{
    noh_input *in = malloc((size_t)count * sizeof *in);
    volatile float sink = 0.0f;
    memset(out, 0, sizeof *out);
    out->count = count;
    count_instructions("sphere_noh_squared_karis", &out->instructions_karis, &out->calls_karis);
    count_instructions("sphere_noh_squared_decima", &out->instructions_decima, &out->calls_decima);
    out->ns_karis = out->ns_decima = NAN;
    out->ns_karis_full = out->ns_decima_full = out->ns_ltc = NAN;
    if (!in)
        return;
    make_inputs(in, count);
    long early = 0;
    for (long i = 0; i < count; ++i)
        early += 2.0f * in[i].n_dot_l * in[i].n_dot_v - in[i].v_dot_l >=
                 1.0f / sqrtf(1.0f + in[i].radius_tan * in[i].radius_tan);
    out->share_early_out = (double)early / count;
    out->ns_karis = time_function(sphere_noh_squared_karis, in, count, repeats, &sink);
    out->ns_decima = time_function(sphere_noh_squared_decima, in, count, repeats, &sink);
    free(in);
    time_full_specular(count, repeats, out, &sink);
}

/* ---- The stage ---- */

/* The LTC table (its side from the quality table; 64^2 as shipped), its files
 * <output>/luts/ltc_ggx.{exr,h,hlsl,glsl} and its held-out scores. */
static int fit_ltc(const study_context *ctx, const sphere_fit_settings *fs, const sphere_fit_outcome *fit,
                   ltc_table *t, sphere_ltc_result *out, gt_error *e)
{
    sphere_light_sample *test = NULL;
    char luts[4096];
    out->table_size = sphere_light_quality_of(ctx->quality)->ltc_table_size;
    if (study_make_dir(ctx, "luts", luts, sizeof luts, e) != 0 ||
        ltc_table_fit_and_write(luts, out->table_size, ctx->threads, t, &out->fit_seconds, e) != 0)
        return -1;
    out->mean_fit_error = t->mean_error, out->max_fit_error = t->max_error;
    if (sphere_fit_held_out_samples(fs, &test, e) != 0) {
        ltc_table_free(t);
        return -1;
    }
    sphere_ltc_score(t, test, fs->test, fit, out);
    free(test);
    return 0;
}

/* The maps and scenes, with the LTC beside the talks' methods. */
static int ltc_stage_parts(const study_context *ctx, const char *dir, const ltc_table *ltc, sphere_light_result *out,
                           gt_error *e)
{
    const sphere_light_quality *q = sphere_light_quality_of(ctx->quality);
    out->map_size = q->map_size;
    out->map_samples = (uint32_t)q->map_samples;
    for (int k = 0; k < SPHERE_MAPS; ++k) {
        out->maps[k] = map_definitions[k];
        if (run_map(ctx, dir, &out->maps[k], out->map_size, out->map_samples, &out->fit.fit.constants, ltc, e) != 0)
            return -1;
    }
    return sphere_scenes_study(ctx, dir, &out->fit.fit.constants, ltc, out->scenes, &out->shadows, e);
}

int sphere_light_study(const study_context *ctx, sphere_light_result *out, gt_error *e)
{
    const sphere_light_quality *q = sphere_light_quality_of(ctx->quality);
    char dir[4096];
    if (study_make_dir(ctx, SPHERE_LIGHT_DIR, dir, sizeof dir, e) != 0)
        return -1;
    int steps = q->noh_steps;
    out->sweep = (sphere_noh_sweep){steps, steps, steps, steps, 256};
    if (sphere_noh_study(&out->sweep, dir, &out->noh, e) != 0)
        return -1;
    out->fit_settings =
        (sphere_fit_settings){q->fit_train, q->fit_test, (uint32_t)q->fit_mc_samples, 1u, ctx->threads};
    if (sphere_fit_study(&out->fit_settings, &out->fit, e) != 0 || write_profile(dir, &out->fit, e) != 0)
        return -1;
    ltc_table ltc;
    if (fit_ltc(ctx, &out->fit_settings, &out->fit, &ltc, &out->ltc, e) != 0)
        return -1;
    int rc = ltc_stage_parts(ctx, dir, &ltc, out, e);
    ltc_table_free(&ltc);
    if (rc != 0)
        return -1;
    sphere_cost_study(q->cost_calls, 3, &out->cost);
    if (sphere_terminator_study(q->terminator_configurations, (uint32_t)q->terminator_samples, &out->terminator) != 0)
        return gt_error_set(e, "sphere light", "out of memory");
    if (sphere_sun_study(q->sun_configurations, (uint32_t)q->sun_samples, &out->sun) != 0)
        return gt_error_set(e, "sphere light", "out of memory");
    return sphere_units_study(q->units_train, q->units_test, (uint32_t)q->units_samples, ctx->threads, &out->units, e);
}
