/* The specular-occlusion screen pass (specular_occlusion/specular_occlusion_screen.c)
 * on a 2x2 synthetic G-buffer seen from eye = (0, 0, 5):
 *  - the per-pixel inputs: n.v and beta worked out by hand (a pixel facing
 *    the eye, one seen at 45 degrees with a bent normal of length 2 at 45
 *    degrees from the reflection vector, one outside the mask, one grazing
 *    with a zero bent normal), the roughness override, no uniform AO;
 *  - every variant equals, pixel by pixel, the functions of
 *    specular_occlusion/specular_occlusion.h (and so_lut_lookup) it stands for, and 0
 *    outside the mask;
 *  - so_variant_parse and so_variant_label round-trip, and reject unknown text. */
#include <string.h>

#include "specular_occlusion/specular_occlusion_screen.h"
#include "specular_occlusion/specular_occlusion_sg.h"
#include "tests/check.h"

enum { PIXELS = 4 };

static const float nx[PIXELS] = {0, 0, 0, 0}, ny[PIXELS] = {0, 0, 0, 1}, nz[PIXELS] = {1, 1, 1, 0};
static const float px[PIXELS] = {0, 5, 0, 0}, py[PIXELS] = {0, 0, 0, 0}, pz[PIXELS] = {0, 0, 0, 0};
static const float bx[PIXELS] = {0, 2, 0, 0}, by[PIXELS] = {0, 0, 0, 0}, bz[PIXELS] = {1, 0, 1, 0};
static const float mask[PIXELS] = {1, 1, 0, 1}, roughness[PIXELS] = {0.3f, 0.6f, 0.9f, 0.5f};
static const float ao_cosine[PIXELS] = {0.8f, 0.5f, 0.3f, 0.6f}, ao_uniform[PIXELS] = {0.7f, 0.4f, 0.2f, 0.5f};

static so_screen_buffers buffers(int with_uniform)
{
    so_screen_buffers b = {2, 2, {nx, ny, nz}, {px, py, pz}, mask, roughness,
                           ao_cosine, with_uniform ? ao_uniform : NULL, {bx, by, bz}};
    return b;
}

static void check_inputs(void)
{
    so_screen_buffers b = buffers(1);
    so_pixel_inputs in;
    CHECK(so_inputs_compute(&b, v3(0, 0, 5), -1.0, &in) == 0);
    static const double n_dot_v[PIXELS] = {1.0, 0.70710678, 0.0, 0.0}, beta[PIXELS] = {0.0, M_PI / 4, 0.0, 0.0};
    for (int p = 0; p < PIXELS; ++p) {
        CHECK(in.mask[p] == mask[p]);
        CHECK_NEAR(in.n_dot_v[p], n_dot_v[p], 1e-6);
        CHECK_NEAR(in.beta[p], beta[p], 1e-6); /* pixel 3: zero bent normal, beta = 0 */
        CHECK(in.roughness[p] == (mask[p] ? roughness[p] : 0.0f));
        CHECK(in.ao_uniform[p] == (mask[p] ? ao_uniform[p] : 0.0f));
    }
    so_inputs_free(&in);
    b = buffers(0);
    CHECK(so_inputs_compute(&b, v3(0, 0, 5), 0.25, &in) == 0);
    CHECK(in.ao_uniform == NULL);
    CHECK(in.roughness[0] == 0.25f && in.roughness[3] == 0.25f && in.roughness[2] == 0.0f);
    so_inputs_free(&in);
}

/* The image pass is the per-pixel function on the mask and 0 off it; and
 * the per-pixel function means what its kind says: the AO variant is the
 * chosen weighting's AO, Lagarde's is so_lagarde at alpha = r^2 (always of
 * the cosine AO), and every variant is a fraction. */
static void check_variant(const so_pixel_inputs *in, const so_variant *v)
{
    float out[PIXELS];
    so_approx_evaluate(in, v, out);
    char label[64];
    so_variant_label(v, label, sizeof label);
    for (int p = 0; p < PIXELS; ++p) {
        double at = so_approx_pixel(in, v, (size_t)p), r = in->roughness[p];
        double ao = v->weighting == SO_AO_UNIFORM ? in->ao_uniform[p] : in->ao_cosine[p];
        CHECK_MSG(out[p] == (mask[p] ? (float)at : 0.0f), "%s at pixel %d: %g", label, p, out[p]);
        if (!mask[p])
            continue;
        CHECK_MSG(at >= 0.0 && at <= 1.0 + 1e-6, "%s at pixel %d: %g outside [0, 1]", label, p, at);
        if (v->kind == SO_VARIANT_AO)
            CHECK(at == ao);
        if (v->kind == SO_VARIANT_LAGARDE)
            CHECK(at == so_lagarde(in->n_dot_v[p], in->ao_cosine[p], r * r));
        if (v->kind == SO_VARIANT_SG)
            CHECK(at == so_sg_occlusion(so_visibility_cos_aperture(ao, v->weighting), cos(in->beta[p]),
                                        in->n_dot_v[p], r * r));
    }
}

static void check_variants(void)
{
    so_screen_buffers b = buffers(1);
    so_pixel_inputs in;
    so_lut lut;
    CHECK(so_inputs_compute(&b, v3(0, 0, 5), -1.0, &in) == 0);
    CHECK(so_lut_build(&lut, 8, SO_LOBE_GGX, SO_AXES_ANGLES, 1) == 0);
    static const char *const kinds[] = {"ao", "lagarde", "lut", "sg", "cone-exact:", "cone-oat:"};
    for (int k = 0; k < 6; ++k)
        for (int m = 0; m < (k < 4 ? 1 : SO_APERTURE_COUNT); ++m)
            for (int w = 0; w < 2; ++w) {
                char text[64];
                snprintf(text, sizeof text, "%s%s", kinds[k], k < 4 ? "" : so_aperture_name((so_aperture_mapping)m));
                so_variant v;
                CHECK(so_variant_parse(text, &v) == 0);
                v.lut = &lut, v.u = 0.05, v.weighting = w ? SO_AO_UNIFORM : SO_AO_COSINE;
                check_variant(&in, &v);
            }
    so_lut_free(&lut);
    so_inputs_free(&in);
}

static void check_labels(void)
{
    static const char *const texts[] = {"ao", "lagarde", "sg", "cone-exact:drobot", "cone-oat:exp2-perceptual",
                                        "cone-exact:exp2-alpha"};
    char label[64];
    so_variant v;
    for (int i = 0; i < 6; ++i) {
        CHECK(so_variant_parse(texts[i], &v) == 0);
        so_variant_label(&v, label, sizeof label);
        CHECK_MSG(strcmp(label, texts[i]) == 0, "%s -> %s", texts[i], label);
    }
    CHECK(so_variant_parse("cone-oat:phong-u", &v) == 0 && v.mapping == SO_APERTURE_PHONG_U);
    so_variant_label(&v, label, sizeof label);
    CHECK(strcmp(label, "cone-oat:phong-u=0.01") == 0);
    CHECK(so_variant_parse("cone-exact:nope", &v) != 0);
    CHECK(so_variant_parse("cone", &v) != 0);
}

int main(void)
{
    check_inputs();
    check_variants();
    check_labels();
    return check_report("test_specular_occlusion_screen");
}
