#include "specular_occlusion/aperture_fit.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "metrics/ssim.h"

static const double SCAN_LO = -12.0, SCAN_HI = -0.05, SCAN_STEP = 0.125, GOLDEN_TOLERANCE = 1e-3;

void aperture_case_free(aperture_case *c) { so_inputs_free(&c->inputs); }

const char *aperture_region_name(aperture_region r)
{
    static const char *const names[APERTURE_REGIONS] = {"grazing", "occluded", "open"};
    return (int)r >= 0 && r < APERTURE_REGIONS ? names[r] : "unknown";
}

static aperture_region region_of(const so_pixel_inputs *in, size_t p)
{
    if (in->n_dot_v[p] < APERTURE_GRAZING_NV)
        return APERTURE_GRAZING;
    return in->ao_cosine[p] < APERTURE_OCCLUDED_AO ? APERTURE_OCCLUDED : APERTURE_OPEN;
}

/* Adds the squared errors of one case's surface pixels to their regions. */
static void add_region_errors(const so_pixel_inputs *in, const float *reference, const float *approx,
                              double squares[APERTURE_REGIONS], long counts[APERTURE_REGIONS])
{
    for (size_t p = 0; p < (size_t)in->width * in->height; ++p) {
        if (in->mask[p] == 0.0f)
            continue;
        aperture_region r = region_of(in, p);
        double d = (double)approx[p] - reference[p];
        squares[r] += d * d, counts[r]++;
    }
}

typedef struct {
    const aperture_case *cases;
    int count, exact;
    so_aperture_mapping mapping;
    float *scratch;
    aperture_fit *fit;
} objective;

/* The mean DSSIM over the cases at u = 10^log10_u; with `curve` >= 0 also
 * the regions' RMSE at that scan point. */
static double mean_dssim_at(objective *o, double log10_u, int curve, gt_error *e, int *failed)
{
    double squares[APERTURE_REGIONS] = {0};
    long counts[APERTURE_REGIONS] = {0};
    so_variant v = {o->exact ? SO_VARIANT_CONE_EXACT : SO_VARIANT_CONE_OAT, o->mapping, pow(10.0, log10_u),
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
        if (curve >= 0)
            add_region_errors(in, o->cases[i].reference, o->scratch, squares, counts);
    }
    for (int k = 0; k < APERTURE_REGIONS && curve >= 0; ++k) {
        o->fit->curve_region_rmse[k][curve] = counts[k] ? sqrt(squares[k] / counts[k]) : NAN;
        o->fit->region_pixels[k] = counts[k];
    }
    o->fit->evaluations++;
    return total / o->count;
}

static double mean_dssim(objective *o, double log10_u, gt_error *e, int *failed)
{
    return mean_dssim_at(o, log10_u, -1, e, failed);
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

/* The scan of log10 u (each point also on the curve); returns the index of its minimum. */
static int scan(objective *o, double *values, int *count, gt_error *e, int *failed)
{
    int best = 0;
    *count = (int)floor((SCAN_HI - SCAN_LO) / SCAN_STEP + 1e-9) + 1;
    for (int i = 0; i < *count && !*failed; ++i) {
        values[i] = mean_dssim_at(o, SCAN_LO + i * SCAN_STEP, i, e, failed);
        add_point(o->fit, SCAN_LO + i * SCAN_STEP, values[i]);
        if (values[i] < values[best])
            best = i;
    }
    return best;
}

/* Each region's lowest RMSE along the scan. */
static void region_minima(aperture_fit *fit)
{
    for (int k = 0; k < APERTURE_REGIONS; ++k) {
        int best = 0;
        for (int i = 1; i < fit->curve_count; ++i)
            if (fit->curve_region_rmse[k][i] < fit->curve_region_rmse[k][best])
                best = i;
        fit->region_best_u[k] = fit->curve_u[best];
    }
}

/* Golden-section search for the minimum in [a, b] to GOLDEN_TOLERANCE: the
 * better of its last two points into *x, *f. */
static void golden_section(objective *o, double a, double b, double *x, double *f, gt_error *e, int *failed)
{
    const double ratio = 0.5 * (sqrt(5.0) - 1.0);
    double x1 = b - ratio * (b - a), x2 = a + ratio * (b - a);
    double f1 = *failed ? 0 : mean_dssim(o, x1, e, failed), f2 = *failed ? 0 : mean_dssim(o, x2, e, failed);
    while (!*failed && b - a > GOLDEN_TOLERANCE) {
        if (f1 <= f2) {
            b = x2, x2 = x1, f2 = f1, x1 = b - ratio * (b - a);
            f1 = mean_dssim(o, x1, e, failed);
        } else {
            a = x1, x1 = x2, f1 = f2, x2 = a + ratio * (b - a);
            f2 = mean_dssim(o, x2, e, failed);
        }
    }
    *x = f1 <= f2 ? x1 : x2, *f = fmin(f1, f2);
}

/* The scan, then golden section between the scan minimum's neighbours. */
static void search(objective *o, aperture_fit *out, gt_error *e, int *failed)
{
    double values[APERTURE_CURVE_MAX], x, f;
    int count, best = scan(o, values, &count, e, failed);
    region_minima(out);
    double a = SCAN_LO + fmax(best - 1, 0) * SCAN_STEP, b = SCAN_LO + fmin(best + 1, count - 1) * SCAN_STEP;
    golden_section(o, a, b, &x, &f, e, failed);
    if (*failed)
        return;
    if (values[best] < f) /* the scan point itself was better than the bracket's interior */
        x = SCAN_LO + best * SCAN_STEP, f = values[best];
    out->log10_u = x, out->u = pow(10.0, x), out->dssim = f;
    out->at_range_edge = x <= SCAN_LO + SCAN_STEP || x >= SCAN_HI - SCAN_STEP;
    out->dssim_at_published = mean_dssim(o, -2.0, e, failed);
}

int aperture_fit_run(const aperture_case *cases, int count, so_aperture_mapping mapping, int exact, aperture_fit *out,
                     gt_error *e)
{
    if (!so_aperture_takes_u(mapping))
        return gt_error_set(e, "fit aperture", "the mapping %s has no parameter u", so_aperture_name(mapping));
    memset(out, 0, sizeof *out);
    out->mapping = mapping;
    size_t largest = 0;
    for (int i = 0; i < count; ++i)
        largest = fmax(largest, (size_t)cases[i].inputs.width * cases[i].inputs.height);
    objective o = {cases, count, exact, mapping, malloc(sizeof(float) * largest), out};
    if (!o.scratch)
        return gt_error_set(e, "fit aperture", "out of memory");
    int failed = 0;
    search(&o, out, e, &failed);
    free(o.scratch);
    return failed ? -1 : 0;
}
