/* gtlab check sphere-noh: how close Karis's point and de Carpentier's
 * Newton step (Decima, SIGGRAPH 2017) come to the maximum of (N.H)^2 over a
 * spherical light, against a brute-force search (raytracer/sphere_light_reference.h). */
#define _GNU_SOURCE
#include "cli/check_sphere_noh.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "cli/gnuplot_plot.h"
#include "core/atomic_file.h"
#include "raytracer/sphere_light_reference.h"
#include "realtime/sphere_light.h"

const char *const sphere_noh_method_names[NOH_METHODS] = {"Karis (0 steps)", "1 Newton step", "2 Newton steps",
                                                          "1 step, guarded"};
const int sphere_noh_baseline[NOH_METHODS] = {-1, NOH_KARIS, NOH_STEP1, NOH_KARIS};

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

/* Mean shortfalls per n.v over every other dimension, from the map's sums
 * (err: cell-major, NOH_METHODS per cell). */
static int write_by_nv(const char *dir, const sphere_noh_sweep *s, const double *err, const double *n, gt_error *e)
{
    char *text = NULL, path[4096];
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    if (!mem)
        return gt_error_set(e, dir, "out of memory");
    fprintf(mem, "n_dot_v,mean_err_karis,mean_err_newton1,mean_err_newton2,mean_err_guarded\n");
    for (int a = 0; a < s->nv_steps; ++a) {
        double sum[NOH_METHODS] = {0}, count = 0;
        for (int b = 0; b < s->theta_steps; ++b) {
            int cell = a * s->theta_steps + b;
            for (int m = 0; m < NOH_METHODS; ++m)
                sum[m] += err[NOH_METHODS * cell + m];
            count += n[cell];
        }
        fprintf(mem, "%.6g", (a + 0.5) / s->nv_steps);
        for (int m = 0; m < NOH_METHODS; ++m)
            fprintf(mem, ",%.6g", sum[m] / count);
        fprintf(mem, "\n");
    }
    fclose(mem);
    snprintf(path, sizeof path, "%s/sphere_noh_by_nv.csv", dir);
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

/* Over the (n.v, light elevation) plane: mean improvement of 1 step over
 * Karis (positive helps) and the share of worse configurations. */
static int write_map(const char *dir, const sphere_noh_sweep *s, long count, const float *best, const float *got,
                     gt_error *e)
{
    int cells = s->nv_steps * s->theta_steps;
    double *gain = calloc((size_t)cells, sizeof *gain), *worse = calloc((size_t)cells, sizeof *worse);
    double *n = calloc((size_t)cells, sizeof *n), *err = calloc((size_t)cells * NOH_METHODS, sizeof *err);
    char path[4096], *text = NULL;
    size_t text_len = 0;
    int rc = -1;
    FILE *mem = NULL;
    if (!gain || !worse || !n || !err) {
        gt_error_set(e, dir, "out of memory");
        goto done;
    }
    for (long i = 0; i < count; ++i) {
        int idx[4];
        grid_config(s, i, idx);
        int cell = idx[0] * s->theta_steps + idx[1];
        double e0 = SHORT(best, got, i, NOH_KARIS), e1 = SHORT(best, got, i, NOH_STEP1);
        gain[cell] += e0 - e1, worse[cell] += e1 > e0 + 1e-6, n[cell] += 1.0;
        for (int m = 0; m < NOH_METHODS; ++m)
            err[NOH_METHODS * cell + m] += SHORT(best, got, i, m);
    }
    if (!(mem = open_memstream(&text, &text_len))) {
        gt_error_set(e, dir, "out of memory");
        goto done;
    }
    fprintf(mem, "n_dot_v,light_theta_deg,mean_gain_newton1,share_newton1_worse\n");
    for (int a = 0; a < s->nv_steps; ++a) {
        for (int b = 0; b < s->theta_steps; ++b) {
            int cell = a * s->theta_steps + b;
            fprintf(mem, "%.6g,%.6g,%.6g,%.6g\n", (a + 0.5) / s->nv_steps, 90.0 * (b + 0.5) / s->theta_steps,
                    gain[cell] / n[cell], worse[cell] / n[cell]);
        }
    fprintf(mem, "\n"); /* gnuplot's blank line between scan rows */
    }
    fclose(mem);
    mem = NULL;
    snprintf(path, sizeof path, "%s/sphere_noh_map.csv", dir);
    if (atomic_write_text(path, text, e) != 0)
        goto done;
    char commands[4096];
    snprintf(commands, sizeof commands,
             "set datafile separator ','\n"
             "set multiplot layout 1,2 title 'GetNoHSquared: one Newton step against Karis (mean over light size and azimuth)'\n"
             "set xlabel 'n.v'\nset ylabel 'light elevation from n (deg)'\n"
             "set palette defined (-1 'red', 0 'white', 1 'blue')\n"
             "set title 'gain in (N.H)^2 (blue: the step helps)'\n"
             "stats '%s/sphere_noh_map.csv' using 3 nooutput\n"
             "m = (abs(STATS_min) > abs(STATS_max) ? abs(STATS_min) : abs(STATS_max))\n"
             "set cbrange [-m:m]\n"
             "plot '%s/sphere_noh_map.csv' using 1:2:3 with image notitle\n"
             "set palette defined (0 'white', 1 'red')\nset cbrange [0:*]\n"
             "set title 'share of configurations where the step is worse'\n"
             "plot '%s/sphere_noh_map.csv' using 1:2:4 with image notitle\n"
             "unset multiplot\n",
             dir, dir, dir);
    snprintf(path, sizeof path, "%s/sphere_noh_map.png", dir);
    if (gnuplot_render(commands, path, 1200, 500, e) != 0 || write_by_nv(dir, s, err, n, e) != 0)
        goto done;
    /* Mean shortfall against n.v, averaged over the elevations too. */
    snprintf(commands, sizeof commands,
             "set datafile separator ','\nset key top right\nset logscale y\n"
             "set xlabel 'n.v'\nset ylabel 'mean shortfall of (N.H)^2 below the maximum'\n"
             "set title 'GetNoHSquared against the brute-force maximum'\n"
             "plot '%s/sphere_noh_by_nv.csv' using 1:2 with linespoints title 'Karis (0 steps)', "
             "'' using 1:3 with linespoints title '1 Newton step (Decima)', "
             "'' using 1:4 with linespoints title '2 Newton steps', "
             "'' using 1:5 with linespoints title \"1 step, guarded (f''(0) < 0)\"\n",
             dir);
    snprintf(path, sizeof path, "%s/sphere_noh_error.png", dir);
    rc = gnuplot_render(commands, path, 800, 500, e);
done:
    if (mem)
        fclose(mem);
    free(text), free(gain), free(worse), free(n), free(err);
    return rc;
}

static void summarise(long count, const float *best, const float *got, sphere_noh_stats *st, float *scratch)
{
    memset(st, 0, sizeof *st);
    st->configurations = count;
    long outside = 0;
    for (long i = 0; i < count; ++i)
        st->r_inside += got[NOH_METHODS * i] == 1.0f;
    for (int m = 0; m < NOH_METHODS; ++m) {
        outside = 0;
        for (long i = 0; i < count; ++i) {
            if (got[NOH_METHODS * i] == 1.0f)
                continue;
            double err = SHORT(best, got, i, m);
            scratch[outside++] = (float)err;
            st->mean[m] += err;
            st->worst[m] = fmax(st->worst[m], err);
            if (sphere_noh_baseline[m] >= 0) {
                double base = SHORT(best, got, i, sphere_noh_baseline[m]);
                st->share_worse[m] += err > base + 1e-6;
                st->share_better[m] += err < base - 1e-6;
            }
        }
        if (outside > 0) {
            st->mean[m] /= outside, st->share_worse[m] /= outside, st->share_better[m] /= outside;
        }
        st->p99[m] = percentile99(scratch, outside);
    }
}

int sphere_noh_sweep_run(const sphere_noh_sweep *s, const char *dir, sphere_noh_stats *stats, gt_error *e)
{
    long count = (long)s->nv_steps * s->theta_steps * s->phi_steps * s->size_steps;
    float *best = malloc((size_t)count * sizeof *best), *got = malloc((size_t)count * NOH_METHODS * sizeof *got);
    float *scratch = malloc((size_t)count * sizeof *scratch);
    int rc = -1;
    if (!best || !got || !scratch) {
        gt_error_set(e, dir, "out of memory");
        goto done;
    }
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
    char path[4096];
    snprintf(path, sizeof path, "%s/sphere_noh.csv", dir);
    if (write_csv(path, s, count, best, got, e) != 0 || write_map(dir, s, count, best, got, e) != 0)
        goto done;
    summarise(count, best, got, stats, scratch);
    rc = 0;
done:
    free(best), free(got), free(scratch);
    return rc;
}

static void print_help(void)
{
    printf("usage: gtlab check sphere-noh [-o DIR] [--steps N] [--rim-steps K]\n"
           "\n"
           "How close GetNoHSquared (Decima, SIGGRAPH 2017) comes to the largest (N.H)^2 over a\n"
           "spherical light: for every configuration of a grid over n.v, the light's elevation\n"
           "and azimuth and its angular size (tan(sigma) from 0.001 to 1), the shortfall below\n"
           "the brute-force maximum over the rim of Karis's point (0 Newton steps), the talk's\n"
           "one Newton step, two steps, and one step guarded (taken only where f''(0) < 0, i.e.\n"
           "where it heads for a maximum; not in the talk). Prints the mean, 99th percentile and worst case, and\n"
           "the share of configurations where a step makes things worse; writes\n"
           "  DIR/sphere_noh.csv        every configuration\n"
           "  DIR/sphere_noh_map.csv    means over (n.v, light elevation)\n"
           "  DIR/sphere_noh_map.png    where the step helps or hurts (and .gp scripts)\n"
           "  DIR/sphere_noh_by_nv.csv  mean shortfalls against n.v\n"
           "  DIR/sphere_noh_error.png  mean shortfall against n.v\n"
           "\n"
           "  -o, --output DIR   output folder (default sphere-noh)\n"
           "  --steps N          grid points per dimension (default 16: 65536 configurations)\n"
           "  --rim-steps K      brute-force angles on the rim before refinement (default 256)\n");
}

int check_sphere_noh(int argc, char **argv)
{
    static const struct option longs[] = {{"output", required_argument, 0, 'o'},
                                          {"steps", required_argument, 0, 's'},
                                          {"rim-steps", required_argument, 0, 'r'},
                                          {"help", no_argument, 0, 'h'},
                                          {0, 0, 0, 0}};
    const char *dir = "sphere-noh";
    long steps = 16, rim_steps = 256;
    int c;
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        switch (c) {
        case 'o': dir = optarg; break;
        case 's': if (cli_parse_int("--steps", optarg, 2, 64, &steps)) return EXIT_USER_ERROR; break;
        case 'r': if (cli_parse_int("--rim-steps", optarg, 16, 65536, &rim_steps)) return EXIT_USER_ERROR; break;
        case 'h': print_help(); return EXIT_OK;
        default: return cli_usage_error("check sphere-noh");
        }
    }
    if (optind < argc)
        return cli_failf("check sphere-noh", "unexpected argument '%s'", argv[optind]);
    if (mkdir(dir, 0755) != 0 && errno != EEXIST)
        return cli_failf(dir, "cannot create folder: %s", strerror(errno));
    sphere_noh_sweep sweep = {(int)steps, (int)steps, (int)steps, (int)steps, (int)rim_steps};
    sphere_noh_stats st;
    gt_error e;
    if (sphere_noh_sweep_run(&sweep, dir, &st, &e) != 0)
        return cli_fail(&e);
    printf("%ld configurations, R inside the light (exact, 1) in %ld\n", st.configurations, st.r_inside);
    printf("shortfall of (N.H)^2 below the brute-force maximum, R outside:\n");
    printf("%-22s %12s %12s %12s %14s %14s  (than)\n", "", "mean", "99th pct", "worst", "worse", "better");
    for (int m = 0; m < NOH_METHODS; ++m)
        printf("%-22s %12.4g %12.4g %12.4g %13.2f%% %13.2f%%  %s\n", sphere_noh_method_names[m], st.mean[m], st.p99[m],
               st.worst[m], 100.0 * st.share_worse[m], 100.0 * st.share_better[m],
               sphere_noh_baseline[m] >= 0 ? sphere_noh_method_names[sphere_noh_baseline[m]] : "");
    printf("written: %s/sphere_noh.csv, sphere_noh_map.csv, sphere_noh_map.png, sphere_noh_error.png\n", dir);
    return EXIT_OK;
}
