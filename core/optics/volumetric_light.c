/* Lights and medium of the volumetric lighting; see volumetric_light.h. */
#include "core/optics/volumetric_light.h"

#include <math.h>

#include "core/optics/phase_function.h"

static const double deg = M_PI / 180.0;

volumetric_light volumetric_spot_light(vec3 position, vec3 target, double outer_deg, double inner_deg,
                                       const double intensity[3])
{
    volumetric_light l = {VOLUMETRIC_SPOT_LIGHT, position, v3_normalize(v3_sub(target, position)),
                          cos(outer_deg * deg), cos(inner_deg * deg), {intensity[0], intensity[1], intensity[2]}};
    return l;
}

volumetric_light volumetric_point_light(vec3 position, const double intensity[3])
{
    volumetric_light l = {VOLUMETRIC_POINT_LIGHT, position, v3(0.0f, -1.0f, 0.0f), -1.0, -1.0,
                          {intensity[0], intensity[1], intensity[2]}};
    return l;
}

int volumetric_medium_validate(const volumetric_medium *m, const char *what, gt_error *e)
{
    if (!(m->sigma_s >= 0.0 && m->sigma_t >= m->sigma_s && isfinite(m->sigma_t)))
        return gt_error_set(e, what, "the medium needs 0 <= sigma_s <= sigma_t (finite), got %g and %g", m->sigma_s,
                            m->sigma_t);
    if (!(fabs(m->g) < 1.0))
        return gt_error_set(e, what, "the phase function's g must be in (-1, 1), got %g", m->g);
    return 0;
}

int volumetric_light_validate(const volumetric_light *l, const char *what, gt_error *e)
{
    for (int c = 0; c < 3; ++c)
        if (!(l->intensity[c] >= 0.0 && isfinite(l->intensity[c])))
            return gt_error_set(e, what, "the light's intensity must be finite and >= 0");
    if (!v3_is_finite(l->position))
        return gt_error_set(e, what, "the light's position is not finite");
    if (l->kind == VOLUMETRIC_SPOT_LIGHT &&
        !(l->cos_outer > 0.0 && l->cos_outer < l->cos_inner && l->cos_inner <= 1.0 && v3_is_finite(l->axis)))
        return gt_error_set(e, what, "the spot's cone needs 0 <= inner < outer < 90 degrees and a finite axis");
    return 0;
}

/* smoothstep(a, b, x) with t clamped to [0, 1]. */
static double smoothstep(double a, double b, double x)
{
    double t = fmin(1.0, fmax(0.0, (x - a) / (b - a)));
    return t * t * (3.0 - 2.0 * t);
}

double volumetric_light_falloff(const volumetric_light *l, vec3 x)
{
    if (l->kind == VOLUMETRIC_POINT_LIGHT)
        return 1.0;
    double d[3] = {(double)x.x - l->position.x, (double)x.y - l->position.y, (double)x.z - l->position.z};
    double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(r > 0.0))
        return 0.0;
    double cos_theta = (d[0] * l->axis.x + d[1] * l->axis.y + d[2] * l->axis.z) / r;
    return smoothstep(l->cos_outer, l->cos_inner, cos_theta);
}

double volumetric_inscatter_density(const volumetric_light *l, const volumetric_medium *m, vec3 o, vec3 w,
                                    double s)
{
    double to_light[3] = {l->position.x - (o.x + s * w.x), l->position.y - (o.y + s * w.y),
                          l->position.z - (o.z + s * w.z)};
    double r2 = to_light[0] * to_light[0] + to_light[1] * to_light[1] + to_light[2] * to_light[2];
    if (!(r2 > 0.0))
        return 0.0;
    double r = sqrt(r2), mu = (to_light[0] * w.x + to_light[1] * w.y + to_light[2] * w.z) / r;
    vec3 x = v3((float)(o.x + s * w.x), (float)(o.y + s * w.y), (float)(o.z + s * w.z));
    double falloff = l->kind == VOLUMETRIC_POINT_LIGHT ? 1.0 : volumetric_light_falloff(l, x);
    return m->sigma_s * henyey_greenstein_phase(fmax(-1.0, fmin(1.0, mu)), m->g) * falloff *
           exp(-m->sigma_t * (s + r)) / r2;
}

/* ---- The ray against the cone ------------------------------------------------ */

typedef struct {
    double d[3], w[3], a[3], c2;
} cone_ray;

static double dot3(const double *x, const double *y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }

static int inside_cone(const cone_ray *cr, double t)
{
    double x[3] = {cr->d[0] + t * cr->w[0], cr->d[1] + t * cr->w[1], cr->d[2] + t * cr->w[2]};
    double along = dot3(x, cr->a);
    return along > 0.0 && along * along >= cr->c2 * dot3(x, x);
}

/* Candidate boundaries: the roots of (x.a)^2 = c^2 |x|^2 in (t_min, t_max). */
static int cone_roots(const cone_ray *cr, double t_min, double t_max, double *points)
{
    double wa = dot3(cr->w, cr->a), da = dot3(cr->d, cr->a);
    double A = wa * wa - cr->c2 * dot3(cr->w, cr->w), B = da * wa - cr->c2 * dot3(cr->d, cr->w),
           C = da * da - cr->c2 * dot3(cr->d, cr->d);
    double roots[2];
    int n = 0, count = 0;
    if (fabs(A) > 1e-12 * (fabs(B) + fabs(C) + 1e-300)) {
        double disc = B * B - A * C;
        if (disc >= 0.0) {
            double q = -(B + copysign(sqrt(disc), B)); /* the stable pair of roots */
            roots[n++] = q / A;
            if (q != 0.0)
                roots[n++] = C / q;
        }
    } else if (B != 0.0)
        roots[n++] = -C / (2.0 * B);
    for (int k = 0; k < n; ++k)
        if (roots[k] > t_min && roots[k] < t_max)
            points[count++] = roots[k];
    if (count == 2 && points[0] > points[1]) {
        double t = points[0];
        points[0] = points[1], points[1] = t;
    }
    return count;
}

int volumetric_cone_interval(const volumetric_light *l, double cos_half, vec3 o, vec3 w, double t_min,
                             double t_max, double *t0, double *t1)
{
    if (l->kind == VOLUMETRIC_POINT_LIGHT) {
        *t0 = t_min, *t1 = t_max;
        return t_max > t_min ? 0 : -1;
    }
    cone_ray cr = {{(double)o.x - l->position.x, (double)o.y - l->position.y, (double)o.z - l->position.z},
                   {w.x, w.y, w.z},
                   {l->axis.x, l->axis.y, l->axis.z},
                   cos_half * cos_half};
    double points[4] = {t_min};
    int n = 1 + cone_roots(&cr, t_min, t_max, points + 1);
    points[n++] = t_max;
    int found = 0;
    for (int k = 0; k + 1 < n; ++k) {
        double mid = isfinite(points[k + 1]) ? 0.5 * (points[k] + points[k + 1]) : points[k] + 1.0 + fabs(points[k]);
        if (points[k + 1] > points[k] && inside_cone(&cr, mid)) {
            if (!found)
                *t0 = points[k];
            *t1 = points[k + 1];
            found = 1;
        }
    }
    return found ? 0 : -1;
}
