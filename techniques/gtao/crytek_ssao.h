/* Screen-space ambient occlusion as CryENGINE 2 introduced it, Mittring,
 * "Finding Next Gen: CryEngine 2" (SIGGRAPH 2007 course), one of the
 * baselines the GTAO talk cites (seeds/001, [Mittring2007]): points S_k
 * spread through a sphere of world radius R about the pixel's point P (no
 * normal), each tested against the depth buffer: S_k counts as occluded
 * when the depth buffer's surface seen through S_k's screen position lies
 * in front of it, unless it lies more than R in front (the range check:
 * a far foreground object is not an occluder of P),
 *
 *     o = (1 / N) sum_k [ d(S_k) - R < z_buffer(S_k) < d(S_k) ],
 *
 * with d the depth along the camera axis. Half the sphere is behind any
 * plane through P, so a flat surface reads o = 1/2 (CryENGINE 2's grey
 * walls); gtlab reports V = min(1, 2 (1 - o)), the normalisation it applies
 * to volumetric obscurance too, so that a plane reads 1 (exactly: the
 * points come in opposite pairs +-o_k, one in front of any plane through P
 * and one behind; tested).
 *
 * Points: N / 2 pairs, pair k at radius R ((k + 0.5) / (N / 2))^(1/3) (equal
 * volumes of the ball) along the k-th point of a Fibonacci sphere, the set
 * rotated about the view axis per pixel by the GTAO talk's pattern (in
 * place of CryENGINE 2's reflection by a 4x4 random-normal texture). The
 * depth buffer is read at S_k's exact screen point (ss_sample_position, the
 * height field the other techniques see). */
#ifndef GTLAB_GTAO_CRYTEK_SSAO_H
#define GTLAB_GTAO_CRYTEK_SSAO_H

#include <stddef.h>

#include "realtime/screen_space.h"

#define CRYTEK_MAX_SAMPLES 64

typedef struct {
    int samples;         /* N, even, 2..CRYTEK_MAX_SAMPLES */
    float radius;        /* R, world space */
    int pattern;         /* rotate the points per pixel by the GTAO talk's pattern (else fixed) */
    int denoise, frames; /* as GTAO's */
} crytek_params;

void crytek_frame(const ss_gbuffer *g, const crytek_params *p, int frame, float *ao);
int crytek_render(const ss_gbuffer *g, const crytek_params *p, float *ao);
void crytek_params_text(const crytek_params *p, char *text, size_t size);

#endif
