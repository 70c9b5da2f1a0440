/* A pixel's height-field horizons as a control variate for its AO
 * (issue 13, part 3; docs/decisions.md, "The height field as a control
 * variate").
 *
 * Directions about the surface point p are parametrised around the view
 * vector v (unit, from p to the eye), as in GTAO's slices
 * (techniques/gtao/gtao.h):
 *   w(psi, theta) = cos theta v + sin theta (cos psi e1 + sin psi e2),
 *   psi in [0, 2 pi) the half-slice's rotation about v, theta in [0, pi] the
 *   angle from v, dw = sin theta dtheta dpsi,
 * with (e1, e2, v) = frame_from_normal(v). Every half-plane of constant psi
 * contains the eye, so the depth buffer seen in it is a 1-D height field and
 * its visibility is a horizon: w is free exactly when theta <= h(psi)
 * (everything behind the surface is solid). The K = SLICE_HORIZON_SIDES
 * half-slices [2 pi k / K, 2 pi (k + 1) / K) each keep the horizon h_k found
 * at their centre; the control variate is
 *   g(w) = 1 if theta(w) <= h_k(psi(w)), else 0,
 * and its integrals over the hemisphere of the shading normal n are exact:
 *   G_d = (1/pi)  \int g(w) (n.w) dw = (1/pi)  sum_k \int_bin_k C(T_k(psi), psi) dpsi,
 *   G_u = (1/2pi) \int g(w) dw       = (1/2pi) sum_k \int_bin_k (1 - cos T_k(psi)) dpsi,
 * where T_k(psi) = min(h_k, U(psi)) and U(psi) = pi/2 + atan(beta(psi) / a)
 * is where the slice leaves the hemisphere (a = n.v > 0, beta = n.(cos psi
 * e1 + sin psi e2)), and the inner integral is closed:
 *   C(T, psi) = \int_0^T (a cos t + beta sin t) sin t dt = a sin^2 T / 2 + beta (T/2 - sin 2T / 4).
 * The outer integral is closed too: where T = h it is linear in beta, and
 * where T = U it is a/2 + beta U / 2 (C at the edge), whose beta atan(beta / a)
 * integrates by parts to elementary functions (slice_horizons.c); each bin
 * is cut where U(psi) crosses h_k (beta(psi) = -a cot h_k, solved in closed
 * form) and at the antiderivatives' seam. So G is exact up to rounding, and
 * an open hemisphere gives exactly 1.
 *
 * An AO sample V(w) of either estimator then becomes V(w) - beta (g(w) - G),
 * with the same mean for any beta fixed independently of the sample and,
 * where the depth buffer describes the occluders (beta = 1), almost no
 * variance (beta here is the coefficient, not beta(psi) above). A pixel
 * whose normal faces away from the eye (a <= 1e-3) gets
 * g = 1, G = 1: its samples are left as they are. */
#ifndef GTLAB_AO_SLICE_HORIZONS_H
#define GTLAB_AO_SLICE_HORIZONS_H

#include "core/frame.h"
#include "core/vec3.h"

enum { SLICE_HORIZON_SIDES = 32 }; /* half-slices: 16 GTAO slices, two sides each */

/* A half-slice whose horizon lies within this angle of the hemisphere's
 * edge at its centre counts as open (the surface's own plane, met again in
 * the neighbouring pixels, must not close a plane's slices by rounding). */
#define SLICE_HORIZON_OPEN_MARGIN 1e-3f

typedef struct {
    vec3 v;                                  /* unit view vector, p to eye */
    float cos_horizon[SLICE_HORIZON_SIDES];  /* cos h_k; -2 for an open half-slice */
    float integral[2];                       /* G_d and G_u */
    float beta[2];                           /* the coefficients (ao_control_variate.h); 1 here */
} slice_horizons;

/* The frame (e1, e2, v) of the parametrisation. */
static inline frame slice_horizons_frame(const slice_horizons *h) { return frame_from_normal(h->v); }

/* The direction at the centre of half-slice k, perpendicular to v. */
vec3 slice_horizons_side(const frame *f, int k);

/* Where the half-slice at angle psi leaves the hemisphere of n (a = n.v > 0). */
double slice_horizons_edge(vec3 n, const frame *f, double psi);

/* Builds a pixel's horizons: theta_k the horizon angle found at the centre
 * of half-slice k (pi or more when nothing occludes), n the unit shading
 * normal; computes the exact integrals. */
void slice_horizons_init(slice_horizons *h, vec3 v, vec3 n, const float *theta);

/* The pixel whose control variate is off: g = 1, G = 1. */
void slice_horizons_off(slice_horizons *h, vec3 v);

/* g(w) for a unit direction w. */
static inline float slice_horizons_visible(const slice_horizons *h, const frame *f, vec3 w)
{
    float c = v3_dot(w, f->n), psi = atan2f(v3_dot(w, f->b), v3_dot(w, f->t));
    int k = (int)((psi < 0.0f ? psi + 6.2831853f : psi) * (SLICE_HORIZON_SIDES / 6.2831853f));
    k = k < 0 ? 0 : k >= SLICE_HORIZON_SIDES ? SLICE_HORIZON_SIDES - 1 : k;
    return c >= h->cos_horizon[k] ? 1.0f : 0.0f;
}

/* The integrals of g over half-slice k alone, [2 pi k / K, 2 pi (k + 1) / K):
 * cosine (without 1/pi) and uniform (without 1/2pi). Exposed for tests. */
void slice_horizons_side_integrals(vec3 n, const frame *f, double horizon, int k, double *cosine, double *uniform);

#endif
