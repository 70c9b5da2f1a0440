/* A specular-occlusion variant from files to file
 * (specular_occlusion_approx.h). */
#include "specular_occlusion/specular_occlusion_approx.h"

#include <string.h>

#include "core/files/exr_io.h"
#include "core/reference_schema.h"
#include "core/roughness_setting.h"
#include "specular_occlusion/specular_occlusion_inputs.h"

/* The output: specocc.V, mask.A, the camera and the variant in the header. */
static int write_output(const char *path, const image *gbuffer, const so_pixel_inputs *in, const so_variant *v,
                        gt_error *e)
{
    image out;
    if (image_init(&out, in->width, in->height) != 0)
        return gt_error_set(e, path, "out of memory");
    float *vs = image_add_channel(&out, CH_SPECOCC), *mask = image_add_channel(&out, CH_MASK);
    char label[128];
    so_variant_label(v, label, sizeof label);
    int rc = vs && mask ? 0 : gt_error_set(e, path, "out of memory");
    if (rc == 0) {
        so_approx_evaluate(in, v, vs);
        memcpy(mask, in->mask, sizeof(float) * image_pixel_count(&out));
        rc = image_set_attribute(&out, ATTR_APPROX, label) |
             image_set_attribute(&out, ATTR_CAMERA, image_get_attribute(gbuffer, ATTR_CAMERA));
        rc = rc ? gt_error_set(e, path, "out of memory") : exr_write(path, &out, e);
    }
    image_free(&out);
    return rc;
}

/* The inputs checked against the variant, the table built, the output written. */
static int evaluate(const so_approx_files *f, const image *gbuffer, const so_pixel_inputs *in, so_variant *v,
                    gt_error *e)
{
    if (v->weighting == SO_AO_UNIFORM && !in->ao_uniform)
        return gt_error_set(e, f->ao, "no ao.Vuniform channel, which --ao-weighting uniform needs");
    so_lut lut = {0};
    int rc = 0;
    if (v->kind == SO_VARIANT_LUT && so_lut_build(&lut, f->lut_size, f->lobe, SO_AXES_ANGLES, f->threads) != 0)
        rc = gt_error_set(e, "approx specular-occlusion", "out of memory");
    v->lut = &lut;
    if (rc == 0)
        rc = write_output(f->output, gbuffer, in, v, e);
    so_lut_free(&lut);
    v->lut = NULL;
    return rc;
}

int so_approx_from_files(const so_approx_files *f, so_variant *v, gt_error *e)
{
    image gbuffer, ao;
    if (exr_read(f->gbuffer, &gbuffer, e) != 0)
        return -1;
    double roughness = roughness_is_material(f->roughness) ? so_reference_roughness(&gbuffer) : f->roughness;
    if (exr_read(f->ao, &ao, e) != 0) {
        image_free(&gbuffer);
        return -1;
    }
    so_pixel_inputs in;
    int rc = so_inputs_from_images(&gbuffer, f->gbuffer, &ao, f->ao, roughness, &in, e);
    if (rc == 0) {
        rc = evaluate(f, &gbuffer, &in, v, e);
        so_inputs_free(&in);
    }
    image_free(&gbuffer);
    image_free(&ao);
    return rc;
}
