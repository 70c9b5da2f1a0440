/* The Decima atmosphere LUTs: sizes, the build (one precomputation per
 * weather blend, every texel FAST) and the lookups (atmosphere/atmosphere_luts.inc).
 * See the header for the definitions and axes. */
#include "atmosphere/atmosphere_luts.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#include "core/optics/phase_function.h"
#include "atmosphere/atmosphere_luts_c.h"
#include "atmosphere/atmosphere_luts.inc"
#include "atmosphere/atmosphere_scattering.h"

enum { MAX_BLENDS = 3 * ATMOSPHERE_LUT_MAX_AXIS };

atmosphere_lut_sizes atmosphere_lut_sizes_talk(void)
{
    return (atmosphere_lut_sizes){{8, 64, 8, 4}, {64, 1, 1, 4}, {64, 1, 1, 4}};
}

static const int *sizes_of(const atmosphere_lut_sizes *s, int table)
{
    return table == ATMOSPHERE_TABLE_INSCATTER ? s->inscatter : table == ATMOSPHERE_TABLE_SUN ? s->sun : s->sky;
}

int atmosphere_lut_sizes_check(const atmosphere_lut_sizes *sizes, char *msg, size_t size)
{
    static const char *const names[ATMOSPHERE_TABLES] = {"inscatter", "sun", "sky"};
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table)
        for (int axis = 0; axis < 4; ++axis) {
            int n = sizes_of(sizes, table)[axis];
            int ok = n >= 1 && n <= ATMOSPHERE_LUT_MAX_AXIS && (table == 0 || axis != ATMOSPHERE_AXIS_THETA_V || n == 1);
            if (!ok) {
                snprintf(msg, size, "atmosphere LUT %s: axis %d size %d out of range 1..%d", names[table], axis, n,
                         ATMOSPHERE_LUT_MAX_AXIS);
                return -1;
            }
        }
    return 0;
}

static size_t texels(const int n[4]) { return (size_t)n[0] * n[1] * n[2] * n[3]; }

double atmosphere_lut_bytes(int table, const int size[4])
{
    return (double)texels(size) * (table == ATMOSPHERE_TABLE_INSCATTER ? 8.0 : 16.0);
}

void atmosphere_luts_description(const atmosphere_luts *luts, char *text, size_t size)
{
    snprintf(text, size,
             "Decima height-fog atmosphere LUTs (Kojima Productions 2017) over Bruneton 2017's atmosphere: "
             "inscatter[((((t*Ny + y)*Nv + v)*Ns + s)*2 + i)*3 + c], i = 0 Rayleigh (plus orders >= 2 / Pbar_R), 1 Mie, "
             "without phase: background = sum_i p_i(dot(view, sun)) inscatter_i; "
             "sun/sky[((t*Ny + y)*Ns + s)*3 + c]: sun = E_sun x transmittance at y, sky = mean sky radiance over the "
             "sphere at y; %s; y_max = %.0f m, R = %.0f m, R_t = %.0f m; c = R, G, B at 680, 550, 440 nm",
             atmosphere_lut_axes_description(luts->parametrization), luts->max_altitude, luts->model.bottom_radius,
             luts->model.top_radius);
}

double atmosphere_lut_axis_value(int axis, int i, int n, double max_altitude)
{
    double f = n > 1 ? (double)i / (n - 1) : 0.0;
    double top = axis == ATMOSPHERE_AXIS_THETA_S   ? ATMOSPHERE_LUT_THETA_S_MAX
                 : axis == ATMOSPHERE_AXIS_THETA_V ? ATMOSPHERE_LUT_THETA_V_MAX
                 : axis == ATMOSPHERE_AXIS_ALTITUDE ? max_altitude
                                                    : 1.0;
    return f * top;
}

atmosphere_lut_frame atmosphere_luts_frame(const atmosphere_luts *luts)
{
    return (atmosphere_lut_frame){luts->parametrization, luts->model.bottom_radius, luts->model.top_radius,
                                  luts->max_altitude};
}

/* The parameters (theta_s, theta_v, y, t) of grid point (s, v, y, w) of a table of sizes n. */
static void grid_point(const atmosphere_luts *luts, const int n[4], int s, int v, int y, int w, double x[4])
{
    atmosphere_lut_frame f = atmosphere_luts_frame(luts);
    int i[4] = {s, v, y, w};
    atmosphere_lut_grid_parameters(&f, n, i, x);
}

/* The in-scatter texels of weather index w (blend s->t). */
static void fill_inscatter(atmosphere_luts *luts, const atmosphere_solution *s, int w, int threads)
{
    const int *n = luts->sizes.inscatter;
    int count = n[0] * n[1] * n[2];
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
    for (int q = 0; q < count; ++q) {
        double x[4];
        grid_point(luts, n, q % n[0], q / n[0] % n[1], q / (n[0] * n[1]), w, x);
        double r = luts->model.bottom_radius + x[2], mu = cos(x[1]), mu_s = cos(x[0]);
        double S[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS], M[ATMOSPHERE_CHANNELS];
        atmosphere_single_scattering(s, ATMOSPHERE_FAST, r, mu, mu_s, 0.0, S);
        atmosphere_multiple_scattering(s, ATMOSPHERE_FAST, r, mu, mu_s, 0.0, M);
        double pbar = atmosphere_azimuthal_phase(ATMOSPHERE_RAYLEIGH, s->model.mie_g, mu, mu_s);
        float *out = luts->table[ATMOSPHERE_TABLE_INSCATTER] + ((size_t)w * count + q) * 6;
        for (int c = 0; c < 3; ++c)
            out[c] = (float)(S[ATMOSPHERE_RAYLEIGH][c] + M[c] / pbar), out[3 + c] = (float)S[ATMOSPHERE_MIE][c];
    }
}

/* The sun or sky texels of weather index w. */
static void fill_light(atmosphere_luts *luts, int table, const atmosphere_solution *s, int w, int threads)
{
    const int *n = sizes_of(&luts->sizes, table);
    int count = n[0] * n[2];
#pragma omp parallel for schedule(dynamic, 2) num_threads(threads)
    for (int q = 0; q < count; ++q) {
        double x[4];
        grid_point(luts, n, q % n[0], 0, q / n[0], w, x);
        double r = luts->model.bottom_radius + x[2], mu_s = cos(x[0]), v[3];
        if (table == ATMOSPHERE_TABLE_SUN) {
            atmosphere_transmittance_to_sun(s, ATMOSPHERE_FAST, r, mu_s, v);
            for (int c = 0; c < 3; ++c)
                v[c] *= s->model.solar_irradiance[c];
        } else {
            atmosphere_sky_mean_radiance(s, ATMOSPHERE_FAST, r, mu_s, 0.0, v);
        }
        float *out = luts->table[table] + ((size_t)w * count + q) * 3;
        for (int c = 0; c < 3; ++c)
            out[c] = (float)v[c];
    }
}

/* Every slice (table, weather index) whose blend is t. */
static void fill_blend(atmosphere_luts *luts, const atmosphere_solution *s, int threads)
{
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        int nt = sizes_of(&luts->sizes, table)[ATMOSPHERE_AXIS_WEATHER];
        for (int w = 0; w < nt; ++w) {
            if (atmosphere_lut_axis_value(ATMOSPHERE_AXIS_WEATHER, w, nt, 0.0) != s->t)
                continue;
            if (table == ATMOSPHERE_TABLE_INSCATTER)
                fill_inscatter(luts, s, w, threads);
            else
                fill_light(luts, table, s, w, threads);
        }
    }
}

int atmosphere_lut_blends(const atmosphere_lut_sizes *sizes, double *blends)
{
    int count = 0;
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        int nt = sizes_of(sizes, table)[ATMOSPHERE_AXIS_WEATHER];
        for (int w = 0; w < nt; ++w) {
            double t = atmosphere_lut_axis_value(ATMOSPHERE_AXIS_WEATHER, w, nt, 0.0);
            int seen = 0;
            for (int k = 0; k < count; ++k)
                seen |= blends[k] == t;
            if (!seen)
                blends[count++] = t;
        }
    }
    return count;
}

static int allocate(atmosphere_luts *luts)
{
    int ok = 1;
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table) {
        size_t per = table == ATMOSPHERE_TABLE_INSCATTER ? 6 : 3;
        luts->table[table] = malloc(sizeof(float) * per * texels(sizes_of(&luts->sizes, table)));
        ok &= luts->table[table] != NULL;
    }
    return ok ? 0 : -1;
}

int atmosphere_luts_build(atmosphere_luts *luts, const atmosphere_model *m, const atmosphere_lut_sizes *sizes,
                          int threads, char *msg, size_t msg_size)
{
    *luts = (atmosphere_luts){.model = *m, .max_altitude = ATMOSPHERE_LUT_MAX_ALTITUDE, .sizes = *sizes};
    if (atmosphere_lut_sizes_check(sizes, msg, msg_size) != 0 || atmosphere_model_check(m, msg, msg_size) != 0)
        return -1;
    double start = omp_get_wtime(), blends[MAX_BLENDS];
    int rc = allocate(luts), count = atmosphere_lut_blends(sizes, blends);
    for (int k = 0; k < count && rc == 0; ++k) {
        atmosphere_solution s;
        rc = atmosphere_solve(m, blends[k], threads, &s);
        if (rc == 0)
            fill_blend(luts, &s, threads);
        atmosphere_solution_free(&s);
    }
    if (rc != 0) {
        atmosphere_luts_free(luts);
        snprintf(msg, msg_size, "atmosphere LUTs: out of memory");
    }
    luts->build_seconds = omp_get_wtime() - start;
    return rc;
}

const atmosphere_solution *atmosphere_solution_find(const atmosphere_solution *solutions, int count, double t)
{
    for (int k = 0; k < count; ++k)
        if (solutions[k].t == t)
            return &solutions[k];
    return NULL;
}

int atmosphere_luts_build_from(atmosphere_luts *luts, const atmosphere_solution *solutions, int count,
                               const atmosphere_lut_sizes *sizes, int threads, char *msg, size_t msg_size)
{
    return atmosphere_luts_build_parametrized(luts, solutions, count, sizes, ATMOSPHERE_PARAM_LINEAR, threads, msg,
                                              msg_size);
}

int atmosphere_luts_build_parametrized(atmosphere_luts *luts, const atmosphere_solution *solutions, int count,
                                       const atmosphere_lut_sizes *sizes, atmosphere_lut_parametrization kind,
                                       int threads, char *msg, size_t msg_size)
{
    *luts = (atmosphere_luts){.max_altitude = ATMOSPHERE_LUT_MAX_ALTITUDE, .sizes = *sizes, .parametrization = kind};
    if (count < 1) {
        snprintf(msg, msg_size, "atmosphere LUTs: no precomputed solution");
        return -1;
    }
    luts->model = solutions[0].model;
    if (atmosphere_lut_sizes_check(sizes, msg, msg_size) != 0 ||
        atmosphere_lut_parametrization_check(kind, sizes->inscatter, msg, msg_size) != 0)
        return -1;
    double start = omp_get_wtime(), blends[MAX_BLENDS];
    int n = atmosphere_lut_blends(sizes, blends);
    for (int k = 0; k < n; ++k)
        if (!atmosphere_solution_find(solutions, count, blends[k])) {
            snprintf(msg, msg_size, "atmosphere LUTs: no precomputed solution for t = %.9g", blends[k]);
            return -1;
        }
    if (allocate(luts) != 0) {
        atmosphere_luts_free(luts);
        snprintf(msg, msg_size, "atmosphere LUTs: out of memory");
        return -1;
    }
    for (int k = 0; k < n; ++k)
        fill_blend(luts, atmosphere_solution_find(solutions, count, blends[k]), threads);
    luts->build_seconds = omp_get_wtime() - start;
    return 0;
}

void atmosphere_luts_free(atmosphere_luts *luts)
{
    for (int table = 0; table < ATMOSPHERE_TABLES; ++table)
        free(luts->table[table]), luts->table[table] = NULL;
}

/* One axis' grid points and weight at a position (atmosphere/atmosphere_lut_axes.h). */
static atmo_axis axis_of(atmosphere_lut_position p)
{
    int i0 = (int)floor(p.p);
    i0 = i0 < p.lo ? p.lo : i0 > p.hi ? p.hi : i0;
    atmo_axis a = {i0, i0 + 1 <= p.hi ? i0 + 1 : p.hi, (float)(p.p - i0)};
    return a;
}

/* Channel `channel` of `table` at (theta_s, theta_v, y, t): the shared
 * lookup text, at the positions of the tables' parametrization. */
static float lookup(const atmosphere_luts *luts, int table, int channel, float theta_s, float theta_v, float y, float t)
{
    atmo_table tab = {luts, table, channel};
    if (luts->parametrization == ATMOSPHERE_PARAM_LINEAR)
        return atmo_lookup(tab, theta_s, theta_v, y, t);
    atmosphere_lut_frame f = atmosphere_luts_frame(luts);
    atmosphere_lut_position p[4];
    atmosphere_lut_positions(&f, sizes_of(&luts->sizes, table), theta_s, theta_v, y, t, p);
    return atmo_lookup_axes(tab, axis_of(p[0]), axis_of(p[1]), axis_of(p[2]), axis_of(p[3]));
}

void atmosphere_lut_inscatter(const atmosphere_luts *luts, float theta_s, float theta_v, float y, float t,
                              float out[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS])
{
    for (int i = 0; i < ATMOSPHERE_SPECIES; ++i)
        for (int c = 0; c < 3; ++c)
            out[i][c] = lookup(luts, ATMOSPHERE_TABLE_INSCATTER, 3 * i + c, theta_s, theta_v, y, t);
}

void atmosphere_lut_light(const atmosphere_luts *luts, int table, float theta_s, float y, float t,
                          float out[ATMOSPHERE_CHANNELS])
{
    for (int c = 0; c < 3; ++c)
        out[c] = lookup(luts, table, c, theta_s, 0.0f, y, t);
}

void atmosphere_lut_background(const atmosphere_luts *luts, float theta_s, float theta_v, float y, float t, float nu,
                               float out[ATMOSPHERE_CHANNELS])
{
    float L[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS];
    atmosphere_lut_inscatter(luts, theta_s, theta_v, y, t, L);
    float pr = (float)rayleigh_phase(nu), pm = (float)cornette_shanks_phase(nu, luts->model.mie_g);
    for (int c = 0; c < 3; ++c)
        out[c] = pr * L[ATMOSPHERE_RAYLEIGH][c] + pm * L[ATMOSPHERE_MIE][c];
}
