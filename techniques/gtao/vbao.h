/* Visibility-bitmask ambient occlusion (VBAO): Therrien, Levesque and Gilet,
 * "Screen Space Indirect Lighting with Visibility Bitmask", 2023. GTAO's
 * slices (gtao.h: the same slice planes, samples, spatio-temporal
 * pattern, slice weight and denoisers), but instead of one horizon per side
 * each slice keeps a bitmask of `sectors` equal angles over the normal's
 * half-circle: theta in [n - pi/2, n + pi/2] maps to x = (theta - n)/pi + 1/2
 * in [0, 1], sector k covering [k/N, (k+1)/N]. Every depth sample is an
 * occluder of constant thickness T: it occupies the sectors between the
 * angle of its front face (the depth buffer's point q) and that of its back
 * face, so light passes behind thin objects; T = INFINITY is GTAO's height
 * field (the union of [front, limit] over a side is [horizon, limit]).
 *
 * What the paper leaves open, gtlab's choices (README.md,
 * "Visibility-bitmask AO"):
 *  - the back face: the paper's listing offsets q by -v T (v the view vector
 *    of the centre pixel: VBAO_BACK_VIEW); VBAO_BACK_DEPTH moves q along its
 *    own eye ray to depth + T, the slab of the thickness-T height-field
 *    reference (techniques/ao/heightfield_ao_integrator.h). Scaling q from the
 *    eye keeps it in the slice plane, so the brute force converges to that
 *    reference;
 *  - what a sample occupies: its segment from front to back face, as
 *    published, except in the exact mode (steps 0), where each pixel cell's
 *    two end samples occupy the hull of their intervals (the slab of the
 *    cell's planar piece): point samples let light leak between them;
 *  - rounding an angle interval [lo, hi] to sectors: the paper's
 *    (VBAO_ROUND_PAPER: start floor(lo N), count ceil((hi - lo) N)) or the
 *    sectors whose centre lies in it (VBAO_ROUND_CENTRE: each boundary off
 *    by at most half a sector, either way);
 *  - the visibility: the paper counts free sectors, 1 - popcount / N
 *    (VBAO_COUNT_EQUAL: every equal angle weighs the same, neither the
 *    cosine nor the solid-angle measure); VBAO_COUNT_COSINE and
 *    VBAO_COUNT_UNIFORM weigh each free run of sectors by its exact share of
 *    GTAO's inner integrals (gtao_integrate_arc_cosine, _uniform), so they
 *    converge to ao.V and ao.Vuniform;
 *  - the radius: a sample farther than gtao.radius is left out (no falloff);
 *  - the bent normal: the cosine-weighted mean direction of the free runs
 *    (gtao_integrate_arc_bent over each), weighted like GTAO's. */
#ifndef GTLAB_GTAO_VBAO_H
#define GTLAB_GTAO_VBAO_H

#include <stdint.h>

#include "gtao/gtao.h"

#define VBAO_MAX_SECTORS 32

typedef enum { VBAO_COUNT_COSINE, VBAO_COUNT_UNIFORM, VBAO_COUNT_EQUAL } vbao_counting;
typedef enum { VBAO_BACK_VIEW, VBAO_BACK_DEPTH } vbao_backface;
typedef enum { VBAO_ROUND_PAPER, VBAO_ROUND_CENTRE } vbao_rounding;

typedef struct {
    /* slices, steps, radius, max_radius_px, pattern, fast_math, denoise and
     * frames as GTAO's; its weighting, falloff, thickness heuristic and bent
     * choice are not used */
    gtao_params gtao;
    int sectors;     /* 1..VBAO_MAX_SECTORS */
    float thickness; /* view-space units; INFINITY: the infinite height field */
    vbao_counting counting;
    vbao_backface backface;
    vbao_rounding rounding;
} vbao_params;

/* GTAO preset `preset` (a gtao_preset_id) with 32 sectors, thickness T and
 * the paper's choices (VBAO_PAPER: equal count, back face along -v, its
 * rounding) or gtlab's (VBAO_EXACT: cosine counting, back face at depth + T,
 * centre rounding: what converges to the thickness-T reference). */
typedef enum { VBAO_PAPER, VBAO_EXACT } vbao_choices;
vbao_params vbao_preset(int preset, float thickness, vbao_choices choices);
/* "sectors=32 thickness=0.5 counting=equal back=view rounding=paper " + GTAO's text. */
void vbao_params_text(const vbao_params *p, char *text, size_t size);

/* The sectors of [lo, hi] (fractions of the half-circle, clamped to [0, 1]). */
uint32_t vbao_sector_bits(float lo, float hi, int sectors, vbao_rounding rounding);
/* The occupied sectors of one slice (its geometry s, from gtao_slice_geometry). */
uint32_t vbao_slice_bits(const ss_gbuffer *g, int x, int y, const vbao_params *p, const gtao_slice *s, float phi,
                         float offset);
/* The free sectors' visibility (before the slice weight) and, if bent is
 * non-NULL, their cosine-weighted direction added to *bent (view space,
 * weighted like the visibility). An open slice gives 1 on average over
 * slices for every counting. */
float vbao_slice_visibility(uint32_t occupied, const gtao_slice *s, const vbao_params *p, vec3 *bent);

/* One frame without denoiser: ao[i] and, if bent is non-NULL, the world-space
 * bent normal. Background pixels get 0. */
void vbao_frame(const ss_gbuffer *g, const vbao_params *p, int frame, float *ao, float *const *bent);
/* p->gtao.frames frames, each denoised if p->gtao.denoise, averaged (GTAO's
 * frame loop). Deterministic for any thread count. 0, or -1 when out of memory. */
int vbao_render(const ss_gbuffer *g, const vbao_params *p, float *ao, float *const *bent);

#endif
