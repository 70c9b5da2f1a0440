/* The SG NDF study (see sg_ndf.h): fits, images and their scores. */
#include "sg_ndf/sg_ndf_study.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/image_io.h"
#include "core/progress.h"
#include "metrics/ssim.h"
#include "sg_ndf/sg_ndf_images.h"
#include "sg_ndf/sg_ndf_parts.h"
#include "sg_ndf/sg_ndf_quality.h"

enum { ALPHA_PAIRS = 5 };

sg_ndf_request sg_ndf_default_request(study_quality quality)
{
    static const double alphas[ALPHA_PAIRS][2] = {{0.1, 0.05}, {0.2, 0.1}, {0.4, 0.2}, {0.5, 0.1}, {0.8, 0.2}};
    const sg_ndf_quality *q = sg_ndf_quality_of(quality);
    int pairs = q->material_pairs < ALPHA_PAIRS ? q->material_pairs : ALPHA_PAIRS; /* past the list: all of it */
    int first = (ALPHA_PAIRS - pairs) / 2; /* the middle material_pairs of the list */
    sg_ndf_request rq = {0};
    for (int kind = 0; kind < 2; ++kind)
        for (int i = first; i < first + pairs; ++i) {
            const double *p = alphas[i];
            rq.materials[rq.material_count] = (anisotropic_ndf){(ndf_kind)kind, p[0], p[1]};
            rq.imaged[rq.material_count++] = p[0] == 0.4 && p[1] == 0.2; /* one per NDF */
        }
    rq.max_lobes = SG_NDF_STUDY_LOBES;
    rq.fit = sg_fit_default_options();
    rq.fit.theta_count = q->fit_theta_count, rq.fit.phi_count = q->fit_phi_count;
    rq.image_size = q->image_size;
    rq.image_samples = q->image_samples;
    rq.seed = 2010u;
    rq.l2_target = 0.05;
    return rq;
}

static double ndf_target(const double m[3], const void *ndf) { return anisotropic_ndf_evaluate(ndf, m); }

/* One thread per fit: the materials run in parallel instead (a fit's own
 * evaluations are too short to share; threads that wait for them spin). */
static void fit_material(const sg_ndf_request *rq, sg_ndf_material *mat, int *rc, gt_error *e)
{
    sg_target t = {ndf_target, &mat->ndf, mat->ndf.alpha_x, mat->ndf.alpha_y};
    sg_fit_options o = rq->fit;
    o.threads = 1;
    if (sg_fit_series(&t, rq->max_lobes, &o, mat->fits, e) != 0) {
        *rc = -1;
        return;
    }
    while (mat->fitted < rq->max_lobes && mat->fits[mat->fitted].status == SG_FIT_OK)
        ++mat->fitted;
    for (int k = mat->fitted; k >= 1; --k)
        if (mat->fits[k - 1].l2_error <= rq->l2_target)
            mat->lobes_for_target = k;
}

typedef struct {
    int size;
    float *mask, *mean, *se, *even, *odd, *approx;
} image_set;

static void image_set_free(image_set *s)
{
    free(s->mask);
    free(s->mean);
    free(s->se);
    free(s->even);
    free(s->odd);
    free(s->approx);
}

static int image_set_init(image_set *s, int size, gt_error *e)
{
    size_t n = (size_t)size * size;
    memset(s, 0, sizeof *s);
    s->size = size;
    float **planes[6] = {&s->mask, &s->mean, &s->se, &s->even, &s->odd, &s->approx};
    for (int i = 0; i < 6; ++i)
        if (!(*planes[i] = calloc(n, sizeof(float))))
            return gt_error_set(e, "sg-ndf", "out of memory for %d^2 images", size);
    sg_image_mask(size, s->mask);
    return 0;
}

static int write_png(const char *dir, const char *name, const float *plane, int size, gt_error *e)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/%s.png", dir, name);
    const float *planes[1] = {plane};
    return image_write_preview(path, planes, 1, size, size, 1.0f, e);
}

static double mean_relative_stderr(const image_set *s)
{
    double sum = 0.0;
    long count = 0;
    for (size_t i = 0; i < (size_t)s->size * s->size; ++i)
        if (s->mask[i] >= 0.5f && s->mean[i] > 0.0f)
            sum += s->se[i] / s->mean[i], ++count;
    return count ? sum / count : 0.0;
}

/* The true image, its noise floor, and each fitted k's DSSIM. */
static int score_images(const sg_ndf_request *rq, const study_context *ctx, const char *dir, sg_ndf_material *mat,
                        image_set *s, gt_error *e)
{
    sg_image_options o = {rq->image_size, rq->image_samples, rq->seed, ctx->threads};
    sg_image_planes truth = {s->mean, s->se, s->even, s->odd}, approx = {s->approx, NULL, NULL, NULL};
    ssim_result sr;
    if (sg_image_render(&mat->ndf, NULL, 0, &o, &truth, e) != 0 || write_png(dir, "true", s->mean, s->size, e) != 0 ||
        ssim_compute(s->even, s->odd, s->mask, s->size, s->size, "sg-ndf true halves", NULL, &sr, e) != 0)
        return -1;
    mat->noise_floor_dssim = sr.dssim;
    mat->mean_relative_stderr = mean_relative_stderr(s);
    for (int k = 1; k <= mat->fitted; ++k) {
        char name[16];
        snprintf(name, sizeof name, "k%d", k);
        if (sg_image_render(NULL, mat->fits[k - 1].lobes, k, &o, &approx, e) != 0 ||
            write_png(dir, name, s->approx, s->size, e) != 0 ||
            ssim_compute(s->mean, s->approx, s->mask, s->size, s->size, "sg-ndf image", NULL, &sr, e) != 0)
            return -1;
        mat->dssim[k - 1] = sr.dssim;
    }
    mat->has_images = 1;
    return 0;
}

static int image_material(const sg_ndf_request *rq, const study_context *ctx, sg_ndf_material *mat, gt_error *e)
{
    char sub[256], dir[4096];
    sg_ndf_material_name(&mat->ndf, sub, sizeof sub);
    char rel[300];
    snprintf(rel, sizeof rel, "%s/%s", SG_NDF_DIR, sub);
    image_set s = {0};
    int rc = study_make_dir(ctx, rel, dir, sizeof dir, e) != 0 || image_set_init(&s, rq->image_size, e) != 0
                 ? -1
                 : score_images(rq, ctx, dir, mat, &s, e);
    image_set_free(&s);
    return rc;
}

int sg_ndf_study(const study_context *ctx, const sg_ndf_request *rq, sg_ndf_result *r, gt_error *e)
{
    double start = seconds_now();
    memset(r, 0, sizeof *r);
    r->request = *rq;
    char dir[4096];
    if (study_make_dir(ctx, SG_NDF_DIR, dir, sizeof dir, e) != 0)
        return -1;
    int rc[SG_NDF_MATERIALS] = {0};
    gt_error errors[SG_NDF_MATERIALS];
#pragma omp parallel for schedule(dynamic, 1) num_threads(ctx->threads)
    for (int i = 0; i < rq->material_count; ++i) {
        r->materials[i].ndf = rq->materials[i];
        fit_material(rq, &r->materials[i], &rc[i], &errors[i]);
    }
    for (int i = 0; i < rq->material_count; ++i)
        if (rc[i] != 0) {
            *e = errors[i];
            return -1;
        }
    for (int i = 0; i < rq->material_count; ++i)
        if (rq->imaged[i] && image_material(rq, ctx, &r->materials[i], e) != 0)
            return -1;
    r->seconds = seconds_now() - start;
    return sg_ndf_write_tables(dir, r, e);
}
