/* The specular-occlusion screen pass's inputs (realtime/
 * specular_occlusion_screen.h) from gtlab's files: the G-buffer channels
 * (N.*, P.*, roughness.Y, mask.A) and the camera (header gtlab.camera) of a
 * reference or G-buffer EXR, and the AO / bent normal (ao.V, bent.*, and if
 * present ao.Vuniform) of an AO EXR of the same view. Used by `gtlab approx
 * specular-occlusion`, `gtlab fit aperture` and the specular-occlusion study. */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_INPUTS_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_INPUTS_H

#include "core/error.h"
#include "core/image.h"
#include "specular_occlusion/aperture_fit.h"
#include "specular_occlusion/specular_occlusion_screen.h"

/* From `gbuffer` and `ao` (the same size; may be the same image; `gtlab
 * approx gtao` output has no ao.Vuniform, and then in->ao_uniform is NULL).
 * roughness >= 0 replaces roughness.Y. Returns 0, or -1 with e naming the
 * file at fault (a missing channel or camera, sizes that differ). */
int so_inputs_from_images(const image *gbuffer, const char *what_gbuffer, const image *ao, const char *what_ao,
                          double roughness, so_pixel_inputs *in, gt_error *e);

/* The buffers so_inputs_from_images reads (pointers into the images) and
 * the eye position of the G-buffer's camera. Returns 0, or -1 with e. */
int so_buffers_from_images(const image *gbuffer, const char *what_gbuffer, const image *ao, const char *what_ao,
                           so_screen_buffers *b, vec3 *eye, gt_error *e);

/* The roughness a specular-occlusion reference was rendered with (its
 * gtlab.roughness attribute), or -1 when it used the materials'. */
double so_reference_roughness(const image *reference);

/* A fit case from a specular-occlusion reference (its G-buffer, its
 * roughness, `channel` = specocc.V, specocc_d.V or specocc_phong.V) and an
 * AO reference of the same view. c->reference points into `reference`. */
int aperture_case_from_images(aperture_case *c, const image *reference, const char *what_reference, const image *ao,
                              const char *what_ao, const char *channel, gt_error *e);

/* count (reference, AO) file pairs read into refs[i], aos[i] and made into
 * cases[i] (aperture_case_from_images). *loaded counts the pairs read;
 * aperture_cases_free releases them, also after a failure. Returns 0, or -1
 * with e naming the file at fault. */
int aperture_cases_load(const char *const *references, const char *const *ao_paths, int count, const char *channel,
                        image *refs, image *aos, aperture_case *cases, int *loaded, gt_error *e);
void aperture_cases_free(image *refs, image *aos, aperture_case *cases, int loaded);

#endif
