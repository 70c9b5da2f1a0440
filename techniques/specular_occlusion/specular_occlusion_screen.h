/* The real-time specular-occlusion variants as a screen pass: from the
 * G-buffer a shader has (normal, position, mask, roughness) and an AO /
 * bent-normal buffer, the per-pixel inputs of GTSO (n.v, the angle beta
 * between the reflection vector and the bent normal, the AO of either
 * weighting, the perceptual roughness), then one variant of
 * specular_occlusion/specular_occlusion.h or the cone/lobe LUT per pixel.
 *
 *   v = normalize(eye - P),  R = 2 (n.v) n - v  (reflect(-v, n)),
 *   cos beta = (b.R) / |b|  (1 where the bent normal b is zero),
 *   n.v stored clamped to >= 0.
 *
 * Dependency: the LUT variant looks its table up with luts/
 * specular_occlusion_lut.h (so_lut_lookup), so this pass, unlike the rest of
 * realtime/, includes luts/ (luts/ needs only core/: no cycle). Loading the
 * buffers from EXR files and the camera is the caller's job
 * (specular_occlusion/specular_occlusion_inputs.h). */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SCREEN_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_SCREEN_H

#include <stddef.h>

#include "core/vec3.h"
#include "specular_occlusion/specular_occlusion_lut.h"
#include "specular_occlusion/specular_occlusion.h"

/* The buffers the pass reads, one float per pixel each (row-major,
 * width x height). ao_uniform may be NULL (GTAO's output has one weighting). */
typedef struct {
    int width, height;
    const float *normal[3], *position[3], *mask, *roughness; /* G-buffer: N, P (world), mask.A, roughness.Y */
    const float *ao_cosine, *ao_uniform, *bent[3];           /* AO buffer: ao.V, ao.Vuniform, bent normal */
} so_screen_buffers;

typedef struct {
    int width, height;
    /* per pixel: mask (1 = surface), n.v, beta, cosine AO, uniform AO, perceptual roughness */
    float *mask, *n_dot_v, *beta, *ao_cosine, *ao_uniform, *roughness;
} so_pixel_inputs;

/* The per-pixel inputs seen from `eye` (0 outside the mask). roughness >= 0
 * replaces the buffer's roughness everywhere; in->ao_uniform is NULL when
 * the buffers have none. Returns 0, or -1 when out of memory. */
int so_inputs_compute(const so_screen_buffers *b, vec3 eye, double roughness, so_pixel_inputs *in);
void so_inputs_free(so_pixel_inputs *in);

typedef enum {
    SO_VARIANT_AO,
    SO_VARIANT_LAGARDE,
    SO_VARIANT_CONE_EXACT,
    SO_VARIANT_CONE_OAT,
    SO_VARIANT_LUT,
    SO_VARIANT_CONE_HORIZON, /* exact caps, normalised above the horizon (so_cone_cone_above_horizon) */
    SO_VARIANT_SG            /* spherical Gaussians, Unity HDRP (specular_occlusion/specular_occlusion_sg.h) */
} so_variant_kind;

typedef struct {
    so_variant_kind kind;
    so_aperture_mapping mapping; /* cone variants */
    double u;                    /* SO_APERTURE_PHONG_U */
    so_ao_weighting weighting;   /* which AO gives the visibility cone */
    const so_lut *lut;           /* SO_VARIANT_LUT */
} so_variant;

/* "ao", "lagarde", "lut", "sg", "cone-exact:<mapping>", "cone-oat:<mapping>"
 * with <mapping> one of so_aperture_name's. Returns 0 or -1. */
int so_variant_parse(const char *text, so_variant *v);
void so_variant_label(const so_variant *v, char *text, size_t size);

/* V_s of one pixel p inside the mask:
 *   ao       the AO of the variant's weighting
 *   lagarde  so_lagarde(n.v, cosine AO, r^2)
 *   lut      so_lut_lookup(a_v, beta, r), a_v from the AO (so_visibility_cos_aperture)
 *   sg       so_sg_occlusion(cos a_v, cos beta, n.v, r^2)
 *   cone-*   so_cone_cone(cos a_v, cos a_s(mapping, r, u), beta). */
double so_approx_pixel(const so_pixel_inputs *in, const so_variant *v, size_t p);
/* V_s of every pixel into out (0 outside the mask). */
void so_approx_evaluate(const so_pixel_inputs *in, const so_variant *v, float *out);

#endif
