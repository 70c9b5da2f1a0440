/* A scene's 3-D and height-field AO references; see gtao_scene_refs.h. */
#include "gtao/gtao_scene_refs.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "ao/ao_quantity.h"
#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"

/* The 3-D reference's channels, or -1 with e naming the file. */
static int bind_3d(gtao_scene_refs *s, const char *ref_path, gt_error *e)
{
    static const char *const bent[3] = CH_BENT_XYZ;
    s->width = s->in.img.width;
    s->height = s->in.img.height;
    s->mask = s->in.g.mask;
    s->ref3d = image_channel_data(&s->in.img, CH_AO);
    s->ref3d_stderr = image_channel_data(&s->in.img, CH_AO_STDERR);
    for (int c = 0; c < 3; ++c)
        s->bent[c] = image_channel_data(&s->in.img, bent[c]);
    if (!s->ref3d || !s->ref3d_stderr)
        return gt_error_set(e, ref_path, "missing channel %s or %s (not an AO reference)", CH_AO, CH_AO_STDERR);
    return 0;
}

/* The height-field reference's channels, or -1 with e naming the file. */
static int bind_hf(gtao_scene_refs *s, const char *ref_path, const char *hf_path, gt_error *e)
{
    s->hf_ao = image_channel_data(&s->hf, CH_AO);
    s->hf_stderr = image_channel_data(&s->hf, CH_AO_STDERR);
    if (!s->hf_ao || !s->hf_stderr)
        return gt_error_set(e, hf_path, "missing channel %s or %s (not an AO reference)", CH_AO, CH_AO_STDERR);
    if (s->hf.width != s->width || s->hf.height != s->height)
        return gt_error_set(e, hf_path, "%dx%d, but its 3-D reference %s is %dx%d", s->hf.width, s->hf.height,
                            ref_path, s->width, s->height);
    return 0;
}

int gtao_scene_refs_load_3d(const char *refs_dir, const char *scene, gtao_scene_refs *out, gt_error *e)
{
    char ref_path[4096];
    memset(out, 0, sizeof *out);
    snprintf(out->scene, sizeof out->scene, "%s", scene);
    snprintf(ref_path, sizeof ref_path, "%s/%s.exr", refs_dir, scene);
    if (approx_load(ref_path, NULL, &out->in, e) != 0)
        return -1;
    if (bind_3d(out, ref_path, e) != 0) {
        gtao_scene_refs_free(out);
        return -1;
    }
    out->vo_radius = 0.25f * v3_length(v3_sub(out->in.cam.target, out->in.cam.position));
    return 0;
}

int gtao_scene_refs_load(const char *refs_dir, const char *gtao_dir, const char *scene, gtao_scene_refs *out,
                         gt_error *e)
{
    char ref_path[4096], hf_path[4096];
    if (gtao_scene_refs_load_3d(refs_dir, scene, out, e) != 0)
        return -1;
    snprintf(ref_path, sizeof ref_path, "%s/%s.exr", refs_dir, scene);
    snprintf(hf_path, sizeof hf_path, "%s/%s_heightfield.exr", gtao_dir, scene);
    if (exr_read(hf_path, &out->hf, e) != 0 || bind_hf(out, ref_path, hf_path, e) != 0) {
        gtao_scene_refs_free(out);
        return -1;
    }
    return 0;
}

void gtao_scene_refs_free(gtao_scene_refs *s)
{
    approx_input_free(&s->in);
    image_free(&s->hf);
    memset(s, 0, sizeof *s);
}

gtao_params gtao_scene_params(const gtao_scene_refs *s, int preset)
{
    gtao_params p;
    gtao_preset(gtao_preset_names[preset], &p);
    p.radius = 1e6f;
    p.falloff = 0.0f;
    p.max_radius_px = (float)s->width;
    p.frames = 1;
    return p;
}

int gtao_render_heightfield(const study_context *ctx, const char *spec, const camera *cam, int spp,
                            double noise_budget, const char *path, image *hf, gt_error *e)
{
    scene s;
    if (scene_load(spec, &s, e) != 0)
        return -1;
    reference_request req = {.quantity = QUANTITY_HEIGHTFIELD_AO,
                             .sampling = {.spp = spp, .seed = 1, .target_stderr = noise_budget, .threads = ctx->threads},
                             .normals = NORMAL_SHADING};
    render_stats stats;
    int rc = reference_render(&s, spec, cam, &req, hf, &stats, e);
    scene_free(&s);
    if (rc == 0 && (rc = exr_write(path, hf, e)) != 0)
        image_free(hf);
    return rc;
}
