/* gtlab lut specular-occlusion: the GTSO cone/lobe table
 * (luts/specular_occlusion_lut.h) in every format, with its accuracy. */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "core/progress.h"
#include "luts/lut_writers.h"
#include "luts/specular_occlusion_lut.h"
#include "luts/specular_occlusion_lut_writers.h"
#include "core/threads.h"

enum { INTERPOLATION_POINTS = 4096 }; /* stated in the help text */

static const char *lobe_name(int i) { return so_lobe_name((so_lobe)i); }
static const char *axes_name(int i) { return so_lut_axes_name((so_lut_axes)i); }

static const cli_option options[] = {
    CLI_INT("size", "N", 2, 256, "entries per axis; the talk: 32, or 16"),
    CLI_CHOICE("lobe", "L", lobe_name, SO_LOBE_COUNT, "ggx (f_r cos, GTSO's definition), ggx-d (D cos, the\n"
               "talk's older definition) or phong (Phong NDF, p = 2/alpha^2 - 2)"),
    CLI_CHOICE("axes", "A", axes_name, SO_AXES_COUNT, "angles (a_v/(pi/2), beta/pi, r: lower interpolation\n"
               "error, see docs/decisions.md) or cosines (cos a_v,\n0.5 cos beta + 0.5, r: the talk's arguments)"),
    CLI_THREADS, CLI_OUTPUT_DIR, CLI_END};
static const cli_command command = {
    "lut specular-occlusion",
    "Tabulates GTSO's cone/lobe specular occlusion V_s(a_v, beta, r): the fraction of\n"
    "the reflection lobe (at normal incidence, n = v = R) inside a visibility cone of\n"
    "half-angle a_v whose axis is beta from the reflection vector, for perceptual\n"
    "roughness r (GGX alpha = r^2), by adaptive Gauss-Kronrod quadrature.\n"
    "Writes DIR/specular_occlusion_<lobe>_<N>.exr (float), .png (8-bit, linear),\n"
    ".h (C array) and .json (axes, quadrature error estimate, interpolation error of\n"
    "trilinear lookup against direct integration at 4096 random points).",
    options};

typedef struct {
    long size;
    int lobe, axes;
    long threads;
    const char *dir;
} lut_options;

int lut_specular_occlusion(int argc, char **argv)
{
    lut_options o = {32, SO_LOBE_GGX, SO_AXES_ANGLES, threads_default(), NULL};
    int status;
    if (cli_options_parse(&command, (void *[]){&o.size, &o.lobe, &o.axes, &o.threads, &o.dir}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(o.dir)) != 0)
        return status;
    double start = seconds_now();
    so_lut lut;
    if (so_lut_build(&lut, (int)o.size, (so_lobe)o.lobe, (so_lut_axes)o.axes, (int)o.threads) != 0)
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
    status = EXIT_OK;
    if (lut_write_all(o.dir, base, identifier, lut.data, (int)o.size, description, &e) != 0 ||
        so_lut_write_json(path, &lut, seconds, INTERPOLATION_POINTS, max_interp, rms_interp, &e) != 0)
        status = cli_fail(&e);
    else
        printf("%s/%s.{exr,png,h,json}: %ld^3 in %.2f s; quadrature error <= %.1e; trilinear error max %.2e, rms %.2e\n",
               o.dir, base, o.size, seconds, lut.max_error_estimate, max_interp, rms_interp);
    so_lut_free(&lut);
    return status;
}
