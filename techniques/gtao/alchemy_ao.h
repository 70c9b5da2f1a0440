/* Alchemy ambient obscurance, McGuire, Osman, Bukowski and Hennessy, "The
 * Alchemy Screen-Space Ambient Obscurance Algorithm" (HPG 2011), one of the
 * baselines the GTAO talk cites (seeds/001, [McGuire2011]). Its estimator,
 * from s points P_i read back from the depth buffer around the pixel's
 * point C (view space) with normal n:
 *
 *     A = max(0, 1 - (2 sigma / s) sum_i max(0, v_i . n + z_C beta) / (v_i . v_i + epsilon))^k,
 *     v_i = P_i - C,
 *
 * sigma the intensity, k the contrast, beta a bias distance that keeps a
 * surface from obscuring itself (z_C < 0 is C's camera-space z, so z_C beta
 * is a depth-proportional margin subtracted from v . n), epsilon guards the
 * division. The paper's defaults: sigma = 1, k = 1, beta = 1e-4, epsilon =
 * 1e-4. The samples lie on a spiral over the screen-space disc of the
 * world-space radius r: sample i at distance r (i + 0.5) / s from the pixel,
 * angle 2 pi tau (i + 0.5) / s + phi, tau = 7 turns, phi a per-pixel
 * rotation (the GTAO talk's 4x4 pattern here, as for HBAO and VO).
 *
 * A is an obscurance, not a cosine-weighted visibility: v . n / |v|^2 is
 * (cos of the angle from the normal) / |v|, so the estimate has units of
 * 1/length and sigma depends on the scene's scale; it is scored as the
 * paper defines it. A plane gives v . n = 0 for every sample, so A = 1
 * exactly (tested). */
#ifndef GTLAB_GTAO_ALCHEMY_AO_H
#define GTLAB_GTAO_ALCHEMY_AO_H

#include <stddef.h>

#include "realtime/screen_space.h"

typedef struct {
    int samples;         /* s */
    float radius;        /* r, world space */
    float max_radius_px; /* clamp of its screen-space radius */
    float sigma, contrast, beta, epsilon;
    int pattern;         /* rotate the spiral by the GTAO talk's pattern (else fixed) */
    int denoise, frames; /* as GTAO's */
} alchemy_params;

/* The paper's defaults, 12 samples (its Figure 1), the given radius. */
alchemy_params alchemy_default_params(float radius);
void alchemy_frame(const ss_gbuffer *g, const alchemy_params *p, int frame, float *ao);
int alchemy_render(const ss_gbuffer *g, const alchemy_params *p, float *ao);
void alchemy_params_text(const alchemy_params *p, char *text, size_t size);

#endif
