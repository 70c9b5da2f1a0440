/* The GTAO talk's 1080p frame at half resolution; see gtao_talk_setting.h. */
#include "gtao/gtao_talk_setting.h"

#include <string.h>

#include "gtao/gtao_quality.h"
#include "scene/scene_loaders.h"
#include "project/scene_list.h"

/* In the order the quality table's talk_scenes takes them. */
static const char *const builtin_scenes[] = {"boxes", "cornell", "menger", "corner"};
enum { BUILTIN_SCENES = sizeof builtin_scenes / sizeof builtin_scenes[0] };

int gtao_talk_scene(const study_context *ctx, const char *label)
{
    const gtao_quality *q = gtao_quality_of(ctx->quality);
    if (study_scenes_from_project(ctx)) {
        for (int i = 0; i < q->talk_project_scenes && i < study_scene_count(ctx); ++i)
            if (strcmp(study_scene_at(ctx, i)->label, label) == 0)
                return 1;
        return 0;
    }
    for (int i = 0; i < q->talk_scenes && i < BUILTIN_SCENES; ++i)
        if (strcmp(builtin_scenes[i], label) == 0)
            return 1;
    return 0;
}

int gtao_talk_frame_render(const study_context *ctx, const char *label, const camera *reference_camera,
                           gtao_talk_frame *out, gt_error *e)
{
    memset(out, 0, sizeof *out);
    camera cam = *reference_camera;
    cam.width = GTAO_TALK_WIDTH;
    cam.height = GTAO_TALK_HEIGHT;
    out->camera_distance = v3_length(v3_sub(cam.target, cam.position));
    scene s;
    if (scene_load(study_scene_spec(ctx, label), &s, e) != 0)
        return -1;
    int rc = approx_render_gbuffer(&s, label, &cam, ctx->threads, &out->full, e);
    scene_free(&s);
    if (rc != 0)
        return -1;
    if (ss_half_resolution(&out->full.g, &out->half) != 0) {
        approx_input_free(&out->full);
        return gt_error_set(e, label, "out of memory");
    }
    return 0;
}

void gtao_talk_frame_free(gtao_talk_frame *f)
{
    ss_half_free(&f->half);
    approx_input_free(&f->full);
}

void gtao_talk_radius(float camera_distance, const ss_gbuffer *pass, gtao_params *p)
{
    p->radius = GTAO_TALK_RADIUS_FRACTION * camera_distance;
    p->falloff = GTAO_TALK_FALLOFF;
    p->max_radius_px = (float)pass->width;
}
