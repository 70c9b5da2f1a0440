/* The AO reference's control variate (`gtlab render ao --control-variate`,
 * issue 13 part 3): each pixel's height-field horizons, found once before
 * sampling, turn each AO sample V(w) into V(w) - g(w) + G
 * (techniques/ao/slice_horizons.h), for ao.V and ao.Vuniform; the bent normal
 * stays plain. The corrected samples go through the same exact film, so
 * standard errors come from them and merges stay exact; the mode is
 * recorded in the header (ATTR_CONTROL_VARIATE) and merge refuses to mix
 * modes. */
#ifndef GTLAB_AO_AO_CONTROL_VARIATE_H
#define GTLAB_AO_AO_CONTROL_VARIATE_H

#include "core/error.h"
#include "raytracer/gbuffer.h"
#include "ao/slice_horizons.h"

typedef enum { AO_CONTROL_VARIATE_NONE, AO_CONTROL_VARIATE_HEIGHTFIELD } ao_control_variate;

/* "none" or "heightfield". */
const char *ao_control_variate_name(ao_control_variate mode);
/* name -> mode; -1 when unknown (mode unchanged). */
int ao_control_variate_parse(const char *name, ao_control_variate *mode);

/* Per G-buffer pixel (row-major) its horizons; background pixels are off. */
typedef struct {
    long pixel_count;
    slice_horizons *pixels;
} ao_control_variate_field;

/* The coefficient. Any beta fixed independently of a pixel's samples keeps
 * V - beta (g - G) unbiased; the variance is least at beta = Cov(V, g) /
 * Var(g). Each pixel estimates it from a pilot of AO_CONTROL_VARIATE_PILOT
 * samples of its own that are never reused: dimension pair 1 (the estimates
 * use pair 0) of the pixel's sequence under the fixed seed
 * AO_CONTROL_VARIATE_PILOT_SEED, so beta depends on the scene, camera and
 * pixel only, not on the render's seed or sample block, and parts of a
 * render merge into the same bits as the whole. beta is clamped to [0, 1]
 * (1: trust the height field; 0: plain sampling), and is 1 when g does not
 * vary over the pilot (a plane: V - (g - G) = 1 exactly). One beta per
 * estimator (cosine, uniform). */
enum { AO_CONTROL_VARIATE_PILOT = 32 };
#define AO_CONTROL_VARIATE_PILOT_SEED 0x5bd1e995u

/* Finds every covered pixel's horizons in the depth buffer of gb (the
 * height field of techniques/ao/heightfield_ao_integrator.h, occluders within
 * max_distance) and its coefficients from its pilot traced in es, with
 * `threads` threads; deterministic for any count. Returns 0, or -1 when
 * out of memory. */
int ao_control_variate_build(ao_control_variate_field *field, const embree_scene *es, const gbuffer *gb,
                             float max_distance, int threads);
void ao_control_variate_free(ao_control_variate_field *field);

#endif
