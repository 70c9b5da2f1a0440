/* The anti-aliasing frames (issue 19): builtin:aa-thin's alpha-tested cards
 * (glTF alphaMode MASK through Embree's filter functions, and through a glb
 * round trip), camera_project as camera_ray's inverse, and the motion
 * vectors of anti_aliasing/frames_render.h checked by tracing the previous
 * camera's ray at the reprojected position; thread independence. */
#include <stdio.h>
#include <string.h>

#include "anti_aliasing/frames_render.h"
#include "scene/builtin_scenes.h"
#include "scene/camera_path.h"
#include "scene/gltf/gltf_reader.h"
#include "scene/gltf/gltf_writer.h"
#include "scene/material_lookup.h"
#include "tests/check.h"

enum { CARD_MESH = 3, W = 64, H = 48 };

/* The world point of card 0 at texture coordinates (u, v). */
static vec3 card_point(const scene *s, float u, float v)
{
    const float *p = s->meshes[CARD_MESH].positions; /* vertices 0, 1, 3: uv (0, 1), (1, 1), (0, 0) */
    vec3 p0 = v3_load(p), p1 = v3_load(p + 3), p3 = v3_load(p + 9);
    return v3_add(p0, v3_add(v3_scale(v3_sub(p1, p0), u), v3_scale(v3_sub(p3, p0), 1.0f - v)));
}

/* A ray from the camera to card 0 at (u, v): 1 if it stops on the card there. */
static int card_hit(const embree_scene *es, const scene *s, float u, float v)
{
    vec3 o = s->camera.position, q = card_point(s, u, v), d = v3_sub(q, o);
    surface_hit h;
    float distance = v3_length(d);
    return embree_closest_hit(es, o, v3_scale(d, 1.0f / distance), INFINITY, &h) && h.mesh == CARD_MESH &&
           fabsf(h.t - distance) < 1e-3f * distance;
}

static void test_alpha_mask(const scene *s, const embree_scene *es)
{
    const float leaf[2] = {0.125f, 0.125f}, hole[2] = {1.0f / 64.0f, 1.0f / 64.0f};
    CHECK(s->alpha_cutoff && s->alpha_cutoff[s->meshes[CARD_MESH].material] == 0.5f);
    CHECK(material_alpha_covers(s, CARD_MESH, leaf) && !material_alpha_covers(s, CARD_MESH, hole));
    CHECK(material_alpha_covers(s, 0, hole)); /* an opaque material */
    CHECK(card_hit(es, s, leaf[0], leaf[1]));
    CHECK(!card_hit(es, s, hole[0], hole[1]));
    char path[4096];
    snprintf(path, sizeof path, "%s/aa_thin_alpha.glb", check_tmp_dir());
    scene back;
    gt_error e;
    CHECK_MSG(gltf_write_glb(path, s, &e) == 0, "%s", e.message);
    CHECK_MSG(gltf_load(path, &back, &e) == 0, "%s", e.message);
    CHECK(back.alpha_cutoff && back.alpha_cutoff[back.meshes[CARD_MESH].material] == 0.5f);
    CHECK(back.alpha_cutoff && back.alpha_cutoff[back.meshes[0].material] == 0.0f);
    scene_free(&back);
}

static void test_projection(const camera *cam)
{
    camera_view view = camera_view_from(cam);
    double worst = 0.0;
    for (int k = 0; k < 100; ++k) {
        float x = (float)(k % 10) * 6.3f + 0.7f, y = (float)(k / 10) * 4.7f + 0.2f, xy[2];
        vec3 o, d;
        camera_ray(&view, x, y, &o, &d);
        CHECK(camera_project(&view, v3_add(o, v3_scale(d, 3.0f + k)), xy) > 0.0f);
        worst = fmax(worst, fmax(fabs(xy[0] - x), fabs(xy[1] - y)));
    }
    CHECK_MSG(worst < 1e-3, "camera_project is off camera_ray by %g pixels", worst);
}

/* Each pixel not disoccluded: the previous camera's ray at its reprojected
 * position finds the same surface point. */
static void test_motion(const embree_scene *es, const camera_path *path)
{
    camera cur = camera_path_at(path, 3), prev = camera_path_at(path, 2);
    frame_lighting light = frame_lighting_default();
    frame_buffers f, g;
    CHECK(frame_buffers_alloc(&f, W, H) == 0 && frame_buffers_alloc(&g, W, H) == 0);
    const float jitter[2] = {0.25f, -0.375f};
    frames_render(es, &cur, &prev, &light, jitter, 1, &f);
    frames_render(es, &cur, &prev, &light, jitter, 2, &g);
    CHECK(memcmp(f.rgb, g.rgb, 3 * sizeof(float) * W * H) == 0 && memcmp(f.motion, g.motion, 8 * W * H) == 0);
    CHECK(memcmp(f.depth, g.depth, 4 * W * H) == 0 && memcmp(f.disoccluded, g.disoccluded, W * H) == 0);
    camera_view pv = camera_view_from(&prev), cv = camera_view_from(&cur);
    int checked = 0, agree = 0, moving = 0, disoccluded = 0;
    for (int k = 0; k < W * H; ++k) {
        disoccluded += f.disoccluded[k];
        if (f.depth[k] == 0.0f || f.disoccluded[k])
            continue;
        float x = k % W + 0.5f + jitter[0], y = k / W + 0.5f + jitter[1], rgb[3];
        surface_hit now, then;
        shaded_frame_sample(es, &cv, &light, x, y, rgb, &now);
        int seen = shaded_frame_sample(es, &pv, &light, x + f.motion[2 * k], y + f.motion[2 * k + 1], rgb, &then);
        ++checked;
        agree += seen && v3_length(v3_sub(now.p, then.p)) < 1e-3f * f.depth[k];
        moving += fabsf(f.motion[2 * k]) > 0.05f;
    }
    CHECK_MSG(checked > W * H / 4 && agree >= checked - checked / 100, "%d of %d reprojections agree", agree, checked);
    CHECK_MSG(moving > checked / 2 && disoccluded > 0, "%d moving, %d disoccluded", moving, disoccluded);
    frame_buffers_free(&f), frame_buffers_free(&g);
}

/* A static camera: motion 0 to rounding, nothing disoccluded. */
static void test_static(const embree_scene *es, const camera *cam)
{
    frame_buffers f;
    CHECK(frame_buffers_alloc(&f, W, H) == 0);
    const float jitter[2] = {0.0f, 0.0f};
    frame_lighting light = frame_lighting_default();
    frames_render(es, cam, cam, &light, jitter, 2, &f);
    double worst = 0.0;
    int disoccluded = 0;
    for (int k = 0; k < W * H; ++k) {
        worst = fmax(worst, fmax(fabs(f.motion[2 * k]), fabs(f.motion[2 * k + 1])));
        disoccluded += f.disoccluded[k];
    }
    CHECK_MSG(worst < 1e-3 && disoccluded == 0, "static motion %g pixels, %d disoccluded", worst, disoccluded);
    frame_buffers_free(&f);
}

int main(void)
{
    scene s;
    embree_scene es;
    gt_error e;
    CHECK_MSG(builtin_scene_build("aa-thin", &s, &e) == 0, "%s", e.message);
    CHECK_MSG(embree_scene_build(&s, &es, &e) == 0, "%s", e.message);
    camera cam = s.camera;
    cam.width = W, cam.height = H;
    camera_path path = {cam, v3(0.05f, 0.0f, 0.0f), 0.004f};
    test_alpha_mask(&s, &es);
    test_projection(&cam);
    test_motion(&es, &path);
    test_static(&es, &cam);
    embree_scene_release(&es);
    scene_free(&s);
    return check_report("test_aa_frames");
}
