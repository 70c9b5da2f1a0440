/* Single scattering in the height fog by quadrature; see
 * height_fog_single_scatter.h. */
#include "height_fog/height_fog_single_scatter.h"

#include <math.h>

#include "core/sampling/quadrature.h"

enum { MAX_SPLITS = 12 };
#define DEPTH_CUT 50.0 /* optical depth beyond which nothing is integrated */

double height_fog_ray_density(const height_fog_param *p, double y0, double dir_y, double distance)
{
    if (isfinite(distance))
        return height_fog_segment_density(p, y0, y0 + dir_y * distance, distance);
    if (dir_y > 0.0)
        return p->scale_height * exp(-fmax(y0, p->floor_y) / p->scale_height) / dir_y;
    if (dir_y < 0.0 && p->floor_y > -INFINITY)
        return y0 < p->floor_y ? 0.0 : height_fog_segment_density(p, y0, p->floor_y, (p->floor_y - y0) / dir_y);
    return y0 >= p->floor_y ? INFINITY : 0.0;
}

/* What the integrand of one channel needs. */
typedef struct {
    const height_fog_lighting *l;
    vec3 origin, dir;
    double beta_t, amb_term, sun_term; /* beta_t,c; beta_s,c L_amb,c; E_c S_sun,c(mu) */
    int channel;
    long rays;
} channel_integrand;

static double sun_visibility(channel_integrand *ci, vec3 x)
{
    if (!ci->l->occluders)
        return 1.0;
    struct RTCRay ray;
    embree_ray_init(&ray, x, ci->l->medium->sun_direction, INFINITY);
    ray.tnear = 1e-4f * (1.0f + v3_max_abs_component(x));
    embree_unoccluded_stream(ci->l->occluders, &ray, 1);
    ++ci->rays;
    return ray.tfar >= 0.0f ? 1.0 : 0.0;
}

static double e2_integrand(double mu, void *ctx)
{
    return mu > 0.0 ? exp(-*(const double *)ctx / mu) : 0.0;
}

double height_fog_exponential_integral_e2(double a)
{
    return quadrature_gk15(e2_integrand, &a, 0.0, 1.0, 1e-12, NULL);
}

/* beta_s,c L_amb,c, times E_2(beta_t,c H rho(y)) / 2 when the fog attenuates
 * the sky, at distance s (infinite: the end of an upward ray, rho = 0). */
static double ambient_source(const channel_integrand *ci, double s)
{
    if (!ci->l->sky_extinction || ci->amb_term == 0.0)
        return ci->amb_term;
    const height_fog_param *p = ci->l->medium;
    double rho = isfinite(s) ? height_fog_density(p, ci->origin.y + ci->dir.y * s) : 0.0;
    return ci->amb_term * 0.5 * height_fog_exponential_integral_e2(ci->beta_t * p->scale_height * rho);
}

/* e^{-beta_t u} J(s(u)). */
static double integrand(double u, void *ctx)
{
    channel_integrand *ci = ctx;
    const height_fog_param *p = ci->l->medium;
    double s = height_fog_distance_at(p, ci->origin.y, ci->dir.y, u);
    double sun = ci->sun_term;
    if (sun > 0.0 && isfinite(s)) {
        double y = ci->origin.y + ci->dir.y * s, t[3] = {1.0, 1.0, 1.0};
        if (ci->l->sun_extinction)
            height_fog_sun_transmittance(p, y, t);
        sun *= t[ci->channel];
        if (sun > 0.0)
            sun *= sun_visibility(ci, v3_add(ci->origin, v3_scale(ci->dir, (float)s)));
    }
    return exp(-ci->beta_t * u) * (sun + ambient_source(ci, s));
}

/* The split points 0, 1/2, 1, 2, 4, ... (in optical depth) up to the end. */
static int split_points(double beta_t, double end, double *points)
{
    int n = 0;
    points[n++] = 0.0;
    for (double tau = 0.5; n < MAX_SPLITS - 1 && tau / beta_t < end; tau *= 2.0)
        points[n++] = tau / beta_t;
    points[n++] = end;
    return n;
}

static void integrate_channel(channel_integrand *ci, double total, double rel_tol, height_fog_ray_estimate *out)
{
    int c = ci->channel;
    double bound = (ci->sun_term + ci->amb_term) / ci->beta_t, end = fmin(total, DEPTH_CUT / ci->beta_t);
    out->inscatter[c] = out->error[c] = 0.0;
    if (!(bound > 0.0) || !(end > 0.0))
        return;
    double points[MAX_SPLITS];
    int n = split_points(ci->beta_t, end, points);
    out->inscatter[c] = quadrature_gk15_split(integrand, ci, points, n, rel_tol * bound, &out->error[c]);
}

void height_fog_single_scatter(const height_fog_lighting *l, vec3 origin, vec3 dir, double distance, double rel_tol,
                        height_fog_ray_estimate *out)
{
    const height_fog_param *p = l->medium;
    double beta_t[3], beta_s[3], sun[3];
    height_fog_extinction(p, beta_t);
    height_fog_scattering(p, beta_s);
    height_fog_sun_scattering(p, v3_dot(p->sun_direction, dir), sun);
    double total = height_fog_ray_density(p, origin.y, dir.y, distance);
    out->rays = 0;
    for (int c = 0; c < 3; ++c) {
        out->transmittance[c] = beta_t[c] > 0.0 ? exp(-beta_t[c] * total) : 1.0;
        channel_integrand ci = {l, origin, dir, beta_t[c], beta_s[c] * p->amb_color[c], p->sun_color[c] * sun[c], c, 0};
        if (beta_t[c] > 0.0)
            integrate_channel(&ci, total, rel_tol, out);
        else
            out->inscatter[c] = out->error[c] = 0.0;
        out->rays += ci.rays;
    }
}
