#include "cli/specular_occlusion_approx.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/camera.h"
#include "core/reference_schema.h"

static const float *channel(const image *img, const char *what, const char *name, gt_error *e)
{
    const float *data = image_channel_data(img, name);
    if (!data)
        gt_error_set(e, what, "no channel %s", name);
    return data;
}

double so_reference_roughness(const image *reference)
{
    double value;
    return schema_get_real(reference, ATTR_ROUGHNESS, NULL, &value, NULL) == 1 ? value : -1.0;
}

void so_inputs_free(so_pixel_inputs *in)
{
    free(in->mask);
    memset(in, 0, sizeof *in);
}

static int allocate(so_pixel_inputs *in, int width, int height)
{
    size_t n = (size_t)width * height;
    memset(in, 0, sizeof *in);
    in->width = width, in->height = height;
    in->mask = calloc(6 * n, sizeof(float));
    if (!in->mask)
        return -1;
    in->n_dot_v = in->mask + n, in->beta = in->mask + 2 * n, in->ao_cosine = in->mask + 3 * n;
    in->ao_uniform = in->mask + 4 * n, in->roughness = in->mask + 5 * n;
    return 0;
}

int so_inputs_from_images(const image *gbuffer, const char *what_gbuffer, const image *ao, const char *what_ao,
                          double roughness, so_pixel_inputs *in, gt_error *e)
{
    static const char *const gnames[8] = {CH_N_X, CH_N_Y, CH_N_Z, CH_P_X, CH_P_Y, CH_P_Z, CH_MASK, CH_ROUGHNESS};
    static const char *const anames[5] = {CH_AO, CH_AO_UNIFORM, CH_BENT_X, CH_BENT_Y, CH_BENT_Z};
    const float *g[8], *a[5];
    for (int i = 0; i < 8; ++i)
        if (!(g[i] = channel(gbuffer, what_gbuffer, gnames[i], e)))
            return -1;
    for (int i = 0; i < 5; ++i)
        if (i != 1 && !(a[i] = channel(ao, what_ao, anames[i], e)))
            return -1;
    a[1] = image_channel_data(ao, anames[1]); /* optional: GTAO's output has one weighting */
    if (ao->width != gbuffer->width || ao->height != gbuffer->height)
        return gt_error_set(e, what_ao, "size %dx%d differs from the G-buffer's %dx%d", ao->width, ao->height,
                            gbuffer->width, gbuffer->height);
    const char *camera_json = image_get_attribute(gbuffer, ATTR_CAMERA);
    camera cam;
    if (!camera_json)
        return gt_error_set(e, what_gbuffer, "no gtlab.camera header attribute (not a gtlab G-buffer?)");
    if (camera_parse_json(camera_json, what_gbuffer, &cam, e) != 0)
        return -1;
    if (allocate(in, gbuffer->width, gbuffer->height) != 0)
        return gt_error_set(e, what_gbuffer, "out of memory");
    for (size_t p = 0; p < image_pixel_count(gbuffer); ++p) {
        if (g[6][p] < 0.5f)
            continue;
        vec3 n = v3(g[0][p], g[1][p], g[2][p]), pos = v3(g[3][p], g[4][p], g[5][p]);
        vec3 b = v3(a[2][p], a[3][p], a[4][p]);
        vec3 v = v3_normalize(v3_sub(cam.position, pos));
        float nv = v3_dot(n, v);
        vec3 r = v3_sub(v3_scale(n, 2.0f * nv), v); /* reflect(-v, n) */
        float blen = v3_length(b);
        double cos_beta = blen > 0.0f ? v3_dot(b, r) / blen : 1.0;
        in->mask[p] = 1.0f;
        in->n_dot_v[p] = fmaxf(nv, 0.0f);
        in->beta[p] = (float)acos(fmax(-1.0, fmin(1.0, cos_beta)));
        in->ao_cosine[p] = a[0][p];
        in->ao_uniform[p] = a[1] ? a[1][p] : NAN;
        in->roughness[p] = roughness >= 0.0 ? (float)roughness : g[7][p];
    }
    if (!a[1])
        in->ao_uniform = NULL;
    return 0;
}

int so_variant_parse(const char *text, so_variant *v)
{
    memset(v, 0, sizeof *v);
    v->u = 0.01;
    v->weighting = SO_AO_COSINE;
    v->mapping = SO_APERTURE_EXP2_ALPHA;
    if (strcmp(text, "ao") == 0)
        return v->kind = SO_VARIANT_AO, 0;
    if (strcmp(text, "lagarde") == 0)
        return v->kind = SO_VARIANT_LAGARDE, 0;
    if (strcmp(text, "lut") == 0)
        return v->kind = SO_VARIANT_LUT, 0;
    const char *mapping = NULL;
    if (strncmp(text, "cone-exact:", 11) == 0)
        v->kind = SO_VARIANT_CONE_EXACT, mapping = text + 11;
    else if (strncmp(text, "cone-oat:", 9) == 0)
        v->kind = SO_VARIANT_CONE_OAT, mapping = text + 9;
    else
        return -1;
    for (int m = 0; m < SO_APERTURE_COUNT; ++m)
        if (strcmp(mapping, so_aperture_name((so_aperture_mapping)m)) == 0)
            return v->mapping = (so_aperture_mapping)m, 0;
    return -1;
}

void so_variant_label(const so_variant *v, char *text, size_t size)
{
    switch (v->kind) {
    case SO_VARIANT_AO: snprintf(text, size, "ao"); break;
    case SO_VARIANT_LAGARDE: snprintf(text, size, "lagarde"); break;
    case SO_VARIANT_LUT:
        snprintf(text, size, "lut-%s-%d", v->lut ? so_lobe_name(v->lut->lobe) : "?", v->lut ? v->lut->size : 0);
        break;
    default:
        if (v->mapping == SO_APERTURE_PHONG_U)
            snprintf(text, size, "%s:phong-u=%.4g", v->kind == SO_VARIANT_CONE_EXACT ? "cone-exact" : "cone-oat", v->u);
        else
            snprintf(text, size, "%s:%s", v->kind == SO_VARIANT_CONE_EXACT ? "cone-exact" : "cone-oat",
                     so_aperture_name(v->mapping));
    }
}

static double evaluate_pixel(const so_pixel_inputs *in, const so_variant *v, size_t p)
{
    double ao = v->weighting == SO_AO_UNIFORM ? in->ao_uniform[p] : in->ao_cosine[p];
    double r = in->roughness[p], cos_av = so_visibility_cos_aperture(ao, v->weighting);
    switch (v->kind) {
    case SO_VARIANT_AO: return ao;
    case SO_VARIANT_LAGARDE: return so_lagarde(in->n_dot_v[p], in->ao_cosine[p], r * r);
    case SO_VARIANT_LUT: return so_lut_lookup(v->lut, acos(cos_av), in->beta[p], r);
    default:
        return so_cone_cone(cos_av, so_reflection_cos_aperture(v->mapping, r, v->u), in->beta[p],
                            v->kind == SO_VARIANT_CONE_EXACT);
    }
}

void so_approx_evaluate(const so_pixel_inputs *in, const so_variant *v, float *out)
{
    size_t n = (size_t)in->width * in->height;
#pragma omp parallel for schedule(static)
    for (size_t p = 0; p < n; ++p)
        out[p] = in->mask[p] >= 0.5f ? (float)evaluate_pixel(in, v, p) : 0.0f;
}
