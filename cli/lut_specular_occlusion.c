/* gtlab lut specular-occlusion: the GTSO cone/lobe table
 * (luts/specular_occlusion_lut.h) in every format, with its accuracy. */
#define _GNU_SOURCE
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "core/progress.h"
#include "luts/lut_writers.h"
#include "luts/specular_occlusion_lut.h"
#include "luts/specular_occlusion_lut_writers.h"
#include "core/threads.h"

enum { INTERPOLATION_POINTS = 4096 };

static void print_help(void)
{
    printf("usage: gtlab lut specular-occlusion [--size N] [--lobe L] [--axes A] -o DIR\n"
           "\n"
           "Tabulates GTSO's cone/lobe specular occlusion V_s(a_v, beta, r): the fraction of\n"
           "the reflection lobe (at normal incidence, n = v = R) inside a visibility cone of\n"
           "half-angle a_v whose axis is beta from the reflection vector, for perceptual\n"
           "roughness r (GGX alpha = r^2), by adaptive Gauss-Kronrod quadrature.\n"
           "Writes DIR/specular_occlusion_<lobe>_<N>.exr (float), .png (8-bit, linear),\n"
           ".h (C array) and .json (axes, quadrature error estimate, interpolation error of\n"
           "trilinear lookup against direct integration at %d random points).\n"
           "\n"
           "options:\n"
           "  --size N        entries per axis, 2..256 (default 32; the talk: 32, or 16)\n"
           "  --lobe L        ggx (f_r cos, GTSO's definition; default), ggx-d (D cos, the\n"
           "                  talk's older definition) or phong (Phong NDF, p = 2/alpha^2 - 2)\n"
           "  --axes A        angles (a_v/(pi/2), beta/pi, r; default: lower interpolation\n"
           "                  error, see docs/decisions.md) or cosines (cos a_v,\n"
           "                  0.5 cos beta + 0.5, r: the talk's arguments)\n"
           "  --threads T     worker threads (default: all cores); the table does not depend on it\n"
           "  -o, --output DIR  output folder (created if absent)\n"
           "  -h, --help\n",
           INTERPOLATION_POINTS);
}

typedef struct {
    long size;
    so_lobe lobe;
    so_lut_axes axes;
    long threads;
    const char *dir;
} lut_options;

static int parse_name(const char *option, const char *text, const char *(*name)(int), int count, int *out)
{
    for (int i = 0; i < count; ++i)
        if (strcmp(text, name(i)) == 0) {
            *out = i;
            return 0;
        }
    return cli_failf(option, "unknown value '%s' (see --help)", text), -1;
}

static const char *lobe_name(int i) { return so_lobe_name((so_lobe)i); }
static const char *axes_name(int i) { return so_lut_axes_name((so_lut_axes)i); }

static int parse_options(int argc, char **argv, lut_options *o)
{
    static const struct option longs[] = {{"size", required_argument, 0, 'n'},   {"lobe", required_argument, 0, 'l'},
                                          {"axes", required_argument, 0, 'a'},   {"threads", required_argument, 0, 't'},
                                          {"output", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'},
                                          {0, 0, 0, 0}};
    int c, value;
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        switch (c) {
        case 'n': if (cli_parse_int("--size", optarg, 2, 256, &o->size)) return -1; break;
        case 'l':
            if (parse_name("--lobe", optarg, lobe_name, SO_LOBE_COUNT, &value)) return -1;
            o->lobe = (so_lobe)value;
            break;
        case 'a':
            if (parse_name("--axes", optarg, axes_name, SO_AXES_COUNT, &value)) return -1;
            o->axes = (so_lut_axes)value;
            break;
        case 't': if (cli_parse_int("--threads", optarg, 1, 1024, &o->threads)) return -1; break;
        case 'o': o->dir = optarg; break;
        case 'h': print_help(); return 1;
        default: return cli_usage_error("lut specular-occlusion"), -1;
        }
    }
    if (optind < argc)
        return cli_failf("lut specular-occlusion", "unexpected argument '%s'", argv[optind]), -1;
    if (!o->dir)
        return cli_failf("lut specular-occlusion", "-o/--output DIR is required"), -1;
    return 0;
}

int lut_specular_occlusion(int argc, char **argv)
{
    lut_options o = {32, SO_LOBE_GGX, SO_AXES_ANGLES, threads_default(), NULL};
    int parsed = parse_options(argc, argv, &o);
    if (parsed != 0)
        return parsed > 0 ? EXIT_OK : EXIT_USER_ERROR;
    if (mkdir(o.dir, 0777) != 0 && errno != EEXIST)
        return cli_failf(o.dir, "cannot create the folder: %s", strerror(errno));
    double start = seconds_now();
    so_lut lut;
    if (so_lut_build(&lut, (int)o.size, o.lobe, o.axes, (int)o.threads) != 0)
        return cli_failf("lut specular-occlusion", "out of memory");
    double seconds = seconds_now() - start, max_interp, rms_interp;
    so_lut_interpolation_error(&lut, INTERPOLATION_POINTS, 1u, (int)o.threads, &max_interp, &rms_interp);
    char base[128], identifier[128], path[4096], description[1024];
    snprintf(base, sizeof base, "specular_occlusion_%s_%ld", so_lobe_name(o.lobe), o.size);
    snprintf(identifier, sizeof identifier, "gtlab_specular_occlusion_%s_%ld", o.lobe == SO_LOBE_GGX_D ? "ggx_d"
             : so_lobe_name(o.lobe), o.size);
    snprintf(description, sizeof description, "GTSO cone/lobe specular occlusion, lobe %s (at n = v = R), size %ld, axes %s: %s",
             so_lobe_name(o.lobe), o.size, so_lut_axes_name(o.axes), so_lut_axes_description(o.axes));
    snprintf(path, sizeof path, "%s/%s.json", o.dir, base);
    gt_error e;
    int status = EXIT_OK;
    if (lut_write_all(o.dir, base, identifier, lut.data, (int)o.size, description, &e) != 0 ||
        so_lut_write_json(path, &lut, seconds, INTERPOLATION_POINTS, max_interp, rms_interp, &e) != 0)
        status = cli_fail(&e);
    else
        printf("%s/%s.{exr,png,h,json}: %ld^3 in %.2f s; quadrature error <= %.1e; trilinear error max %.2e, rms %.2e\n",
               o.dir, base, o.size, seconds, lut.max_error_estimate, max_interp, rms_interp);
    so_lut_free(&lut);
    return status;
}
