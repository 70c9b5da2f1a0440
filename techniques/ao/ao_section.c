/* Report section: the AO and bent-normal references of every built-in
 * scene (ao_references.h), rendered into the report: a table of
 * their sampling, noise and noise floor, and their previews. */
#include <stdio.h>

#include "ao/ao_section.h"
#include "ao/ao_references.h"
#include "report/report_table.h"

static void size_cell(const void *row, char *text, size_t size)
{
    const ao_reference_row *r = row;
    snprintf(text, size, "%dx%d", r->width, r->height);
}

static void mrays_cell(const void *row, char *text, size_t size)
{
    snprintf(text, size, "%.1f", ((const ao_reference_row *)row)->rays_per_second * 1e-6);
}

static const report_column columns[] = {
    REPORT_TEXT("scene", "scene", ao_reference_row, scene),
    REPORT_COUNT("triangles", "triangles", ao_reference_row, triangles),
    REPORT_CELL("size", size_cell),
    REPORT_INT(NULL, "width", ao_reference_row, width),
    REPORT_INT(NULL, "height", ao_reference_row, height),
    REPORT_INT(NULL, "covered_pixels", ao_reference_row, covered_pixels),
    REPORT_REAL("mean spp", "mean_spp", "%.0f", ao_reference_row, mean_spp),
    REPORT_REAL("seconds", "seconds", "%.2f", ao_reference_row, seconds),
    REPORT_CELL("Mrays/s", mrays_cell),
    REPORT_REAL(NULL, "rays_per_second", NULL, ao_reference_row, rays_per_second),
    REPORT_REAL("mean stderr", "mean_stderr_ao", "%.2e", ao_reference_row, mean_stderr),
    REPORT_REAL("max stderr", "max_stderr_ao", "%.2e", ao_reference_row, max_stderr),
    REPORT_REAL("noise RMSE", "noise_rmse_ao", "%.2e", ao_reference_row, noise_rmse),
    REPORT_REAL("noise floor (DSSIM)", "noise_floor_dssim_ao", "%.2e", ao_reference_row, noise_floor_dssim),
};

static void add_figures(report *doc, const ao_references_result *r)
{
    static const char *const labels[3] = {"cosine AO", "bent normal (0.5 + 0.5 n)", "standard error of AO"};
    for (int i = 0; i < r->count; ++i) {
        const char *name = r->rows[i].scene;
        char paths[3][256], caption[256];
        snprintf(paths[0], 256, "figures/ao_%s.png", name);
        snprintf(paths[1], 256, "figures/bent_%s.png", name);
        snprintf(paths[2], 256, "figures/ao_stderr_%s.png", name);
        snprintf(caption, sizeof caption, "%s: the AO reference, its bent normal and its standard error", name);
        const char *p[3] = {paths[0], paths[1], paths[2]};
        report_comparison(doc, 3, p, labels, 1, caption);
    }
}

int ao_references_section(report_context *ctx, const ao_references_result *r, gt_error *e)
{
    (void)e;
    char stop[96] = "";
    const ao_references_request *rq = &r->request;
    if (rq->target_stderr > 0)
        snprintf(stop, sizeof stop, ", a pixel stopping at its noise budget, a standard error of %g", rq->target_stderr);
    report_heading(ctx->doc, 2, "Ambient occlusion and bent-normal references");
    report_paragraph(ctx->doc,
                     "Cosine-weighted AO V_d = (1/pi) integral of V(w) (n.w) over the hemisphere, uniform AO and "
                     "the bent normal, at the surface seen through each pixel centre, rendered with Embree from "
                     "Owen-scrambled Sobol' samples (%d per pixel at most%s; seed %u). Standard errors are per "
                     "pixel, from the samples themselves. The noise floor is the DSSIM between the AO of the even "
                     "and of the odd samples: no approximation can be scored more finely than that. The noise RMSE, "
                     "sqrt(mean stderr^2), is what an RMSE against the reference carries: an error of true RMSE f "
                     "reads sqrt(f^2 + noise^2); where it is ranked the report checks it against the figures' "
                     "budget (At a glance, GTAO).",
                     rq->spp, stop, (unsigned)rq->seed);
    report_rows(ctx->doc, cJSON_AddArrayToObject(ctx->summary, "ao_references"), columns,
                (int)(sizeof columns / sizeof columns[0]), r->rows, sizeof r->rows[0], r->count);
    add_figures(ctx->doc, r);
    return 0;
}
