/* Volumetric obscurance, Loos and Sloan, "Volumetric Obscurance" (I3D 2010),
 * with the 4 line samples of CryENGINE 3 (Kaplanyan, SIGGRAPH 2010 course,
 * seeds/004, "SSAO improvements": "Volumetric Obscurance [LS10] with 4(!)
 * samples"). The obscurance is the fraction of a sphere of world radius R
 * about the surface point that lies behind the depth buffer, estimated by
 * line integrals through the sphere along the view axis at 4 points of its
 * screen disc (two opposite pairs, so a plane through the centre is exactly
 * half full whatever its slope). A plane fills half the sphere, so the
 * visibility reported is V = min(1, 2 (1 - obscurance)): 1 on a plane, 0 when
 * buried. Depth only; no normals. */
#ifndef GTLAB_GTAO_VOLUMETRIC_OBSCURANCE_H
#define GTLAB_GTAO_VOLUMETRIC_OBSCURANCE_H

#include <stddef.h>

#include "realtime/screen_space.h"

typedef struct {
    float radius;        /* world-space sphere radius */
    float max_radius_px; /* clamp of its screen-space radius */
    int pattern;         /* rotate the samples by the GTAO talk's 4x4 pattern (else fixed) */
    int denoise, frames; /* as GTAO's */
} vo_params;

void vo_frame(const ss_gbuffer *g, const vo_params *p, int frame, float *ao);
int vo_render(const ss_gbuffer *g, const vo_params *p, float *ao);
void vo_params_text(const vo_params *p, char *text, size_t size);

#endif
