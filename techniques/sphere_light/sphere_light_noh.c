/* GetNoHSquared against the brute-force maximum of (N.H)^2 over the light
 * (sphere_light/sphere_light_study.h): Karis's point and de Carpentier's Newton step
 * (sphere_light/sphere_light.h) against sphere_light/sphere_light_reference.h (the REFERENCE part). */
#define _GNU_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/atomic_file.h"
#include "sphere_light/sphere_light_reference.h"
#include "sphere_light/sphere_light.h"
#include "sphere_light/sphere_light_study.h"

static const char *const method_names[NOH_METHODS] = {"Karis (0 steps)", "1 Newton step", "2 Newton steps",
                                                      "1 step, guarded"};
static const int baseline[NOH_METHODS] = {-1, NOH_KARIS, NOH_STEP1, NOH_KARIS};

/* Shortfall of method m for configuration i. */
#define SHORT(best, got, i, m) ((double)(best)[i] - (got)[NOH_METHODS * (i) + (m)])

#define TAN_MIN 1e-3
#define TAN_MAX 1.0

/* Configuration i of the grid: n.v and the light's polar angle at cell
 * centres of (0, 1] and (0, 90 deg), azimuth from v's plane in (0, 180 deg)
 * (the other half is its mirror image), tan(sigma) log-spaced over
 * [1e-3, 1] (a sun-sized 0.06 deg to 45 deg). */
static sphere_noh_config grid_config(const sphere_noh_sweep *s, long i, int idx[4])
{
    idx[3] = (int)(i % s->size_steps), i /= s->size_steps;
    idx[2] = (int)(i % s->phi_steps), i /= s->phi_steps;
    idx[1] = (int)(i % s->theta_steps), i /= s->theta_steps;
    idx[0] = (int)i;
    double n_dot_v = (idx[0] + 0.5) / s->nv_steps;
    double theta = 0.5 * M_PI * (idx[1] + 0.5) / s->theta_steps;
    double phi = M_PI * (idx[2] + 0.5) / s->phi_steps;
    double t = s->size_steps > 1 ? (double)idx[3] / (s->size_steps - 1) : 0.0;
    double radius_tan = TAN_MIN * pow(TAN_MAX / TAN_MIN, t);
    return sphere_noh_config_make(n_dot_v, theta, phi, radius_tan);
}

static int compare_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* Nearest-rank 99th percentile of n values (sorted in place). */
static double percentile99(float *v, long n)
{
    if (n == 0)
        return 0.0;
    qsort(v, (size_t)n, sizeof *v, compare_float);
    long k = (long)ceil(0.99 * n) - 1;
    return v[k < 0 ? 0 : k];
}

static int write_csv(const char *path, const sphere_noh_sweep *s, long count, const float *best, const float *got,
                     gt_error *e)
{
    atomic_file f;
    FILE *out = atomic_file_open(&f, path, "w", e);
    if (!out)
        return -1;
    fprintf(out, "n_dot_v,light_theta_deg,light_phi_deg,radius_tan,max_noh2,karis_noh2,newton1_noh2,newton2_noh2,"
                 "guarded_noh2\n");
    for (long i = 0; i < count; ++i) {
        int idx[4];
        sphere_noh_config c = grid_config(s, i, idx);
        const float *g = got + NOH_METHODS * i;
        fprintf(out, "%.6g,%.6g,%.6g,%.6g,%.9g,%.9g,%.9g,%.9g,%.9g\n", c.v[2], acos(c.lc[2]) * 180.0 / M_PI,
                atan2(c.lc[1], c.lc[0]) * 180.0 / M_PI, c.radius_tan, best[i], g[0], g[1], g[2], g[3]);
    }
    return atomic_file_close(&f, out, e);
}

/* Sums over the (n.v, light elevation) cells: gain of 1 step over Karis,
 * configurations where it is worse, count, and each method's shortfall. */
typedef struct {
    int cells;
    double *gain, *worse, *n, *err; /* err: NOH_METHODS per cell */
} noh_cells;

static int cells_sum(const sphere_noh_sweep *s, long count, const float *best, const float *got, noh_cells *c)
{
    c->cells = s->nv_steps * s->theta_steps;
    c->gain = calloc((size_t)c->cells, sizeof *c->gain), c->worse = calloc((size_t)c->cells, sizeof *c->worse);
    c->n = calloc((size_t)c->cells, sizeof *c->n), c->err = calloc((size_t)c->cells * NOH_METHODS, sizeof *c->err);
    if (!c->gain || !c->worse || !c->n || !c->err)
        return -1;
    for (long i = 0; i < count; ++i) {
        int idx[4];
        grid_config(s, i, idx);
        int cell = idx[0] * s->theta_steps + idx[1];
        double e0 = SHORT(best, got, i, NOH_KARIS), e1 = SHORT(best, got, i, NOH_STEP1);
        c->gain[cell] += e0 - e1, c->worse[cell] += e1 > e0 + 1e-6, c->n[cell] += 1.0;
        for (int m = 0; m < NOH_METHODS; ++m)
            c->err[NOH_METHODS * cell + m] += SHORT(best, got, i, m);
    }
    return 0;
}

static void cells_free(noh_cells *c) { free(c->gain), free(c->worse), free(c->n), free(c->err); }

/* Writes text built by `print` into path through an in-memory stream. */
static int write_text(const char *path, void (*print)(FILE *, const sphere_noh_sweep *, const noh_cells *),
                      const sphere_noh_sweep *s, const noh_cells *c, gt_error *e)
{
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    if (!mem)
        return gt_error_set(e, path, "out of memory");
    print(mem, s, c);
    fclose(mem);
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

/* Mean improvement of 1 step over Karis (positive helps) and the share of
 * worse configurations per cell, a blank line between scan rows (gnuplot). */
static void print_map(FILE *mem, const sphere_noh_sweep *s, const noh_cells *c)
{
    fprintf(mem, "n_dot_v,light_theta_deg,mean_gain_newton1,share_newton1_worse\n");
    for (int a = 0; a < s->nv_steps; ++a) {
        for (int b = 0; b < s->theta_steps; ++b) {
            int cell = a * s->theta_steps + b;
            fprintf(mem, "%.6g,%.6g,%.6g,%.6g\n", (a + 0.5) / s->nv_steps, 90.0 * (b + 0.5) / s->theta_steps,
                    c->gain[cell] / c->n[cell], c->worse[cell] / c->n[cell]);
        }
        fprintf(mem, "\n");
    }
}

/* Mean shortfalls per n.v over every other dimension. */
static void print_by_nv(FILE *mem, const sphere_noh_sweep *s, const noh_cells *c)
{
    fprintf(mem, "n_dot_v,mean_err_karis,mean_err_newton1,mean_err_newton2,mean_err_guarded\n");
    for (int a = 0; a < s->nv_steps; ++a) {
        double sum[NOH_METHODS] = {0}, count = 0;
        for (int b = 0; b < s->theta_steps; ++b) {
            int cell = a * s->theta_steps + b;
            for (int m = 0; m < NOH_METHODS; ++m)
                sum[m] += c->err[NOH_METHODS * cell + m];
            count += c->n[cell];
        }
        fprintf(mem, "%.6g", (a + 0.5) / s->nv_steps);
        for (int m = 0; m < NOH_METHODS; ++m)
            fprintf(mem, ",%.6g", sum[m] / count);
        fprintf(mem, "\n");
    }
}

static int write_cells(const char *dir, const sphere_noh_sweep *s, long count, const float *best, const float *got,
                       gt_error *e)
{
    noh_cells c = {0};
    char map[4096], by_nv[4096];
    snprintf(map, sizeof map, "%s/sphere_noh_map.csv", dir);
    snprintf(by_nv, sizeof by_nv, "%s/sphere_noh_by_nv.csv", dir);
    int rc = cells_sum(s, count, best, got, &c) != 0 ? gt_error_set(e, dir, "out of memory")
             : write_text(map, print_map, s, &c, e) != 0 ? -1
                                                          : write_text(by_nv, print_by_nv, s, &c, e);
    cells_free(&c);
    return rc;
}

/* One method's row over the configurations with R outside the light. */
static void summarise_method(int m, long count, const float *best, const float *got, sphere_noh_row *r,
                             float *scratch)
{
    long outside = 0;
    memset(r, 0, sizeof *r);
    r->method = method_names[m];
    r->has_baseline = baseline[m] >= 0;
    r->baseline = r->has_baseline ? method_names[baseline[m]] : "-";
    for (long i = 0; i < count; ++i) {
        if (got[NOH_METHODS * i] == 1.0f)
            continue;
        double err = SHORT(best, got, i, m);
        scratch[outside++] = (float)err;
        r->mean += err;
        r->worst = fmax(r->worst, err);
        if (r->has_baseline) {
            double base = SHORT(best, got, i, baseline[m]);
            r->share_worse += err > base + 1e-6;
            r->share_better += err < base - 1e-6;
        }
    }
    if (outside > 0)
        r->mean /= outside, r->share_worse /= outside, r->share_better /= outside;
    r->p99 = percentile99(scratch, outside);
}

static void summarise(long count, const float *best, const float *got, sphere_noh_stats *st, float *scratch)
{
    memset(st, 0, sizeof *st);
    st->configurations = count;
    for (long i = 0; i < count; ++i)
        st->r_inside += got[NOH_METHODS * i] == 1.0f;
    for (int m = 0; m < NOH_METHODS; ++m)
        summarise_method(m, count, best, got, &st->rows[m], scratch);
}

/* The brute-force maximum and every method at each configuration. */
static void evaluate(const sphere_noh_sweep *s, long count, float *best, float *got)
{
#pragma omp parallel for schedule(dynamic, 64)
    for (long i = 0; i < count; ++i) {
        int idx[4];
        sphere_noh_config c = grid_config(s, i, idx);
        float nl, nv, vl;
        sphere_noh_config_dots(&c, &nl, &nv, &vl);
        /* R inside: the maximum is 1 (the disc search only approaches it). */
        best[i] = sphere_noh_r_inside(&c) ? 1.0f : (float)sphere_noh_squared_max(&c, s->rim_steps, 0, NULL);
        float *g = got + NOH_METHODS * i;
        for (int m = NOH_KARIS; m <= NOH_STEP2; ++m)
            g[m] = sphere_noh_squared((float)c.radius_tan, nl, nv, vl, m);
        g[NOH_GUARDED] = sphere_noh_squared_guarded((float)c.radius_tan, nl, nv, vl);
    }
}

int sphere_noh_study(const sphere_noh_sweep *s, const char *dir, sphere_noh_stats *stats, gt_error *e)
{
    long count = (long)s->nv_steps * s->theta_steps * s->phi_steps * s->size_steps;
    float *best = malloc((size_t)count * sizeof *best), *got = malloc((size_t)count * NOH_METHODS * sizeof *got);
    float *scratch = malloc((size_t)count * sizeof *scratch);
    int rc = -1;
    char path[4096];
    snprintf(path, sizeof path, "%s/sphere_noh.csv", dir);
    if (!best || !got || !scratch)
        gt_error_set(e, dir, "out of memory");
    else {
        evaluate(s, count, best, got);
        if (write_csv(path, s, count, best, got, e) == 0 && write_cells(dir, s, count, best, got, e) == 0) {
            summarise(count, best, got, stats, scratch);
            rc = 0;
        }
    }
    free(best), free(got), free(scratch);
    return rc;
}
