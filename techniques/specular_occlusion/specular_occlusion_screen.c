#include "specular_occlusion/specular_occlusion_screen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/roughness_setting.h"
#include "specular_occlusion/specular_occlusion_sg.h"

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

static vec3 load3(const float *const c[3], size_t p) { return v3(c[0][p], c[1][p], c[2][p]); }

/* n.v and beta of one surface pixel. */
static void view_angles(const so_screen_buffers *b, vec3 eye, size_t p, float *n_dot_v, float *beta)
{
    vec3 n = load3(b->normal, p), pos = load3(b->position, p), bent = load3(b->bent, p);
    vec3 v = v3_normalize(v3_sub(eye, pos));
    float nv = v3_dot(n, v);
    vec3 r = v3_sub(v3_scale(n, 2.0f * nv), v); /* reflect(-v, n) */
    float blen = v3_length(bent);
    double cos_beta = blen > 0.0f ? v3_dot(bent, r) / blen : 1.0;
    *n_dot_v = fmaxf(nv, 0.0f);
    *beta = (float)acos(fmax(-1.0, fmin(1.0, cos_beta)));
}

int so_inputs_compute(const so_screen_buffers *b, vec3 eye, double roughness, so_pixel_inputs *in)
{
    if (allocate(in, b->width, b->height) != 0)
        return -1;
    for (size_t p = 0; p < (size_t)b->width * b->height; ++p) {
        if (b->mask[p] < 0.5f)
            continue;
        view_angles(b, eye, p, &in->n_dot_v[p], &in->beta[p]);
        in->mask[p] = 1.0f;
        in->ao_cosine[p] = b->ao_cosine[p];
        in->ao_uniform[p] = b->ao_uniform ? b->ao_uniform[p] : NAN;
        in->roughness[p] = (float)roughness_choose(roughness, b->roughness[p]);
    }
    if (!b->ao_uniform)
        in->ao_uniform = NULL;
    return 0;
}

/* The cone variants' "<kind>:<mapping>" text; -1 when it is not one. */
static int parse_cone(const char *text, so_variant *v)
{
    const char *mapping = NULL;
    if (strncmp(text, "cone-exact:", 11) == 0)
        v->kind = SO_VARIANT_CONE_EXACT, mapping = text + 11;
    else if (strncmp(text, "cone-oat:", 9) == 0)
        v->kind = SO_VARIANT_CONE_OAT, mapping = text + 9;
    else if (strncmp(text, "cone-horizon:", 13) == 0)
        v->kind = SO_VARIANT_CONE_HORIZON, mapping = text + 13;
    else
        return -1;
    for (int m = 0; m < SO_APERTURE_COUNT; ++m)
        if (strcmp(mapping, so_aperture_name((so_aperture_mapping)m)) == 0)
            return v->mapping = (so_aperture_mapping)m, 0;
    return -1;
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
    if (strcmp(text, "sg") == 0)
        return v->kind = SO_VARIANT_SG, 0;
    return parse_cone(text, v);
}

void so_variant_label(const so_variant *v, char *text, size_t size)
{
    const char *cone = v->kind == SO_VARIANT_CONE_EXACT ? "cone-exact"
                       : v->kind == SO_VARIANT_CONE_OAT ? "cone-oat"
                                                         : "cone-horizon";
    switch (v->kind) {
    case SO_VARIANT_AO: snprintf(text, size, "ao"); break;
    case SO_VARIANT_LAGARDE: snprintf(text, size, "lagarde"); break;
    case SO_VARIANT_SG: snprintf(text, size, "sg"); break;
    case SO_VARIANT_LUT:
        snprintf(text, size, "lut-%s-%d", v->lut ? so_lobe_name(v->lut->lobe) : "?", v->lut ? v->lut->size : 0);
        break;
    default:
        if (so_aperture_takes_u(v->mapping))
            snprintf(text, size, "%s:%s=%.4g", cone, so_aperture_name(v->mapping), v->u);
        else
            snprintf(text, size, "%s:%s", cone, so_aperture_name(v->mapping));
    }
}

double so_approx_pixel(const so_pixel_inputs *in, const so_variant *v, size_t p)
{
    double ao = v->weighting == SO_AO_UNIFORM ? in->ao_uniform[p] : in->ao_cosine[p];
    double r = in->roughness[p], cos_av = so_visibility_cos_aperture(ao, v->weighting);
    switch (v->kind) {
    case SO_VARIANT_AO: return ao;
    case SO_VARIANT_LAGARDE: return so_lagarde(in->n_dot_v[p], in->ao_cosine[p], r * r);
    case SO_VARIANT_LUT: return so_lut_lookup(v->lut, acos(cos_av), in->beta[p], r);
    case SO_VARIANT_SG: return so_sg_occlusion(cos_av, cos(in->beta[p]), in->n_dot_v[p], r * r);
    case SO_VARIANT_CONE_HORIZON:
        return so_cone_cone_above_horizon(cos_av, so_reflection_cos_aperture(v->mapping, r, v->u), in->beta[p],
                                          in->n_dot_v[p]);
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
        out[p] = in->mask[p] >= 0.5f ? (float)so_approx_pixel(in, v, p) : 0.0f;
}
