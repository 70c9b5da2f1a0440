/* The multi-bounce study's plot data (gnuplot reads them; cli draws the
 * plots): the samples, the models' curves and coefficients, all evaluated by
 * multibounce/multibounce.c, never re-typed in a plot script. */
#include <stdio.h>
#include <stdlib.h>

#include "core/files/atomic_file.h"
#include "multibounce/multibounce_parts.h"

enum { SCATTER_POINTS = 2500, CURVE_STEPS = 100 };

/* Per albedo (gnuplot index k): up to SCATTER_POINTS samples (V_d, V'_d),
 * taken at a regular stride over every scene. */
static int write_scatter_data(const multibounce_data *d, const char *path, gt_error *e)
{
    size_t size = (size_t)d->albedo_count * (SCATTER_POINTS + 8) * 32 + 1024, used = 0;
    char *text = malloc(size);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    used += (size_t)snprintf(text, size, "# V_d V'_d, one block per albedo (gtlab all)\n");
    for (int k = 0; k < d->albedo_count; ++k) {
        size_t in_albedo = 0, taken = 0;
        for (size_t i = 0; i < d->count; ++i)
            in_albedo += d->samples[i].albedo_index == k;
        size_t stride = in_albedo / SCATTER_POINTS + 1, seen = 0;
        for (size_t i = 0; i < d->count && taken < SCATTER_POINTS; ++i) {
            const multibounce_sample *s = &d->samples[i];
            if (s->albedo_index != k || seen++ % stride != 0)
                continue;
            used += (size_t)snprintf(text + used, size - used, "%.5f %.5f\n", (double)s->visibility,
                                     (double)s->multibounce);
            ++taken;
        }
        used += (size_t)snprintf(text + used, size - used, "\n\n");
    }
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

/* Per albedo: x, the talk's curve, ours (joint), the albedo's own cubic — all
 * evaluated by multibounce/multibounce.c, never re-typed in gnuplot. */
static int write_curve_data(const multibounce_data *d, const multibounce_analysis *a, const char *path, gt_error *e)
{
    size_t size = (size_t)d->albedo_count * (CURVE_STEPS + 4) * 64 + 256, used = 0;
    char *text = malloc(size);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    const multibounce_model talk = multibounce_model_jimenez2016();
    used += (size_t)snprintf(text, size, "# V_d talk gtlab_joint per_albedo_cubic, one block per albedo\n");
    for (int k = 0; k < d->albedo_count; ++k) {
        float rho = d->albedos[k];
        for (int i = 0; i <= CURVE_STEPS; ++i) {
            double x = (double)i / CURVE_STEPS;
            used += (size_t)snprintf(text + used, size - used, "%.4f %.6f %.6f %.6f\n", x,
                                     gtao_multibounce(&talk, x, rho), gtao_multibounce(&a->joint[MB_JOINT_LINEAR].model, x, rho),
                                     gtao_multibounce(&a->per_albedo[k].fit.model, x, rho));
        }
        used += (size_t)snprintf(text + used, size - used, "\n\n");
    }
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

/* Block 0: per-albedo a, b, c with standard errors; block 1: the joint
 * models' a, b, c over rho in [0, 1] (ours linear, talk, ours quadratic,
 * ours anchored; a model the data cannot determine repeats the linear). */
static int write_coefficient_data(const multibounce_data *d, const multibounce_analysis *a, const char *path,
                                  gt_error *e)
{
    size_t size = (size_t)(d->albedo_count + CURVE_STEPS + 8) * 200, used = 0;
    char *text = malloc(size);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    used += (size_t)snprintf(text, size, "# rho a se_a b se_b c se_c (per-albedo fits)\n");
    for (int k = 0; k < d->albedo_count; ++k) {
        const multibounce_fit *f = &a->per_albedo[k].fit;
        used += (size_t)snprintf(text + used, size - used, "%.3f %.6f %.6f %.6f %.6f %.6f %.6f\n",
                                 (double)d->albedos[k], f->model.a[0], f->standard_errors[0], f->model.b[0],
                                 f->standard_errors[1], f->model.c[0], f->standard_errors[2]);
    }
    used += (size_t)snprintf(text + used, size - used,
                             "\n\n# rho a b c (ours linear) a b c (talk) a b c (ours quadratic) a b c (ours anchored)\n");
    const multibounce_model talk = multibounce_model_jimenez2016();
    const multibounce_model *models[4] = {&a->joint[MB_JOINT_LINEAR].model, &talk,
                                          &a->joint[a->has[MB_JOINT_QUADRATIC] ? MB_JOINT_QUADRATIC : 0].model,
                                          &a->joint[MB_JOINT_ANCHORED].model};
    for (int i = 0; i <= CURVE_STEPS; ++i) {
        double rho = (double)i / CURVE_STEPS;
        used += (size_t)snprintf(text + used, size - used, "%.3f", rho);
        for (int m = 0; m < 4; ++m) {
            multibounce_cubic c = multibounce_cubic_at(models[m], rho);
            used += (size_t)snprintf(text + used, size - used, " %.6f %.6f %.6f", c.a, c.b, c.c);
        }
        used += (size_t)snprintf(text + used, size - used, "\n");
    }
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

int multibounce_write_plot_data(const multibounce_data *d, const multibounce_analysis *a, const char *figures,
                                gt_error *e)
{
    char points[4096], curves[4096], coefficients[4096];
    snprintf(points, sizeof points, "%s/%s", figures, MULTIBOUNCE_SCATTER_DATA);
    snprintf(curves, sizeof curves, "%s/%s", figures, MULTIBOUNCE_CURVES_DATA);
    snprintf(coefficients, sizeof coefficients, "%s/%s", figures, MULTIBOUNCE_COEFFICIENTS_DATA);
    if (write_scatter_data(d, points, e) != 0 || write_curve_data(d, a, curves, e) != 0)
        return -1;
    return write_coefficient_data(d, a, coefficients, e);
}
