/* The GTAO parameter fit recovers the parameters that made a synthetic
 * reference: GTAO itself (low preset) on a 24x24 G-buffer of the corner
 * scene at a known radius, falloff and thickness, fitted from the fit's own
 * start (0.25, 0.25, 0.1) under either objective. */
#include <math.h>
#include <string.h>

#include "gtao/gtao.h"
#include "gtao/gtao_params_fit.h"
#include "raytracer/reference_render.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

enum { SIZE = 24 };

typedef struct {
    image img;
    camera cam;
    ss_gbuffer g;
} test_gbuffer;

static int render_gbuffer(const char *spec, test_gbuffer *b)
{
    gt_error e;
    scene s;
    if (scene_load(spec, &s, &e) != 0)
        return -1;
    reference_request req = {.quantity = QUANTITY_GBUFFER, .sampling = {.threads = 1}, .normals = NORMAL_SHADING};
    render_stats stats;
    int rc = scene_choose_camera(&s, NULL, SIZE, SIZE, &b->cam, &e) != 0 ||
             reference_render(&s, spec, &b->cam, &req, &b->img, &stats, &e) != 0;
    scene_free(&s);
    if (rc)
        return -1;
    camera_view v = camera_view_from(&b->cam);
    ss_camera c = {v.forward, v.right, v.up, v.tan_half_yfov, v.aspect};
    return ss_gbuffer_from_image(&b->img, spec, c, &b->g, &e);
}

/* The truth: radius 0.5 of the camera distance, falloff 0.5, thickness 0.3. */
static const double truth[GTAO_FIT_PARAMS] = {0.5, 0.5, 0.3};

static void check_recovers(const test_gbuffer *b, gtao_fit_objective objective, double tolerance)
{
    const char *objective_name = gtao_fit_objective_names[objective];
    float distance = v3_length(v3_sub(b->cam.target, b->cam.position));
    gtao_params p;
    CHECK(gtao_preset("low", &p) == 0);
    p.radius = (float)truth[0] * distance;
    p.falloff = (float)truth[1];
    p.thickness = (float)truth[2];
    static float reference[SIZE * SIZE];
    CHECK(gtao_render(&b->g, &p, reference, NULL) == 0);
    gtao_fit_scene scene = {"corner", &b->g, reference, distance};
    gtao_fit_problem problem = {&scene, 1, &scene, 1, "low", objective};
    static gtao_fit_result r;
    gt_error e;
    CHECK(gtao_params_fit(&problem, &r, &e) == 0);
    for (int k = 0; k < GTAO_FIT_PARAMS; ++k)
        CHECK_MSG(fabs(r.value[k] - truth[k]) < tolerance, "%s: %s %g, truth %g", objective_name,
                  gtao_fit_param_names[k], r.value[k], truth[k]);
    CHECK(r.score_count == 2 && !r.scores[0].held_out && r.scores[1].held_out);
    const gtao_fit_score *train = &r.scores[0];
    CHECK(train->rmse_after < 0.05 * train->rmse_before);
    CHECK(train->dssim_after < train->dssim_before);
    /* the held-out copy of the scene scores the same */
    CHECK(r.scores[1].rmse_after == train->rmse_after && r.scores[1].dssim_after == train->dssim_after);
    /* one training scene: the objective per scene is its own score after the fit */
    double after = objective == GTAO_FIT_DSSIM ? train->dssim_after : train->rmse_after * train->rmse_after;
    CHECK_NEAR(r.objective_per_scene, after, 1e-6 * fmax(1.0, after));
}

int main(void)
{
    static test_gbuffer b;
    CHECK(render_gbuffer("builtin:corner", &b) == 0);
    check_recovers(&b, GTAO_FIT_RMSE, 1e-3);
    check_recovers(&b, GTAO_FIT_DSSIM, 0.01);
    image_free(&b.img);
    return check_report("fitters_gtao_params_fit");
}
