/* The specular-occlusion rankings' statistics: paired differences over
 * scenes against the textbook mean and standard error computed here by two
 * passes, NaN cases left out, region scores read with their stride; and the
 * scoring of one case, where a reference made by a variant itself scores
 * DSSIM 0 and signed error 0 exactly; the closest variant and the
 * runner-up. */
#include <math.h>
#include <stdlib.h>

#include "specular_occlusion/specular_occlusion_rankings.h"
#include "tests/check.h"

enum { SCENES = 5, R = SO_STUDY_ROUGHNESSES };

static void check_paired(void)
{
    double a[SCENES * R], b[SCENES * R], scene_d[SCENES];
    for (int s = 0; s < SCENES; ++s) {
        scene_d[s] = 0.0;
        for (int k = 0; k < R; ++k) {
            int i = s * R + k;
            a[i] = 0.1 * s + 0.01 * k * k, b[i] = 0.05 * s * s - 0.02 * k;
            scene_d[s] += (a[i] - b[i]) / R;
        }
    }
    double mean = 0.0, var = 0.0;
    for (int s = 0; s < SCENES; ++s)
        mean += scene_d[s] / SCENES;
    for (int s = 0; s < SCENES; ++s)
        var += (scene_d[s] - mean) * (scene_d[s] - mean) / (SCENES - 1);
    so_paired_difference d = so_paired_over_scenes(a, b, 1, SCENES, -1);
    CHECK(d.cases == SCENES);
    CHECK_MSG(fabs(d.mean - mean) < 1e-14, "mean %.17g vs %.17g", d.mean, mean);
    CHECK_MSG(fabs(d.standard_error - sqrt(var / SCENES)) < 1e-12, "se %.17g vs %.17g", d.standard_error,
              sqrt(var / SCENES));
    /* one roughness: the scenes' values at it */
    so_paired_difference one = so_paired_over_scenes(a, b, 1, SCENES, 2);
    double m2 = 0.0;
    for (int s = 0; s < SCENES; ++s)
        m2 += (a[s * R + 2] - b[s * R + 2]) / SCENES;
    CHECK(fabs(one.mean - m2) < 1e-14);
    /* a scene without scores is left out */
    for (int k = 0; k < R; ++k)
        a[1 * R + k] = NAN;
    so_paired_difference four = so_paired_over_scenes(a, b, 1, SCENES, -1);
    CHECK(four.cases == SCENES - 1);
    CHECK(fabs(four.mean - (mean * SCENES - scene_d[1]) / (SCENES - 1)) < 1e-14);
    /* fewer than two scenes: no standard error */
    CHECK(isnan(so_paired_over_scenes(a, b, 1, 1, -1).standard_error));
}

/* A 32x32 case: a smooth field of inputs, the silhouette region the left 8 columns. */
static void check_case(void)
{
    enum { N = 32 };
    static float mask[N * N], nv[N * N], beta[N * N], aoc[N * N], aou[N * N], rough[N * N], reference[N * N];
    static float sil[N * N], interior[N * N];
    so_pixel_inputs in = {N, N, mask, nv, beta, aoc, aou, rough};
    for (int i = 0; i < N * N; ++i) {
        int x = i % N, y = i / N;
        mask[i] = 1.0f, nv[i] = 0.2f + 0.7f * x / N, beta[i] = 0.1f + 1.2f * y / N;
        aoc[i] = aou[i] = 0.3f + 0.6f * (x + y) / (2.0f * N), rough[i] = 0.5f;
        sil[i] = x < 8, interior[i] = x >= 8;
    }
    so_regions regions = {N, N, {sil, interior}, {8 * N, (N - 8) * N}};
    so_ranking_scores *s = calloc(1, sizeof *s);
    so_lut lut;
    CHECK(so_lut_build(&lut, 8, SO_LOBE_PHONG, SO_AXES_ANGLES, 1) == 0);
    so_ranking_scores_init(s, &lut);
    so_approx_evaluate(&in, &s->variants[SO_RANK_AO], reference); /* the reference is AO-as-V_s itself */
    gt_error e = {0};
    for (int scene = 0; scene < 2; ++scene)
        for (int k = 0; k < R; ++k)
            CHECK(so_ranking_scores_add(s, &in, reference, &regions, "test", &e) == 0);
    CHECK(s->cases == 2 * R);
    CHECK(s->dssim[SO_RANK_AO][0] == 0.0);
    CHECK(s->region[SO_RANK_AO][0][SO_REGION_SILHOUETTE].bias == 0.0);
    CHECK(s->region[SO_RANK_AO][0][SO_REGION_INTERIOR].dssim == 0.0);
    CHECK(s->dssim[SO_RANK_CONE][0] > 0.0);
    so_ranking_setting out;
    so_ranking_setting_compute(s, 2, &out);
    CHECK_MSG(fabs(out.cone_minus_ao.mean - s->dssim[SO_RANK_CONE][0]) < 1e-15, "%g vs %g", out.cone_minus_ao.mean,
              s->dssim[SO_RANK_CONE][0]);
    CHECK(out.cone_minus_ao.standard_error == 0.0); /* identical scenes */
    free(s);
    so_lut_free(&lut);
}

/* The closest variant and the runner-up (so_study_best_variants, the
 * At-a-glance row's and the best maps'): the lowest mean DSSIM among the
 * variants on the reference's inputs; a variant on GTAO's inputs, lower
 * still, is neither; with the lowest first, the runner-up is the next. */
static void check_best_variants(void)
{
    static so_study_result r;
    const double dssim[5] = {0.30, 0.12, 0.05, 0.20, 0.11};
    r.variant_count = 5;
    for (int v = 0; v < 5; ++v)
        r.variants[v].mean_dssim = dssim[v];
    r.variants[2].on_gtao = SO_GTAO_ARC_MEAN;
    int best, runner_up;
    so_study_best_variants(&r, &best, &runner_up);
    CHECK_MSG(best == 4 && runner_up == 1, "best %d, runner-up %d", best, runner_up);
    r.variants[0].mean_dssim = 0.01;
    so_study_best_variants(&r, &best, &runner_up);
    CHECK_MSG(best == 0 && runner_up == 4, "best %d, runner-up %d", best, runner_up);
}

int main(void)
{
    check_paired();
    check_case();
    check_best_variants();
    return check_report("studies_so_rankings");
}
