/* The real-time specular-occlusion variants run on a G-buffer and an AO /
 * bent-normal image, as `gtlab approx specular-occlusion`, `gtlab fit
 * aperture` and the `gtlab all` stage use them: the per-pixel inputs a
 * shader would have (n.v, the reflection vector's angle beta to the bent
 * normal, the AO of either weighting, the roughness), then one variant of
 * realtime/specular_occlusion.h or luts/specular_occlusion_lut.h per pixel. */
#ifndef GTLAB_CLI_SPECULAR_OCCLUSION_APPROX_H
#define GTLAB_CLI_SPECULAR_OCCLUSION_APPROX_H

#include <stddef.h>

#include "core/error.h"
#include "core/image.h"
#include "luts/specular_occlusion_lut.h"
#include "realtime/specular_occlusion.h"

typedef struct {
    int width, height;
    /* per pixel: mask (1 = surface), n.v, beta, cosine AO, uniform AO, perceptual roughness */
    float *mask, *n_dot_v, *beta, *ao_cosine, *ao_uniform, *roughness;
} so_pixel_inputs;

/* From the G-buffer channels (N.*, P.*, roughness.Y, mask.A, header
 * gtlab.camera) of `gbuffer` and ao.V, bent.* and, if present, ao.Vuniform
 * of `ao` (the same size; may be the same image; `gtlab approx gtao` output
 * has no ao.Vuniform, and then in->ao_uniform is NULL). roughness >= 0
 * replaces roughness.Y. */
int so_inputs_from_images(const image *gbuffer, const char *what_gbuffer, const image *ao, const char *what_ao,
                          double roughness, so_pixel_inputs *in, gt_error *e);
void so_inputs_free(so_pixel_inputs *in);
/* The roughness a specular-occlusion reference was rendered with (its
 * gtlab.settings "roughness=R"), or -1 when it used the materials'. */
double so_reference_roughness(const image *reference);

typedef enum { SO_VARIANT_AO, SO_VARIANT_LAGARDE, SO_VARIANT_CONE_EXACT, SO_VARIANT_CONE_OAT, SO_VARIANT_LUT } so_variant_kind;

typedef struct {
    so_variant_kind kind;
    so_aperture_mapping mapping; /* cone variants */
    double u;                    /* SO_APERTURE_PHONG_U */
    so_ao_weighting weighting;   /* which AO gives the visibility cone */
    const so_lut *lut;           /* SO_VARIANT_LUT */
} so_variant;

/* "ao", "lagarde", "lut", "cone-exact:<mapping>", "cone-oat:<mapping>" with
 * <mapping> one of so_aperture_name's. Returns 0 or -1. */
int so_variant_parse(const char *text, so_variant *v);
void so_variant_label(const so_variant *v, char *text, size_t size);

/* V_s of every pixel into out (0 outside the mask). */
void so_approx_evaluate(const so_pixel_inputs *in, const so_variant *v, float *out);

#endif
