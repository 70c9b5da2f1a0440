/* The single-scattering integral of a volumetric light along a ray; see
 * volumetric_light_integral.h. */
#include "volumetric_light/volumetric_light_integral.h"

#include <math.h>

#include "core/sampling/quadrature.h"

enum { MIN_PIECES = 16, MAX_POINTS = 40, MAX_MC_BATCH = 64 };

/* The equiangular frame of a ray: closest approach s0 and distance h. */
typedef struct {
    vec3 o, w;
    double s0, h;
} equiangular_frame;

static equiangular_frame frame_of(const volumetric_light *light, vec3 o, vec3 w)
{
    double d[3] = {(double)light->position.x - o.x, (double)light->position.y - o.y, (double)light->position.z - o.z};
    double s0 = d[0] * w.x + d[1] * w.y + d[2] * w.z;
    double q[3] = {d[0] - s0 * w.x, d[1] - s0 * w.y, d[2] - s0 * w.z};
    double h = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    equiangular_frame f = {o, w, s0, fmax(h, 1e-9 * (1.0 + fabs(s0)))};
    return f;
}

static double theta_of(const equiangular_frame *f, double s) { return atan2(s - f->s0, f->h); }
static double s_of(const equiangular_frame *f, double theta) { return f->s0 + f->h * tan(theta); }

static vec3 point_at(const equiangular_frame *f, double s)
{
    return v3((float)(f->o.x + s * f->w.x), (float)(f->o.y + s * f->w.y), (float)(f->o.z + s * f->w.z));
}

/* j(s) r^2 / h, the integrand in theta, without visibility. */
static double angular_integrand(const volumetric_lighting *l, const equiangular_frame *f, double s)
{
    double ds = s - f->s0, r2 = f->h * f->h + ds * ds;
    return volumetric_inscatter_density(l->light, l->medium, f->o, f->w, s) * r2 / f->h;
}

static void shadow_ray(const volumetric_light *light, vec3 x, struct RTCRay *ray)
{
    vec3 to_light = v3_sub(light->position, x);
    float r = v3_length(to_light);
    embree_ray_init(ray, x, v3_scale(to_light, 1.0f / r), r * (1.0f - 1e-5f));
    ray->tnear = 0.0f; /* x is in the medium: no surface to leave (the end point s = d has measure 0) */
}

int volumetric_light_visible(const embree_scene *occluders, const volumetric_light *light, vec3 x)
{
    struct RTCRay ray;
    shadow_ray(light, x, &ray);
    embree_unoccluded_stream(occluders, &ray, 1);
    return ray.tfar >= 0.0f;
}

/* ---- Quadrature --------------------------------------------------------------- */

typedef struct {
    const volumetric_lighting *l;
    equiangular_frame f;
    long rays;
} quadrature_context;

static double integrand(double theta, void *ctx)
{
    quadrature_context *q = ctx;
    double s = s_of(&q->f, theta), value = angular_integrand(q->l, &q->f, s);
    if (value > 0.0 && q->l->occluders) {
        ++q->rays;
        if (!volumetric_light_visible(q->l->occluders, q->l->light, point_at(&q->f, s)))
            return 0.0;
    }
    return value;
}

/* The break points in theta: the outer cone's interval, split at the inner
 * cone's, each piece cut into equal parts so there are >= MIN_PIECES. */
static int break_points(const volumetric_lighting *l, const equiangular_frame *f, double distance, double *points)
{
    double a, b, cuts[4];
    if (volumetric_cone_interval(l->light, l->light->cos_outer, f->o, f->w, 0.0, distance, &a, &b) != 0)
        return 0;
    int n = 0;
    cuts[n++] = theta_of(f, a);
    double c0, c1;
    if (l->light->kind == VOLUMETRIC_SPOT_LIGHT &&
        volumetric_cone_interval(l->light, l->light->cos_inner, f->o, f->w, a, b, &c0, &c1) == 0) {
        if (c0 > a)
            cuts[n++] = theta_of(f, c0);
        if (c1 < b)
            cuts[n++] = theta_of(f, c1);
    }
    cuts[n++] = theta_of(f, b);
    double range = cuts[n - 1] - cuts[0];
    int count = 0;
    for (int k = 0; k + 1 < n; ++k) {
        int parts = (int)ceil(MIN_PIECES * (cuts[k + 1] - cuts[k]) / range);
        for (int i = 0; i < parts; ++i)
            points[count++] = cuts[k] + (cuts[k + 1] - cuts[k]) * i / parts;
    }
    points[count++] = cuts[n - 1];
    return range > 0.0 ? count : 0;
}

/* The largest value of p_HG(., g): at mu = sign(g). */
static double phase_max(double g)
{
    double a = 1.0 - fabs(g);
    return (1.0 - g * g) / (4.0 * M_PI * a * a * a);
}

void volumetric_light_quadrature(const volumetric_lighting *l, vec3 o, vec3 w, double distance, double rel_tol,
                                 volumetric_ray_estimate *out)
{
    quadrature_context q = {l, frame_of(l->light, o, w), 0};
    double points[MAX_POINTS], value = 0.0, error = 0.0;
    int n = break_points(l, &q.f, distance, points);
    if (n >= 2) {
        double bound = l->medium->sigma_s * phase_max(l->medium->g) * (points[n - 1] - points[0]) / q.f.h;
        value = quadrature_gk15_split(integrand, &q, points, n, rel_tol * bound, &error);
    }
    for (int c = 0; c < 3; ++c) {
        out->radiance[c] = l->light->intensity[c] * value;
        out->error[c] = l->light->intensity[c] * error;
    }
    out->rays = q.rays;
}

/* ---- Monte Carlo ------------------------------------------------------------- */

int volumetric_light_mc_samples(const volumetric_lighting *l, vec3 o, vec3 w, double distance, const float *u,
                                int count, double *samples)
{
    equiangular_frame f = frame_of(l->light, o, w);
    double theta0 = theta_of(&f, 0.0), span = theta_of(&f, distance) - theta0;
    struct RTCRay rays[MAX_MC_BATCH];
    int traced[MAX_MC_BATCH], n = 0;
    for (int k = 0; k < count; ++k) {
        double s = fmin(distance, fmax(0.0, s_of(&f, theta0 + span * u[k])));
        samples[k] = span * angular_integrand(l, &f, s);
        if (samples[k] > 0.0 && l->occluders) {
            shadow_ray(l->light, point_at(&f, s), &rays[n]);
            traced[n++] = k;
        }
    }
    if (n > 0)
        embree_unoccluded_stream(l->occluders, rays, (unsigned)n);
    for (int i = 0; i < n; ++i)
        if (!(rays[i].tfar >= 0.0f))
            samples[traced[i]] = 0.0;
    return n;
}
