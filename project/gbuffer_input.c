/* G-buffer input and approximation output; see gbuffer_input.h. */
#include "project/gbuffer_input.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "core/files/run_inputs.h"
#include "raytracer/reference_render.h"

ss_camera approx_ss_camera(const camera *cam)
{
    camera_view v = camera_view_from(cam);
    ss_camera c = {v.forward, v.right, v.up, v.tan_half_yfov, v.aspect};
    return c;
}

static int load_camera(const char *path, const char *camera_path, const image *img, camera *cam, gt_error *e)
{
    if (camera_path)
        return camera_read_json(camera_path, cam, e);
    const char *text = image_get_attribute(img, ATTR_CAMERA);
    if (text)
        return camera_parse_json(text, path, cam, e);
    char sidecar[4096];
    camera_sidecar_path(path, sidecar, sizeof sidecar);
    if (access(sidecar, F_OK) != 0)
        return gt_error_set(e, path, "no camera: no gtlab.camera header, no %s; give --camera", sidecar);
    run_inputs_note(sidecar, "the camera of the G-buffer:"); /* an input too, though no option named it */
    return camera_read_json(sidecar, cam, e);
}

/* Every surface pixel (mask.A = 1) has a finite depth and normal, and
 * mask.A itself is finite: a NaN would spread through the screen-space
 * passes (GTAO's denoiser turns one into 16). The first offender is named. */
static int check_finite(const ss_gbuffer *g, const char *path, gt_error *e)
{
    const char *names[4] = {CH_DEPTH, CH_N_X, CH_N_Y, CH_N_Z};
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            size_t i = (size_t)y * (size_t)g->width + (size_t)x;
            if (!isfinite(g->mask[i]))
                return gt_error_set(e, path, "pixel (%d, %d): %s is %g", x, y, CH_MASK, g->mask[i]);
            const float v[4] = {g->depth[i], g->normal[0][i], g->normal[1][i], g->normal[2][i]};
            for (int k = 0; k < 4 && g->mask[i] > 0; ++k)
                if (!isfinite(v[k]))
                    return gt_error_set(e, path, "pixel (%d, %d): %s is %g on a surface pixel (%s = 1); a G-buffer "
                                        "must be finite where it has a surface", x, y, names[k], v[k], CH_MASK);
        }
    return 0;
}

int approx_load(const char *path, const char *camera_path, approx_input *in, gt_error *e)
{
    memset(in, 0, sizeof *in);
    if (exr_read(path, &in->img, e) != 0)
        return -1;
    return approx_from_image(path, camera_path, in, e);
}

int approx_from_image(const char *path, const char *camera_path, approx_input *in, gt_error *e)
{
    int rc = load_camera(path, camera_path, &in->img, &in->cam, e);
    if (rc == 0 && (in->cam.width != in->img.width || in->cam.height != in->img.height))
        rc = gt_error_set(e, camera_path ? camera_path : path, "camera is %dx%d but the G-buffer is %dx%d",
                          in->cam.width, in->cam.height, in->img.width, in->img.height);
    if (rc == 0)
        rc = camera_validate(&in->cam, camera_path ? camera_path : path, e);
    if (rc == 0)
        rc = ss_gbuffer_from_image(&in->img, path, approx_ss_camera(&in->cam), &in->g, e);
    if (rc == 0)
        rc = check_finite(&in->g, path, e);
    if (rc != 0)
        image_free(&in->img);
    return rc;
}

void approx_input_free(approx_input *in) { image_free(&in->img); }

int approx_render_gbuffer(const scene *s, const char *name, const camera *cam, int threads, approx_input *in,
                          gt_error *e)
{
    memset(in, 0, sizeof *in);
    in->cam = *cam;
    reference_request req = {.quantity = QUANTITY_GBUFFER, .sampling = {.threads = threads}, .normals = NORMAL_SHADING};
    render_stats stats;
    if (reference_render(s, name, cam, &req, &in->img, &stats, e) != 0)
        return -1;
    if (ss_gbuffer_from_image(&in->img, name, approx_ss_camera(cam), &in->g, e) != 0) {
        image_free(&in->img);
        return -1;
    }
    return 0;
}

int approx_output_init(const approx_input *in, const char *technique, const char *settings, image *out)
{
    if (image_init(out, in->img.width, in->img.height) != 0)
        return -1;
    float *mask = image_add_channel(out, CH_MASK);
    int rc = mask ? 0 : -1;
    if (mask)
        memcpy(mask, in->g.mask, sizeof *mask * image_pixel_count(out));
    rc |= image_set_attribute(out, ATTR_VERSION, GTLAB_VERSION);
    rc |= image_set_attribute(out, ATTR_QUANTITY, QUANTITY_NAME_APPROX);
    rc |= image_set_attribute(out, ATTR_TECHNIQUE, technique);
    rc |= image_set_attribute(out, ATTR_SETTINGS, settings);
    for (int k = 0; k < 2; ++k) {
        const char *key = k ? ATTR_SCENE : ATTR_CAMERA, *value = image_get_attribute(&in->img, key);
        if (value)
            rc |= image_set_attribute(out, key, value);
    }
    if (rc != 0)
        image_free(out);
    return rc;
}
