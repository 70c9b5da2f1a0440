/* A user's functions and plug-ins scored for any quantity
 * (scoring/function_score.h). */
#include "scoring/function_score.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/path_name.h"
#include "plugins/plugin_loader.h"

struct function_scorer {
    const function_score_quantity *quantity;
    const function_score_files *files;
    int builtins;                              /* the variants before the files */
    char *text[FUNCTION_SCORE_MAX_FILES];      /* the function files' texts */
    gtlab_plugin plugin[FUNCTION_SCORE_MAX_FILES];
    gpu_device *device;                        /* opened for the first function file */
    double timeout;
};

static void name_variant(function_score_result *out, const char *name, const char *kind)
{
    function_score_variant *v = &out->variants[out->variant_count++];
    snprintf(v->name, sizeof v->name, "%s", name);
    v->kind = kind;
}

void function_score_add_builtin(function_score_result *out, const char *name) { name_variant(out, name, "gtlab"); }

int function_score_check_files(const function_score_files *f, gt_error *e)
{
    if (f->function_count + f->plugin_count == 0)
        return gt_error_set(e, "shader score", "nothing to score: give --function F.glsl|F.hlsl or --plugin LIB.so");
    if (f->function_count > FUNCTION_SCORE_MAX_FILES || f->plugin_count > FUNCTION_SCORE_MAX_FILES)
        return gt_error_set(e, "shader score", "at most %d function files and %d plug-ins", FUNCTION_SCORE_MAX_FILES,
                            FUNCTION_SCORE_MAX_FILES);
    return 0;
}

/* Function file i's text, checked against the contract now (before any work). */
static int load_function(function_scorer *s, int i, function_score_result *out, gt_error *e)
{
    const char *path = s->files->functions[i];
    name_variant(out, path_file_name(path), "function");
    if (gpu_function_load(s->quantity->function, path, &s->text[i], e) != 0 ||
        (!s->device && gpu_device_open(s->files->device, &s->device, e) != 0))
        return -1;
    snprintf(out->device, sizeof out->device, "%s", gpu_device_name(s->device));
    return 0;
}

static int load_plugin(function_scorer *s, int i, function_score_result *out, gt_error *e)
{
    const char *path = s->files->plugins[i];
    name_variant(out, path_file_name(path), "plug-in");
    if (plugin_open(path, &s->plugin[i], e) != 0)
        return -1;
    if (!plugin_exports(&s->plugin[i], s->quantity->plugin_symbol))
        return gt_error_set(e, path, "exports no %s (%s, core/plugin_abi.h)", s->quantity->plugin_symbol,
                            s->quantity->name);
    return 0;
}

int function_scorer_open(const function_score_quantity *q, const function_score_files *f, function_score_result *out,
                         function_scorer **s, gt_error *e)
{
    if (!(*s = calloc(1, sizeof **s)))
        return gt_error_set(e, "shader score", "out of memory");
    **s = (function_scorer){.quantity = q, .files = f, .builtins = out->variant_count,
                            .timeout = f->timeout > 0.0 ? f->timeout : 10.0};
    for (int i = 0; i < f->function_count; ++i)
        if (load_function(*s, i, out, e) != 0)
            return -1;
    for (int i = 0; i < f->plugin_count; ++i)
        if (load_plugin(*s, i, out, e) != 0)
            return -1;
    return 0;
}

void function_scorer_close(function_scorer *s)
{
    if (!s)
        return;
    for (int i = 0; i < FUNCTION_SCORE_MAX_FILES; ++i) {
        free(s->text[i]);
        plugin_close(&s->plugin[i]);
    }
    if (s->device)
        gpu_device_close(s->device);
    free(s);
}

int function_scorer_apply(const function_scorer *s, int k, const float *const planes[], const float constants[],
                          const float *mask, size_t n, float *out, gt_error *e)
{
    const function_score_quantity *q = s->quantity;
    int i = k - s->builtins;
    if (i < s->files->function_count)
        return gpu_function_eval_masked(s->device, q->function, s->text[i], s->files->functions[i], planes, constants,
                                        mask, n, out, s->timeout, e);
    i -= s->files->function_count;
    return plugin_apply(&s->plugin[i], q->plugin_symbol, q->function->inputs, planes, constants, mask, n, out,
                        s->files->plugins[i], e);
}

void function_score_take_means(function_score_result *out)
{
    function_score_row *m = &out->mean;
    memset(m, 0, sizeof *m);
    snprintf(m->scene, sizeof m->scene, "mean");
    m->value = NAN;
    for (int r = 0; r < out->row_count; ++r) {
        const function_score_row *row = &out->rows[r];
        m->noise_floor_dssim += row->noise_floor_dssim / out->row_count;
        m->noise_floor_rmse += row->noise_floor_rmse / out->row_count;
        for (int k = 0; k < out->variant_count; ++k)
            m->dssim[k] += row->dssim[k] / out->row_count, m->rmse[k] += row->rmse[k] / out->row_count;
    }
    for (int k = 0; k < out->variant_count; ++k) {
        function_score_variant *v = &out->variants[k];
        v->dssim = m->dssim[k], v->rmse = m->rmse[k];
        v->dssim_floor = m->noise_floor_dssim, v->rmse_floor = m->noise_floor_rmse;
    }
}

/* The parameter column's width: 6, or its name's. */
static int parameter_width(const function_score_result *r)
{
    int n = (int)strlen(r->parameter);
    return n > 6 ? n : 6;
}

static void print_row(FILE *f, const function_score_result *r, const function_score_row *row)
{
    int width = parameter_width(r);
    char value[32];
    snprintf(value, sizeof value, "%*s", width, "-");
    if (!isnan(row->value))
        snprintf(value, sizeof value, "%*.2f", width, row->value);
    fprintf(f, "%-20.20s %s  %12.3e", row->scene, value, row->noise_floor_dssim);
    for (int k = 0; k < r->variant_count; ++k)
        fprintf(f, " %12.3e", row->dssim[k]);
    fprintf(f, "  %12.5f", row->noise_floor_rmse);
    for (int k = 0; k < r->variant_count; ++k)
        fprintf(f, " %12.5f", row->rmse[k]);
    fputc('\n', f);
}

void function_score_print(FILE *f, const function_score_result *r)
{
    fprintf(f, "%s%s%s\n", r->caption, r->device[0] ? "; functions on " : "", r->device);
    fprintf(f, "%-20s %*s  %12s", "scene", parameter_width(r), r->parameter, "DSSIM floor");
    for (int k = 0; k < r->variant_count; ++k)
        fprintf(f, " %12.12s", r->variants[k].name);
    fprintf(f, "  %12s", "RMSE floor");
    for (int k = 0; k < r->variant_count; ++k)
        fprintf(f, " %12.12s", r->variants[k].name);
    fputc('\n', f);
    for (int i = 0; i < r->row_count; ++i)
        print_row(f, r, &r->rows[i]);
    print_row(f, r, &r->mean);
}
