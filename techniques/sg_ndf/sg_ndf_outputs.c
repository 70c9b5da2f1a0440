/* The SG NDF study's tables: lobes as JSON and as a C header, and the error
 * curves as a gnuplot data file (one index per material). */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/atomic_file.h"
#include "sg_ndf/sg_ndf_parts.h"

void sg_ndf_material_name(const anisotropic_ndf *ndf, char *out, size_t size)
{
    snprintf(out, size, "%s_%.2f_%.2f", ndf_kind_name(ndf->kind), ndf->alpha_x, ndf->alpha_y);
}

static cJSON *lobe_json(const sg_fit *f, int j)
{
    cJSON *l = cJSON_CreateObject();
    const spherical_gaussian *g = &f->lobes[j];
    cJSON_AddItemToObject(l, "axis", cJSON_CreateDoubleArray(g->axis, 3));
    cJSON_AddNumberToObject(l, "sharpness", g->sharpness);
    cJSON_AddNumberToObject(l, "amplitude", g->amplitude);
    cJSON_AddItemToObject(l, "gnomonic_ab", cJSON_CreateDoubleArray(f->params + SG_NDF_LOBE_PARAMS * j, 2));
    if (f->has_stderr)
        cJSON_AddItemToObject(l, "stderr_a_b_sharpness_amplitude",
                              cJSON_CreateDoubleArray(f->stderr_ + SG_NDF_LOBE_PARAMS * j, SG_NDF_LOBE_PARAMS));
    return l;
}

static cJSON *fit_json(const sg_fit *f)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddNumberToObject(o, "k", f->lobe_count);
    cJSON_AddStringToObject(o, "status", sg_fit_status_name(f->status));
    cJSON_AddStringToObject(o, "note", f->note);
    if (f->status == SG_FIT_NOT_RUN)
        return o;
    cJSON_AddNumberToObject(o, "l2_error", f->l2_error);
    cJSON_AddNumberToObject(o, "max_error", f->max_error);
    cJSON_AddNumberToObject(o, "projected_area", f->projected_area);
    cJSON *lobes = cJSON_AddArrayToObject(o, "lobes");
    for (int j = 0; j < f->lobe_count; ++j)
        cJSON_AddItemToArray(lobes, lobe_json(f, j));
    return o;
}

static int write_json(const char *dir, const sg_ndf_result *r, gt_error *e)
{
    cJSON *root = cJSON_CreateObject(), *mats = cJSON_AddArrayToObject(root, "materials");
    cJSON_AddStringToObject(root, "model", "D(m) ~ sum_j amplitude_j exp(sharpness_j (m.axis_j - 1)), m in the "
                                           "tangent frame (x = tangent, alpha_x; z = normal)");
    cJSON_AddStringToObject(root, "objective", "min int (S - D)^2 dm / int D^2 dm over the hemisphere (solid angle)");
    for (int i = 0; i < r->request.material_count; ++i) {
        const sg_ndf_material *m = &r->materials[i];
        cJSON *o = cJSON_CreateObject(), *fits = cJSON_AddArrayToObject(o, "fits");
        cJSON_AddStringToObject(o, "ndf", ndf_kind_name(m->ndf.kind));
        cJSON_AddNumberToObject(o, "alpha_x", m->ndf.alpha_x);
        cJSON_AddNumberToObject(o, "alpha_y", m->ndf.alpha_y);
        for (int k = 0; k < r->request.max_lobes; ++k)
            cJSON_AddItemToArray(fits, fit_json(&m->fits[k]));
        cJSON_AddItemToArray(mats, o);
    }
    char path[4096], *text = cJSON_Print(root);
    snprintf(path, sizeof path, "%s/sg_ndf_lobes.json", dir);
    int rc = text ? atomic_write_text(path, text, e) : gt_error_set(e, path, "out of memory");
    free(text);
    cJSON_Delete(root);
    return rc;
}

static void header_fit(FILE *f, const char *name, const sg_fit *fit)
{
    fprintf(f, "/* E = %.4g, max error %.4g */\nstatic const sg_ndf_lobe %s_k%d[%d] = {\n", fit->l2_error,
            fit->max_error, name, fit->lobe_count, fit->lobe_count);
    for (int j = 0; j < fit->lobe_count; ++j) {
        const spherical_gaussian *g = &fit->lobes[j];
        fprintf(f, "    {{%.9ef, %.9ef, %.9ef}, %.9ef, %.9ef},\n", g->axis[0], g->axis[1], g->axis[2], g->sharpness,
                g->amplitude);
    }
    fputs("};\n", f);
}

static int write_header(const char *dir, const sg_ndf_result *r, gt_error *e)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/sg_ndf_lobes.h", dir);
    atomic_file af;
    FILE *f = atomic_file_open(&af, path, "w", e);
    if (!f)
        return -1;
    fputs("/* Spherical-Gaussian fits of anisotropic NDFs (gtlab, techniques/sg_ndf/sg_ndf_study.h): D(m) ~ sum over a table's\n"
          " * lobes of amplitude exp(sharpness (dot(m, axis) - 1)), m in the tangent frame (x: alpha_x, z: n).\n"
          " * Only fits that passed every check (status ok). Generated; do not edit. */\n"
          "#pragma once\ntypedef struct { float axis[3]; float sharpness; float amplitude; } sg_ndf_lobe;\n",
          f);
    for (int i = 0; i < r->request.material_count; ++i) {
        char name[64];
        sg_ndf_material_name(&r->materials[i].ndf, name, sizeof name);
        for (char *c = name; *c; ++c)
            *c = *c == '.' ? '_' : *c;
        for (int k = 0; k < r->materials[i].fitted; ++k)
            header_fit(f, name, &r->materials[i].fits[k]);
    }
    return atomic_file_close(&af, f, e);
}

static int write_dat(const char *dir, const sg_ndf_result *r, gt_error *e)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/sg_ndf_error.dat", dir);
    atomic_file af;
    FILE *f = atomic_file_open(&af, path, "w", e);
    if (!f)
        return -1;
    for (int i = 0; i < r->request.material_count; ++i) {
        const sg_ndf_material *m = &r->materials[i];
        char name[64];
        sg_ndf_material_name(&m->ndf, name, sizeof name);
        fprintf(f, "%s# %s: k E max_error dssim\n", i ? "\n\n" : "", name);
        for (int k = 0; k < m->fitted; ++k)
            fprintf(f, "%d %.9g %.9g %.9g\n", k + 1, m->fits[k].l2_error, m->fits[k].max_error, m->dssim[k]);
        if (m->fitted == 0)
            fputs("nan nan nan nan\n", f);
    }
    return atomic_file_close(&af, f, e);
}

int sg_ndf_write_tables(const char *dir, const sg_ndf_result *r, gt_error *e)
{
    return write_json(dir, r, e) != 0 || write_header(dir, r, e) != 0 || write_dat(dir, r, e) != 0 ? -1 : 0;
}
