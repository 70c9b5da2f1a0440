/* One specular-occlusion variant (specular_occlusion/specular_occlusion_screen.h) on
 * a G-buffer file and an AO / bent-normal file of the same view
 * (specular_occlusion_inputs.h), written as an EXR: specocc.V, mask.A, the
 * G-buffer's camera and the variant's label (gtlab.approx) in the header,
 * so `gtlab compare ref.exr out.exr --channel specocc.V` scores it. Used by
 * `gtlab approx specular-occlusion`. */
#ifndef GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_APPROX_H
#define GTLAB_SPECULAR_OCCLUSION_SPECULAR_OCCLUSION_APPROX_H

#include "core/error.h"
#include "specular_occlusion/specular_occlusion_lut.h"
#include "specular_occlusion/specular_occlusion_screen.h"

typedef struct {
    const char *gbuffer, *ao, *output; /* file paths */
    double roughness;                  /* < 0: the G-buffer reference's (its --roughness), else roughness.Y */
    int lut_size;                      /* the LUT variant's table, built on the fly */
    so_lobe lobe;
    int threads;                       /* for building the table */
} so_approx_files;

/* Reads both files, evaluates variant v on every pixel (v->lut is set to the
 * table built here for SO_VARIANT_LUT) and writes f->output. Returns 0, or
 * -1 with e naming the file at fault (a missing channel, ao.Vuniform absent
 * while v asks for the uniform weighting) or saying it ran out of memory. */
int so_approx_from_files(const so_approx_files *f, so_variant *v, gt_error *e);

#endif
