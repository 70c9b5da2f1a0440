/* The GTAO talk's "Possible Pitfall" slide (seeds/001) as a negative
 * control: the slice integral written with |sin n| (the normal's angle) in
 * place of the Jacobian |sin theta| of the horizon parametrisation,
 *
 *     pitfall:  integral_{h1}^{h2} cos(theta - n) |sin n| dtheta = |sin n| (sin(h2 - n) - sin(h1 - n)),
 *     correct:  integral_{h1}^{h2} cos(theta - n) |sin theta| dtheta   (gtao_integrate_arc_cosine),
 *
 * with everything else of GTAO kept (horizons, projected-normal length,
 * slice weights, average over slices). The talk warns against it; scoring it
 * beside the baselines shows whether the report's numbers would have caught
 * it: a surface facing the camera (n = 0 in every slice) reads 0 instead of
 * 1, and an open slice gives 2 |sin n| instead of 1. */
#ifndef GTLAB_GTAO_GTAO_SIN_N_PITFALL_H
#define GTLAB_GTAO_GTAO_SIN_N_PITFALL_H

#include "gtao/gtao.h"

float gtao_integrate_arc_pitfall(float h1, float h2, float n);

/* One frame of GTAO with the pitfall's integrand (p's slices, steps,
 * pattern; no denoiser, no bent normal). Background pixels get 0. */
void gtao_pitfall_frame(const ss_gbuffer *g, const gtao_params *p, int frame, float *ao);
/* p->frames frames, each denoised if p->denoise, averaged, as gtao_render.
 * Returns 0, or -1 when out of memory. */
int gtao_pitfall_render(const ss_gbuffer *g, const gtao_params *p, float *ao);

#endif
