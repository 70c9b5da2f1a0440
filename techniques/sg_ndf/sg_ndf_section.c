/* The SG NDF fit's section of `gtlab all` (see sg_ndf_section.h). */
#include "sg_ndf/sg_ndf_section.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report/claim_thresholds.h"
#include "report/gnuplot_plot.h"

static const int shown_k[5] = {1, 3, 5, 7, 9};

static void cell_error(const sg_ndf_material *m, int k, char *text, size_t size)
{
    if (k > SG_NDF_STUDY_LOBES || m->fits[k - 1].status == SG_FIT_NOT_RUN)
        snprintf(text, size, "-");
    else if (m->fits[k - 1].status != SG_FIT_OK)
        snprintf(text, size, "%s", sg_fit_status_name(m->fits[k - 1].status));
    else
        snprintf(text, size, "%.4f / %.4f", m->fits[k - 1].l2_error, m->fits[k - 1].max_error);
}

static void error_table(report *doc, const sg_ndf_result *r)
{
    const char *headers[8] = {"NDF", "alpha_x, alpha_y", "E / max, k=1", "k=3", "k=5", "k=7", "k=9",
                              "least k, E <= target"};
    report_table_begin(doc, 8, headers);
    for (int i = 0; i < r->request.material_count; ++i) {
        const sg_ndf_material *m = &r->materials[i];
        char cells[8][64];
        const char *row[8];
        snprintf(cells[0], 64, "%s", ndf_kind_name(m->ndf.kind));
        snprintf(cells[1], 64, "%.2f, %.2f", m->ndf.alpha_x, m->ndf.alpha_y);
        for (int c = 0; c < 5; ++c)
            cell_error(m, shown_k[c], cells[2 + c], 64);
        if (m->lobes_for_target)
            snprintf(cells[7], 64, "%d", m->lobes_for_target);
        else
            snprintf(cells[7], 64, "none of k <= %d", m->fitted);
        for (int c = 0; c < 8; ++c)
            row[c] = cells[c];
        report_table_row(doc, row);
    }
    report_table_end(doc);
}

static void stopped_notes(report *doc, const sg_ndf_result *r)
{
    for (int i = 0; i < r->request.material_count; ++i) {
        const sg_ndf_material *m = &r->materials[i];
        if (m->fitted < r->request.max_lobes)
            report_paragraph(doc, "%s (%.2f, %.2f): the series stopped at k = %d (%s): %s.",
                             ndf_kind_name(m->ndf.kind), m->ndf.alpha_x, m->ndf.alpha_y, m->fitted + 1,
                             sg_fit_status_name(m->fits[m->fitted].status), m->fits[m->fitted].note);
    }
}

static void image_rows(report_context *ctx, const sg_ndf_material *m, int samples, cJSON *json)
{
    char name[64], paths[4][256], captions[4][128];
    snprintf(name, sizeof name, "%s_%.2f_%.2f", ndf_kind_name(m->ndf.kind), m->ndf.alpha_x, m->ndf.alpha_y);
    const char *headers[3] = {"k", "DSSIM vs true NDF", "noise floor (true image's halves)"};
    report_table_begin(ctx->doc, 3, headers);
    for (int k = 1; k <= m->fitted; ++k) {
        char c0[16], c1[32], c2[32];
        snprintf(c0, sizeof c0, "%d", k);
        snprintf(c1, sizeof c1, "%.5f", m->dssim[k - 1]);
        snprintf(c2, sizeof c2, "%.5f", m->noise_floor_dssim);
        const char *row[3] = {c0, c1, c2};
        report_table_row(ctx->doc, row);
    }
    report_table_end(ctx->doc);
    int resolved = 0;
    for (int k = 1; k <= m->fitted; ++k)
        resolved += m->dssim[k - 1] > m->noise_floor_dssim;
    report_paragraph(ctx->doc, "%s: %d of %d DSSIMs lie above the noise floor; those below it are not resolved "
                     "from Monte Carlo noise at %d samples per pixel (mean relative standard error %.3f).",
                     name, resolved, m->fitted, samples,
                     m->mean_relative_stderr);
    cJSON_AddItemToObject(json, "dssim", cJSON_CreateDoubleArray(m->dssim, m->fitted));
    cJSON_AddNumberToObject(json, "noise_floor_dssim", m->noise_floor_dssim);
    const int show[3] = {1, 3, m->fitted >= 7 ? 7 : m->fitted};
    const char *p[4], *c[4];
    snprintf(paths[0], sizeof paths[0], "%s/%s/true.png", SG_NDF_DIR, name);
    snprintf(captions[0], sizeof captions[0], "%s: true NDF (Monte Carlo)", name);
    for (int i = 0; i < 3; ++i) {
        snprintf(paths[i + 1], sizeof paths[i + 1], "%s/%s/k%d.png", SG_NDF_DIR, name, show[i]);
        snprintf(captions[i + 1], sizeof captions[i + 1], "%d SG lobes, DSSIM %.4f", show[i], m->dssim[show[i] - 1]);
    }
    for (int i = 0; i < 4; ++i)
        p[i] = paths[i], c[i] = captions[i];
    report_figures(ctx->doc, m->fitted >= 1 ? 4 : 1, p, c);
}

static int plot(const report_context *ctx, const sg_ndf_result *r, gt_error *e)
{
    char data[4096], png[4096], script[16384];
    snprintf(data, sizeof data, "%s/%s/sg_ndf_error.dat", ctx->study.output_dir, SG_NDF_DIR);
    snprintf(png, sizeof png, "%s/figures/sg_ndf_error.png", ctx->study.output_dir);
    int n = snprintf(script, sizeof script,
                     "set logscale y\nset xrange [0.5:%d.5]\nset xlabel 'lobes k'\n"
                     "set ylabel 'relative L2 error E (solid angle)'\nset key outside right\n"
                     "set title 'NDF fit with spherical Gaussians'\nset arrow from 7, graph 0 to 7, graph 1 nohead "
                     "dashtype 2\nset arrow from graph 0, first %g to graph 1, first %g nohead dashtype 3\nplot ",
                     r->request.max_lobes, r->request.l2_target, r->request.l2_target);
    for (int i = 0; i < r->request.material_count && n < (int)sizeof script - 256; ++i) {
        const anisotropic_ndf *d = &r->materials[i].ndf;
        n += snprintf(script + n, sizeof script - n, "%s'%s' index %d using 1:2 with linespoints dashtype %d title '%s %.2f %.2f'",
                      i ? ", " : "", data, i, d->kind == NDF_WARD ? 1 : 2, ndf_kind_name(d->kind), d->alpha_x,
                      d->alpha_y);
    }
    snprintf(script + n, sizeof script - n, "\n");
    return gnuplot_render(script, png, 900, 520, e);
}

static const claim_record kSevenLobes = {
    .talk = "Kaplanyan 2010 (CryENGINE 3)", .seed = "004", .section = "Anisotropic deferred materials, part I",
    .quote = "Approximate NDF with **Spherical Gaussians** [WRGSG09] - Need only ~ 7 lobes for Anisotropic Ward NDF",
    .setting = "the NDF of an anisotropic Ward BRDF (the part of the BRDF the lighting cannot defer: the lit "
               "result is proportional to it) fitted with spherical Gaussians as in Wang et al. 2009, for a "
               "deferred lighting pass; the talk names no roughness and says \"in a vast majority of cases\"",
    .setting_match = CLAIM_SETTING_INDEPENDENT,
    .setting_note = "the roughnesses are gtlab's (Ward (0.2, 0.1), (0.4, 0.2), (0.5, 0.1)): one row per material "
                    "whose checked 7-lobe fit exists; the fit is of a function, so no image resolution enters",
    .reading = "seven SG lobes reproduce the Ward NDF with no visible change of the lit result; since the lit "
               "result is proportional to the NDF, its relative L2 error E = ||S - D||/||D|| is the highlight's "
               "relative change, and the greedy fit's E bounds the best 7-lobe E from above.",
    .form = CLAIM_RANGE, .low = -INFINITY, .high = CLAIM_WEBER_FRACTION,
    .tolerance_source = CLAIM_TOLERANCE_VISIBILITY,
    .tolerance = "a 1% relative change of the lit highlight (CLAIM_WEBER_FRACTION)"};

/* One row per Ward material at k = 7 (the talk's number), when its 7-lobe fit
 * passed its checks and lies within the threshold. A fit above it is no
 * refutation: the greedy fit is a local optimum, so its E only bounds the
 * best 7-lobe error from above; the report says so instead. */
void sg_ndf_claim_rows(report_context *ctx, const sg_ndf_result *r)
{
    for (int i = 0; i < r->request.material_count; ++i) {
        const sg_ndf_material *m = &r->materials[i];
        if (m->ndf.kind != NDF_WARD)
            continue;
        if (m->fitted < 7 || m->fits[6].l2_error > CLAIM_WEBER_FRACTION) {
            report_paragraph(ctx->doc,
                             "Ward (%.2f, %.2f), k = 7: %s; E of a local optimum only bounds the best 7-lobe error "
                             "from above, so this is not a refutation of the talk (no claims row; the talk says "
                             "\"in a vast majority of cases\").",
                             m->ndf.alpha_x, m->ndf.alpha_y,
                             m->fitted < 7 ? "no checked 7-lobe fit" : "E above a 1% change of the highlight");
            continue;
        }
        claims_table_add(ctx->claims, &kSevenLobes, m->fits[6].l2_error, 0.0,
                         "Ward (%.2f, %.2f): relative L2 error E of a 7-lobe SG fit (solid-angle least squares in "
                         "D, Ceres; an upper bound on the best 7-lobe E; max |S - D| / max D %.4f); deterministic",
                         m->ndf.alpha_x, m->ndf.alpha_y, m->fits[6].max_error);
    }
}

static cJSON *material_json(const sg_ndf_material *m)
{
    cJSON *o = cJSON_CreateObject();
    double e[SG_NDF_STUDY_LOBES], mx[SG_NDF_STUDY_LOBES];
    for (int k = 0; k < m->fitted; ++k)
        e[k] = m->fits[k].l2_error, mx[k] = m->fits[k].max_error;
    cJSON_AddStringToObject(o, "ndf", ndf_kind_name(m->ndf.kind));
    cJSON_AddNumberToObject(o, "alpha_x", m->ndf.alpha_x);
    cJSON_AddNumberToObject(o, "alpha_y", m->ndf.alpha_y);
    cJSON_AddNumberToObject(o, "fitted_lobes", m->fitted);
    cJSON_AddNumberToObject(o, "lobes_for_target", m->lobes_for_target);
    cJSON_AddItemToObject(o, "l2_error", cJSON_CreateDoubleArray(e, m->fitted));
    cJSON_AddItemToObject(o, "max_error", cJSON_CreateDoubleArray(mx, m->fitted));
    return o;
}

int sg_ndf_section(report_context *ctx, const sg_ndf_result *r, gt_error *e)
{
    char figures[2048];
    if (study_make_dir(&ctx->study, "figures", figures, sizeof figures, e) != 0 || plot(ctx, r, e) != 0)
        return -1;
    const sg_ndf_request *rq = &r->request;
    report_heading(ctx->doc, 2, "NDF fit with spherical Gaussians (CryENGINE 3)");
    report_paragraph(ctx->doc,
                     "Kaplanyan 2010 approximates an anisotropic NDF by spherical Gaussians S(m) = sum mu_j "
                     "exp(lambda_j (m.p_j - 1)) and states that anisotropic Ward needs only ~7 lobes. gtlab fits k = "
                     "1..%d lobes (axis as two gnomonic coordinates, sharpness, amplitude) with Ceres to anisotropic "
                     "Ward and GGX, each normalised to int D (m.n) dm = 1. Objective: least squares in D weighted by "
                     "solid angle on a %d x %d hemisphere grid adapted to the lobe's slope scale; E = ||S - D||_2 / "
                     "||D||_2 and max |S - D| / max D on the grid. Lobe k+1 starts from the k-lobe fit plus a lobe at "
                     "the largest deficit, so E cannot grow with k; a series stops at a lobe on a bound of its range, "
                     "two coinciding lobes, or no convergence (said below). Lobe tables: %s/sg_ndf_lobes.json and .h "
                     "(with covariance standard errors). %.1f s.",
                     rq->max_lobes, rq->fit.theta_count, rq->fit.phi_count, SG_NDF_DIR, r->seconds);
    error_table(ctx->doc, r);
    stopped_notes(ctx->doc, r);
    const char *p[1] = {"figures/sg_ndf_error.png"}, *c[1] = {"E against k (dotted: the target, dashed: k = 7)"};
    report_figures(ctx->doc, 1, p, c);
    report_paragraph(ctx->doc,
                     "Specular images: a sphere under the analytic sky, I(n) = int D(m)(m.n) L(reflect(v, m)) dm by "
                     "Monte Carlo (%d^2, %d samples per pixel, seed %u) with the true NDF and with each k-lobe sum, "
                     "DSSIM against the true NDF's image; the noise floor is the DSSIM of the true image's two "
                     "independent halves (each half as noisy as sqrt 2 times the full image).",
                     rq->image_size, rq->image_samples, rq->seed);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "sg_ndf"), *mats = cJSON_AddArrayToObject(json, "materials");
    for (int i = 0; i < rq->material_count; ++i) {
        cJSON *mj = material_json(&r->materials[i]);
        cJSON_AddItemToArray(mats, mj);
        if (r->materials[i].has_images)
            image_rows(ctx, &r->materials[i], rq->image_samples, mj);
    }
    sg_ndf_claim_rows(ctx, r);
    return 0;
}
