/* The horizon-based numerical integrator of the GTAO talk's methodology
 * (seeds/001, "Methodology": "Horizon-based numerical integrator"): GTAO's
 * horizons, but each slice's arc integrated numerically against the full
 * 3-D normal, (n . w(theta)) |sin theta| over [h1, h2] (composite Simpson,
 * split at theta = 0 where |sin| has its kink), with no projected normal and
 * no closed form. It checks IntegrateArc and Timonen's projection together.
 *
 * It is GTAO's real-time part rather than the ray tracer's because it is
 * built on GTAO's horizon search (what it checks is the integration, so both
 * must see the same horizons) and traces no rays; raytracer/ may not depend
 * on a real-time part (dependencies point one way, DESIGN.md). */
#ifndef GTLAB_GTAO_HORIZON_INTEGRATOR_H
#define GTLAB_GTAO_HORIZON_INTEGRATOR_H

#include "gtao/gtao.h"

/* The arc of slice s for view-space normal n: cosine weighting gives
 * integral of max(n . w, 0) |sin theta|, uniform (1/2) integral of |sin theta|,
 * with `intervals` Simpson intervals per side (even). */
double horizon_arc_numeric(const gtao_slice *s, vec3 n, gtao_weighting w, int intervals);
/* AO of every pixel with p's slices and samples (regular slices, offset 0.5,
 * no denoiser), each slice integrated numerically. */
void horizon_integrator_render(const ss_gbuffer *g, const gtao_params *p, int intervals, float *ao);

#endif
