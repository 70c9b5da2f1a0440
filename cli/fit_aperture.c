/* gtlab fit aperture: the GTSO talk's gloss-to-aperture parameter u, found
 * as the talk did, by DSSIM of cone/cone specular-occlusion images against
 * Monte Carlo references (cli/fit_aperture.h describes the search). */
#define _GNU_SOURCE
#include "cli/fit_aperture.h"

#include <cjson/cJSON.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/gnuplot_plot.h"
#include "core/atomic_file.h"
#include "core/exr_io.h"
#include "metrics/ssim.h"
#include "core/reference_schema.h"

static const double SCAN_LO = -12.0, SCAN_HI = -0.05, SCAN_STEP = 0.125, GOLDEN_TOLERANCE = 1e-3;

int aperture_case_init(aperture_case *c, const image *reference, const char *what_reference, const image *ao,
                       const char *what_ao, const char *channel, gt_error *e)
{
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", what_reference);
    if (!(c->reference = image_channel_data(reference, channel)))
        return gt_error_set(e, what_reference, "no channel %s (not a specular-occlusion reference?)", channel);
    return so_inputs_from_images(reference, what_reference, ao, what_ao, so_reference_roughness(reference), &c->inputs, e);
}

void aperture_case_free(aperture_case *c) { so_inputs_free(&c->inputs); }

typedef struct {
    const aperture_case *cases;
    int count, exact;
    float *scratch;
    aperture_fit *fit;
} objective;

static double mean_dssim(objective *o, double log10_u, gt_error *e, int *failed)
{
    so_variant v = {o->exact ? SO_VARIANT_CONE_EXACT : SO_VARIANT_CONE_OAT, SO_APERTURE_PHONG_U, pow(10.0, log10_u),
                    SO_AO_COSINE, NULL};
    double total = 0.0;
    for (int i = 0; i < o->count; ++i) {
        const so_pixel_inputs *in = &o->cases[i].inputs;
        so_approx_evaluate(in, &v, o->scratch);
        ssim_result r;
        if (ssim_compute(o->cases[i].reference, o->scratch, in->mask, in->width, in->height, o->cases[i].name, NULL,
                         &r, e) != 0) {
            *failed = 1;
            return NAN;
        }
        total += r.dssim;
    }
    o->fit->evaluations++;
    return total / o->count;
}

static void add_point(aperture_fit *fit, double log10_u, double dssim)
{
    if (fit->curve_count >= APERTURE_CURVE_MAX)
        return;
    int i = fit->curve_count++;
    double u = pow(10.0, log10_u);
    while (i > 0 && fit->curve_u[i - 1] > u) {
        fit->curve_u[i] = fit->curve_u[i - 1], fit->curve_dssim[i] = fit->curve_dssim[i - 1];
        --i;
    }
    fit->curve_u[i] = u, fit->curve_dssim[i] = dssim;
}

int aperture_fit_run(const aperture_case *cases, int count, int exact, aperture_fit *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    size_t largest = 0;
    for (int i = 0; i < count; ++i)
        largest = fmax(largest, (size_t)cases[i].inputs.width * cases[i].inputs.height);
    objective o = {cases, count, exact, malloc(sizeof(float) * largest), out};
    if (!o.scratch)
        return gt_error_set(e, "fit aperture", "out of memory");
    int failed = 0, best = 0, scan_count = (int)floor((SCAN_HI - SCAN_LO) / SCAN_STEP + 1e-9) + 1;
    double scan[APERTURE_CURVE_MAX];
    for (int i = 0; i < scan_count && !failed; ++i) {
        scan[i] = mean_dssim(&o, SCAN_LO + i * SCAN_STEP, e, &failed);
        add_point(out, SCAN_LO + i * SCAN_STEP, scan[i]);
        if (scan[i] < scan[best])
            best = i;
    }
    /* golden section in the bracket around the scan's minimum */
    double a = SCAN_LO + fmax(best - 1, 0) * SCAN_STEP, b = SCAN_LO + fmin(best + 1, scan_count - 1) * SCAN_STEP;
    const double ratio = 0.5 * (sqrt(5.0) - 1.0);
    double x1 = b - ratio * (b - a), x2 = a + ratio * (b - a);
    double f1 = failed ? 0 : mean_dssim(&o, x1, e, &failed), f2 = failed ? 0 : mean_dssim(&o, x2, e, &failed);
    while (!failed && b - a > GOLDEN_TOLERANCE) {
        if (f1 <= f2) {
            b = x2, x2 = x1, f2 = f1, x1 = b - ratio * (b - a);
            f1 = mean_dssim(&o, x1, e, &failed);
        } else {
            a = x1, x1 = x2, f1 = f2, x2 = a + ratio * (b - a);
            f2 = mean_dssim(&o, x2, e, &failed);
        }
    }
    if (!failed) {
        double x = f1 <= f2 ? x1 : x2, f = fmin(f1, f2);
        if (scan[best] < f) /* the scan point itself was better than the bracket's interior */
            x = SCAN_LO + best * SCAN_STEP, f = scan[best];
        out->log10_u = x, out->u = pow(10.0, x), out->dssim = f;
        out->dssim_at_published = mean_dssim(&o, -2.0, e, &failed);
    }
    free(o.scratch);
    return failed ? -1 : 0;
}

/* ---- the verb ------------------------------------------------------------------ */

enum { MAX_CASES = 32 };

static void print_help(void)
{
    printf("usage: gtlab fit aperture --reference SO.exr --ao AO.exr [--reference ... --ao ...] -o fit.json\n"
           "\n"
           "Finds the GTSO talk's gloss-to-aperture parameter u (a_s = arccos(u^(1/(p+2))),\n"
           "p = 2/alpha^2 - 2) as the talk did: the u whose cone/cone specular-occlusion\n"
           "images have the lowest mean DSSIM against the Monte Carlo references. DSSIM is not\n"
           "smooth in u, so the search scans log10 u over [-12, -0.05] by 1/8 decade, then\n"
           "refines by golden section (to 1e-3 in log10 u). The talk found u = 0.01.\n"
           "\n"
           "options:\n"
           "  --reference F.exr   a 'gtlab render specular-occlusion' output (repeat for several)\n"
           "  --ao F.exr          the 'gtlab render ao' output of the same view (one per --reference)\n"
           "  --definition D      gtso (specocc.V, GGX f_r-weighted; default), d-only\n"
           "                      (specocc_d.V, the talk's older GGX D-weighted definition) or\n"
           "                      phong (specocc_phong.V, Phong-NDF-weighted, as the talk fitted)\n"
           "  --intersection I    exact (default) or oat (Oat 2007's approximation)\n"
           "  --plot F.png        the DSSIM-vs-u curve (gnuplot)\n"
           "  -o, --output F.json u, its DSSIM, the DSSIM at the talk's u = 0.01, and the curve\n"
           "  -h, --help\n");
}

typedef struct {
    const char *references[MAX_CASES], *aos[MAX_CASES], *output, *plot;
    int reference_count, ao_count, exact;
    const char *channel;
} fit_options;

static int parse_options(int argc, char **argv, fit_options *o)
{
    static const struct option longs[] = {{"reference", required_argument, 0, 'r'}, {"ao", required_argument, 0, 'a'},
                                          {"definition", required_argument, 0, 'd'}, {"intersection", required_argument, 0, 'i'},
                                          {"plot", required_argument, 0, 'p'},      {"output", required_argument, 0, 'o'},
                                          {"help", no_argument, 0, 'h'},            {0, 0, 0, 0}};
    int c;
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        switch (c) {
        case 'r':
            if (o->reference_count == MAX_CASES) return cli_failf("--reference", "at most %d", MAX_CASES), -1;
            o->references[o->reference_count++] = optarg;
            break;
        case 'a':
            if (o->ao_count == MAX_CASES) return cli_failf("--ao", "at most %d", MAX_CASES), -1;
            o->aos[o->ao_count++] = optarg;
            break;
        case 'd':
            if (strcmp(optarg, "gtso") == 0) o->channel = CH_SPECOCC;
            else if (strcmp(optarg, "d-only") == 0) o->channel = CH_SPECOCC_D;
            else if (strcmp(optarg, "phong") == 0) o->channel = CH_SPECOCC_PHONG;
            else return cli_failf("--definition", "'%s' is not gtso, d-only or phong", optarg), -1;
            break;
        case 'i':
            if (strcmp(optarg, "exact") == 0) o->exact = 1;
            else if (strcmp(optarg, "oat") == 0) o->exact = 0;
            else return cli_failf("--intersection", "'%s' is neither exact nor oat", optarg), -1;
            break;
        case 'p': o->plot = optarg; break;
        case 'o': o->output = optarg; break;
        case 'h': print_help(); return 1;
        default: return cli_usage_error("fit aperture"), -1;
        }
    }
    if (optind < argc)
        return cli_failf("fit aperture", "unexpected argument '%s'", argv[optind]), -1;
    if (o->reference_count == 0 || o->reference_count != o->ao_count)
        return cli_failf("fit aperture", "give one --ao per --reference (at least one pair)"), -1;
    if (!o->output)
        return cli_failf("fit aperture", "-o/--output is required"), -1;
    return 0;
}

cJSON *aperture_fit_json(const aperture_fit *fit, const char *channel, int exact)
{
    cJSON *j = cJSON_CreateObject();
    cJSON_AddStringToObject(j, "problem", "aperture");
    cJSON_AddStringToObject(j, "reference_channel", channel);
    cJSON_AddStringToObject(j, "intersection", exact ? "exact" : "oat");
    cJSON_AddStringToObject(j, "search", "scan of log10 u by 1/8 decade, then golden section to 1e-3");
    cJSON_AddNumberToObject(j, "u", fit->u);
    cJSON_AddNumberToObject(j, "log10_u", fit->log10_u);
    cJSON_AddNumberToObject(j, "mean_dssim", fit->dssim);
    cJSON_AddNumberToObject(j, "mean_dssim_at_talk_u_0.01", fit->dssim_at_published);
    cJSON_AddNumberToObject(j, "evaluations", fit->evaluations);
    cJSON *curve = cJSON_AddArrayToObject(j, "curve");
    for (int i = 0; i < fit->curve_count; ++i) {
        cJSON *p = cJSON_CreateObject();
        cJSON_AddNumberToObject(p, "u", fit->curve_u[i]);
        cJSON_AddNumberToObject(p, "mean_dssim", fit->curve_dssim[i]);
        cJSON_AddItemToArray(curve, p);
    }
    return j;
}

/* The DSSIM-vs-u curve on a log axis, the fitted u marked; the points go
 * inline as a gnuplot datablock so the kept .gp script reruns alone. */
int aperture_fit_plot(const aperture_fit *fit, const char *path, const char *title, gt_error *e)
{
    char *script = NULL;
    size_t size = 0;
    FILE *mem = open_memstream(&script, &size);
    if (!mem)
        return gt_error_set(e, path, "out of memory");
    fprintf(mem, "$curve << EOD\n");
    for (int i = 0; i < fit->curve_count; ++i)
        fprintf(mem, "%.9g %.9g\n", fit->curve_u[i], fit->curve_dssim[i]);
    fprintf(mem,
            "EOD\nset termoption noenhanced\nset title \"%s\"\nset xlabel 'u'\nset ylabel 'mean DSSIM vs reference'\n"
            "set grid\nset logscale x\nset arrow from %.9g, graph 0 to %.9g, graph 1 nohead dt 2\n"
            "set label 'fitted u' at %.9g, graph 0.95\nplot $curve using 1:2 with linespoints notitle\n",
            title, fit->u, fit->u, fit->u);
    fclose(mem);
    int rc = gnuplot_render(script, path, 800, 500, e);
    free(script);
    return rc;
}

static int load_cases(const fit_options *o, image *refs, image *aos, aperture_case *cases, int *loaded, gt_error *e)
{
    for (int i = 0; i < o->reference_count; ++i) {
        if (exr_read(o->references[i], &refs[i], e) != 0)
            return -1;
        if (exr_read(o->aos[i], &aos[i], e) != 0) {
            image_free(&refs[i]);
            return -1;
        }
        *loaded = i + 1;
        if (aperture_case_init(&cases[i], &refs[i], o->references[i], &aos[i], o->aos[i], o->channel, e) != 0)
            return -1;
    }
    return 0;
}

int fit_aperture(int argc, char **argv)
{
    fit_options o = {.exact = 1, .channel = CH_SPECOCC};
    int parsed = parse_options(argc, argv, &o);
    if (parsed != 0)
        return parsed > 0 ? EXIT_OK : EXIT_USER_ERROR;
    gt_error e;
    if (atomic_file_check_writable(o.output, &e) != 0)
        return cli_fail(&e);
    static image refs[MAX_CASES], aos[MAX_CASES];
    static aperture_case cases[MAX_CASES];
    int loaded = 0, status = EXIT_OK;
    aperture_fit fit;
    if (load_cases(&o, refs, aos, cases, &loaded, &e) != 0 || aperture_fit_run(cases, loaded, o.exact, &fit, &e) != 0) {
        status = cli_fail(&e);
    } else {
        cJSON *j = aperture_fit_json(&fit, o.channel, o.exact);
        char *text = cJSON_Print(j);
        cJSON_Delete(j);
        if (!text || atomic_write_text(o.output, text, &e) != 0 ||
            (o.plot && aperture_fit_plot(&fit, o.plot, "GTSO gloss-to-aperture: DSSIM against u", &e) != 0))
            status = cli_fail(&e);
        else
            printf("u = %.4g (log10 u = %.3f): mean DSSIM %.5f; at the talk's u = 0.01: %.5f (%d evaluations)\n", fit.u,
                   fit.log10_u, fit.dssim, fit.dssim_at_published, fit.evaluations);
        free(text);
    }
    for (int i = 0; i < loaded; ++i) {
        aperture_case_free(&cases[i]);
        image_free(&refs[i]);
        image_free(&aos[i]);
    }
    return status;
}
