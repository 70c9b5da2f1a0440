/* The GTAO talk's fast arc cosine (seeds/001, "Cosine Weighting LUT vs
 * Analytical": "Use fast sqrt [Drobot2014a] and acos [Eberly2014]") with
 * its coefficients free, and GTAO's slice visibility replayed from cached
 * horizon cosines, so the AO error of any coefficients is measured without
 * searching the depth buffer again (issue 25, item 9).
 *
 * The talk's polynomial (Eberly 2014, first order), for x in [-1, 1]:
 *     acos(|x|) ~ (c1 |x| + c0) sqrt~(1 - |x|),   acos(x) = pi - acos(-x) for x < 0,
 * with c1 = -0.156583 ("the slope"), c0 = pi/2 (exact at x = 0) and sqrt~
 * the fast square root of Drobot 2014 (magic constant and shift).
 *
 * The replay: with no attenuation (falloff 0, samples within the radius) and
 * no thickness heuristic, a side's horizon cosine is max(low, m), where m
 * is the highest sample cosine seen from the pixel along the side (found
 * once) and low = -+sin n the hemisphere limit, which depends on the
 * normal's angle n = acos(cos n) and so on the arc cosine being measured.
 * gtao_replay_slice then applies the same arc cosines, clamp and integral
 * as gtao_frame (gtao.c), which it matches to float rounding
 * (tests/test_gtao_fast_acos.c). */
#ifndef GTLAB_GTAO_GTAO_FAST_ACOS_H
#define GTLAB_GTAO_GTAO_FAST_ACOS_H

#include <stdint.h>

#include "gtao/gtao.h"

typedef struct {
    float slope;    /* c1 */
    float constant; /* c0 */
    uint32_t magic; /* the fast sqrt's constant */
} gtao_acos_poly;

/* The talk's coefficients with Drobot's constant (what gtao_fast_acos computes). */
gtao_acos_poly gtao_acos_poly_talk(void);
float gtao_fast_acos_poly(float x, const gtao_acos_poly *c);

/* What one slice's visibility needs besides the arc cosines. */
typedef struct {
    float weight;       /* d psi / d phi */
    float n_len;        /* length of the projected normal */
    float cos_n;        /* cosine of the normal's angle from v in the slice */
    float n_sign;       /* +1: the normal leans to side 2; -1: to side 1 */
    float max_cos[2];   /* highest sample cosine from v on side 1, side 2 (-2 when no sample) */
} gtao_slice_cosines;

/* One slice's cosines at pixel (x, y), slice angle phi, step offset
 * `offset`, for p's slices/steps/radius (p must have falloff 0 and
 * thickness 0 for the replay to be exact). */
void gtao_slice_cosines_at(const ss_gbuffer *g, int x, int y, const gtao_params *p, float phi, float offset,
                           gtao_slice_cosines *out);

/* The slice's weighted cosine visibility, weight n_len IntegrateArc(h1, h2,
 * n), with the arc cosines of c, or acosf when c is NULL. */
float gtao_replay_slice(const gtao_slice_cosines *s, const gtao_acos_poly *c);

#endif
