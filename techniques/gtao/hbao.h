/* Horizon-based AO, Bavoil, Sainz and Dimitrov, "Image-Space Horizon-Based
 * Ambient Occlusion" (SIGGRAPH 2008 talk), the baseline the GTAO talk
 * (seeds/001, "Method") compares with: uniform weighting, per direction the
 * occluded elevation from the tangent angle t up to the horizon angle h,
 *   V = 1 - (1/N) sum_directions (sin h - sin t),
 * optionally with Bavoil's per-sample attenuation W(r) = 1 - r^2 / R^2
 * (each rise of the horizon counts W(r) (sin h_i - sin h_{i-1})). Without it
 * HBAO equals GTAO with uniform weighting and no attenuation (the talk's
 * claim, tested). The tangent comes from the G-buffer normal. */
#ifndef GTLAB_GTAO_HBAO_H
#define GTLAB_GTAO_HBAO_H

#include <stddef.h>

#include "realtime/screen_space.h"

typedef struct {
    int directions;      /* screen directions over the full turn, per pixel and frame */
    int steps;           /* samples per direction */
    float radius;        /* world-space radius */
    float max_radius_px; /* clamp of the screen-space radius */
    int attenuation;     /* Bavoil's W(r) = 1 - r^2 / R^2 */
    int pattern;         /* the GTAO talk's spatio-temporal pattern (else regular) */
    int denoise, frames; /* as GTAO's */
} hbao_params;

void hbao_frame(const ss_gbuffer *g, const hbao_params *p, int frame, float *ao);
int hbao_render(const ss_gbuffer *g, const hbao_params *p, float *ao);
void hbao_params_text(const hbao_params *p, char *text, size_t size);

#endif
