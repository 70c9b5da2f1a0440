/* The height-field control variate's g and its exact integrals; see
 * slice_horizons.h. */
#include "ao/slice_horizons.h"

#include <math.h>

static const double two_pi = 2.0 * M_PI;

vec3 slice_horizons_side(const frame *f, int k)
{
    double psi = two_pi * (k + 0.5) / SLICE_HORIZON_SIDES;
    return v3_add(v3_scale(f->t, (float)cos(psi)), v3_scale(f->b, (float)sin(psi)));
}

/* n in the frame: a = n.v and beta(psi) = n.(cos psi e1 + sin psi e2)
 * = rho cos(psi - psi0). */
typedef struct {
    double a, rho, psi0, horizon;
} side_geometry;

static double beta(const side_geometry *s, double psi) { return s->rho * cos(psi - s->psi0); }

static double edge(const side_geometry *s, double psi) { return 0.5 * M_PI + atan(beta(s, psi) / s->a); }

static double dot(vec3 a, vec3 b) { return (double)a.x * b.x + (double)a.y * b.y + (double)a.z * b.z; }

/* In double and renormalised: a float normal and frame are unit only to
 * ~1e-7, and the integrals scale with |n|. */
static side_geometry geometry(vec3 n, const frame *f, double horizon)
{
    double a = dot(n, f->n), b1 = dot(n, f->t), b2 = dot(n, f->b), length = sqrt(a * a + b1 * b1 + b2 * b2);
    side_geometry s = {a / length, hypot(b1, b2) / length, atan2(b2, b1), horizon};
    return s;
}

double slice_horizons_edge(vec3 n, const frame *f, double psi)
{
    side_geometry s = geometry(n, f, 0.0);
    return edge(&s, psi);
}

/* Antiderivatives in u = psi - psi0, u in [-pi, pi], with k = rho / a:
 *   \int beta du                 = rho sin u
 *   \int beta atan(beta / a) du  = rho sin u atan(k cos u) + rho k S(u),
 *     S(u) = \int sin^2 u / (1 + k^2 cos^2 u) du
 *          = (m atan2(sin u, m cos u) - u) / k^2,  m = sqrt(1 + k^2)
 *     (by parts, then sin^2 = (1 + 1/k^2) / (1 + k^2 cos^2) - 1/k^2 times
 *     the denominator; continuous on [-pi, pi]), for small k its series
 *     u/2 - sin 2u / 4 - k^2 (u/8 - sin 4u / 32);
 *   \int beta / sqrt(a^2 + beta^2) du = asin(rho sin u / sqrt(a^2 + rho^2)). */
static double sin2_over(double k, double u)
{
    if (k < 1e-3)
        return 0.5 * u - 0.25 * sin(2.0 * u) - k * k * (u / 8.0 - sin(4.0 * u) / 32.0);
    double m = sqrt(1.0 + k * k);
    return (m * atan2(sin(u), m * cos(u)) - u) / (k * k);
}

static double beta_atan(const side_geometry *s, double u)
{
    double k = s->rho / s->a;
    return s->rho * sin(u) * atan(k * cos(u)) + s->rho * k * sin2_over(k, u);
}

static double beta_over_length(const side_geometry *s, double u)
{
    return asin(s->rho * sin(u) / sqrt(s->a * s->a + s->rho * s->rho));
}

/* The integrals over psi in [lo, hi] (u = psi - psi0 within [-pi, pi] all
 * along) where g reaches the hemisphere's edge, T = U(psi):
 *   C(U, psi) = a/2 + beta U / 2 = a/2 + (pi/4) beta + beta atan(beta / a) / 2,
 *   1 - cos U = 1 + beta / sqrt(a^2 + beta^2). */
static void edge_piece(const side_geometry *s, double u0, double u1, double *cosine, double *uniform)
{
    *cosine += 0.5 * s->a * (u1 - u0) + 0.25 * M_PI * s->rho * (sin(u1) - sin(u0)) +
               0.5 * (beta_atan(s, u1) - beta_atan(s, u0));
    *uniform += (u1 - u0) + beta_over_length(s, u1) - beta_over_length(s, u0);
}

/* ... and where the horizon limits it, T = h:
 *   C(h, psi) = a sin^2 h / 2 + beta (h/2 - sin 2h / 4),  1 - cos h. */
static void horizon_piece(const side_geometry *s, double u0, double u1, double *cosine, double *uniform)
{
    double h = s->horizon, sh = sin(h);
    *cosine += 0.5 * s->a * sh * sh * (u1 - u0) + (0.5 * h - 0.25 * sin(2.0 * h)) * s->rho * (sin(u1) - sin(u0));
    *uniform += (1.0 - cos(h)) * (u1 - u0);
}

/* Adds the angle psi0 + offset, taken into (lo, hi), to the cuts. */
static void add_cut(double psi, double lo, double hi, double *cuts, int *count)
{
    psi -= two_pi * floor((psi - lo) / two_pi); /* into [lo, lo + 2 pi) */
    if (psi > lo && psi < hi)
        cuts[(*count)++] = psi;
}

/* The angles in (lo, hi) where the hemisphere's edge U(psi) crosses the
 * horizon (beta(psi) = -a cot h), and where u = psi - psi0 passes pi (the
 * antiderivatives' seam), in increasing order; returns their number. */
static int cuts_in(const side_geometry *s, double lo, double hi, double cuts[3])
{
    int count = 0;
    add_cut(s->psi0 + M_PI, lo, hi, cuts, &count);
    double c = -s->a / tan(s->horizon);
    if (s->horizon < M_PI && s->rho > 0.0 && fabs(c) <= s->rho) {
        double d = acos(c / s->rho);
        add_cut(s->psi0 + d, lo, hi, cuts, &count);
        add_cut(s->psi0 - d, lo, hi, cuts, &count);
    }
    for (int i = 1; i < count; ++i) /* insertion sort of at most 3 */
        for (int j = i; j > 0 && cuts[j - 1] > cuts[j]; --j) {
            double t = cuts[j];
            cuts[j] = cuts[j - 1];
            cuts[j - 1] = t;
        }
    return count;
}

void slice_horizons_side_integrals(vec3 n, const frame *f, double horizon, int k, double *cosine, double *uniform)
{
    side_geometry s = geometry(n, f, horizon);
    double lo = two_pi * k / SLICE_HORIZON_SIDES, hi = two_pi * (k + 1) / SLICE_HORIZON_SIDES;
    double points[5] = {lo}, cuts[3];
    int count = cuts_in(&s, lo, hi, cuts);
    for (int j = 0; j < count; ++j)
        points[1 + j] = cuts[j];
    points[1 + count] = hi;
    *cosine = *uniform = 0.0;
    for (int j = 0; j <= count; ++j) {
        double mid = 0.5 * (points[j] + points[j + 1]);
        /* u of the piece in [-pi, pi]: it does not cross the seam, and
         * rounding must not carry an end past it (atan2 would jump). */
        double u_mid = mid - s.psi0 - two_pi * floor((mid - s.psi0 + M_PI) / two_pi);
        double u0 = fmax(u_mid - (mid - points[j]), -M_PI), u1 = fmin(u_mid + (points[j + 1] - mid), M_PI);
        if (s.horizon < edge(&s, mid))
            horizon_piece(&s, u0, u1, cosine, uniform);
        else
            edge_piece(&s, u0, u1, cosine, uniform);
    }
}

void slice_horizons_off(slice_horizons *h, vec3 v)
{
    h->v = v;
    for (int k = 0; k < SLICE_HORIZON_SIDES; ++k)
        h->cos_horizon[k] = -2.0f;
    h->integral[0] = h->integral[1] = 1.0f;
    h->beta[0] = h->beta[1] = 1.0f;
}

void slice_horizons_init(slice_horizons *h, vec3 v, vec3 n, const float *theta)
{
    slice_horizons_off(h, v);
    frame f = slice_horizons_frame(h);
    if (!(v3_dot(n, f.n) > 1e-3f))
        return;
    double cosine = 0.0, uniform = 0.0;
    for (int k = 0; k < SLICE_HORIZON_SIDES; ++k) {
        double psi = two_pi * (k + 0.5) / SLICE_HORIZON_SIDES;
        int open = theta[k] >= slice_horizons_edge(n, &f, psi) - SLICE_HORIZON_OPEN_MARGIN;
        h->cos_horizon[k] = open ? -2.0f : cosf(theta[k]);
        /* Integrate the horizon g sees: the float cosine's angle. */
        double c, u, seen = open ? M_PI : acos((double)h->cos_horizon[k]);
        slice_horizons_side_integrals(n, &f, seen, k, &c, &u);
        cosine += c;
        uniform += u;
    }
    h->integral[0] = (float)(cosine / M_PI);
    h->integral[1] = (float)(uniform / two_pi);
}
