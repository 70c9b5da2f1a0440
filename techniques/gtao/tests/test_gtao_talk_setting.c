/* The GTAO talk's setting for its claims rows (issue 42, item 4;
 * gtao_talk_setting.h): which scenes run in it at each quality,
 * the 1920x1080 frame seen from the reference's camera and its 960x540 half
 * (each half pixel the closest covered pixel of its 2x2 block), and the
 * claims rows' studies on a small frame: the claims' radius only, the "4x
 * samples" runs within the half pass only, the cycle on the half pass. */
#include <math.h>
#include <string.h>

#include "gtao/gtao_shortcuts.h"
#include "gtao/gtao_talk_setting.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"

static void test_scenes(void)
{
    study_context preview = {check_tmp_dir(), QUALITY_PREVIEW, 2, NULL, NULL, 0};
    study_context production = {check_tmp_dir(), QUALITY_PRODUCTION, 2, NULL, NULL, 0};
    CHECK(gtao_talk_scene(&preview, "boxes") && gtao_talk_scene(&preview, "cornell"));
    CHECK(!gtao_talk_scene(&preview, "menger") && !gtao_talk_scene(&preview, "plane"));
    CHECK(gtao_talk_scene(&production, "menger") && gtao_talk_scene(&production, "corner"));
    CHECK(gtao_talk_scene(&production, "boxes") && !gtao_talk_scene(&production, "plane"));
}

/* The closest covered depth of full's 2x2 block (x, y), or -1 if none is covered. */
static float block_min_depth(const ss_gbuffer *full, int x, int y)
{
    float best = -1.0f;
    for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
            if (ss_covered(full, 2 * x + dx, 2 * y + dy)) {
                float d = full->depth[(long)(2 * y + dy) * full->width + 2 * x + dx];
                best = best < 0.0f || d < best ? d : best;
            }
    return best;
}

static void test_frame(void)
{
    study_context ctx = {check_tmp_dir(), QUALITY_PREVIEW, 2, NULL, NULL, 0};
    camera reference = {{27, 22, 35}, {0, 0, 0}, {0, 1, 0}, 0.785398f, 256, 256};
    gtao_talk_frame f;
    gt_error e;
    int rc = gtao_talk_frame_render(&ctx, "boxes", &reference, &f, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    if (rc != 0)
        return;
    CHECK(f.full.g.width == 1920 && f.full.g.height == 1080 && f.half.g.width == 960 && f.half.g.height == 540);
    CHECK(f.full.cam.width == 1920 && f.full.cam.height == 1080 && f.full.cam.yfov == reference.yfov);
    CHECK(fabsf(f.camera_distance - sqrtf(27 * 27 + 22 * 22 + 35 * 35)) < 1e-3f);
    long covered = 0, wrong = 0;
    for (int y = 0; y < f.half.g.height; ++y)
        for (int x = 0; x < f.half.g.width; ++x) {
            float want = block_min_depth(&f.full.g, x, y);
            int is = ss_covered(&f.half.g, x, y);
            covered += is;
            wrong += is != (want >= 0.0f) || (is && f.half.g.depth[(long)y * f.half.g.width + x] != want);
        }
    CHECK_MSG(wrong == 0 && covered > 960 * 540 / 2, "%ld wrong, %ld covered", wrong, covered);
    gtao_talk_frame_free(&f);
}

/* The studies on a 96x54 frame of boxes and its 48x27 half. */
static void test_studies(void)
{
    scene s;
    gt_error e;
    CHECK(scene_load("builtin:boxes", &s, &e) == 0);
    camera cam = {{27, 22, 35}, {0, 0, 0}, {0, 1, 0}, 0.785398f, 96, 54};
    approx_input full;
    int rc = approx_render_gbuffer(&s, "boxes", &cam, 2, &full, &e);
    scene_free(&s);
    CHECK_MSG(rc == 0, "%s", e.message);
    if (rc != 0)
        return;
    ss_half_gbuffer half;
    CHECK(ss_half_resolution(&full.g, &half) == 0);
    static gtao_talk_result r;
    rc = gtao_shortcuts_talk_scene("boxes", &full.g, &half.g, 50.0f, &r, &e);
    CHECK_MSG(rc == 0, "%s", e.message);
    CHECK(r.scene_count == 1 && strcmp(r.scenes[0], "boxes") == 0);
    CHECK(r.full_width == 96 && r.full_height == 54 && r.half_width == 48 && r.half_height == 27);
    CHECK(r.half_res.radius_count == 1 && r.half_res.radii[0].radius_fraction == GTAO_HALF_RES_4X_RADIUS);
    CHECK(r.half_pass.radius_count == 1);
    CHECK_MSG(r.half_res.min_vs_mip.blocks == 0 && r.half_pass.min_vs_mip.blocks > 0, "%ld %ld",
              r.half_res.min_vs_mip.blocks, r.half_pass.min_vs_mip.blocks);
    /* the half pass's own half resolution changes the AO: it only darkens */
    const gtao_half_res_radius *k = &r.half_res.radii[0];
    CHECK(k->change[GTAO_HALF_RES_HALF_MIP_MIN].blocks > 0 && block_mean_value(&k->change[GTAO_HALF_RES_HALF_MIP_MIN]) > 0.0);
    CHECK(r.pattern.scene_count == 1 && r.denoisers.scene_count == 1 && r.pattern.cycle_se2.blocks > 0);
    ss_half_free(&half);
    approx_input_free(&full);
}

int main(void)
{
    test_scenes();
    test_frame();
    test_studies();
    return check_report("test_gtao_talk_setting");
}
