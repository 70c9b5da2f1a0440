/* Volumetric path tracing in the height fog; see height_fog_path_tracer.h. */
#include "height_fog/height_fog_path_tracer.h"

#include <math.h>

#include "core/optics/phase_function.h"
#include "core/sampling/sobol.h"

enum { ROULETTE_AFTER = 8 };

/* Counter-based random numbers (splitmix64 of a running counter). */
typedef struct {
    uint64_t state;
} height_fog_rng;

static double rng_next(height_fog_rng *r)
{
    uint64_t z = (r->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1.0p-53;
}

/* A straight piece of a path through the medium. */
typedef struct {
    vec3 origin, dir;
    double length; /* to the scene, or +infinity */
} path_leg;

/* Samples the next collision on the leg. Returns 1 with the collision's
 * distance *t, or 0 when the path leaves the leg; weight[] gets w_c of the
 * header (collision or leaving). A leaving probability of 0 never happens
 * with 0 returned (the draw collides first). */
static int free_flight(const height_fog_param *p, const double beta_t[3], const path_leg *leg, height_fog_rng *r,
                       double *t, double weight[3])
{
    int c = (int)(3.0 * rng_next(r));
    c = c > 2 ? 2 : c;
    double depth = -log1p(-rng_next(r)) / beta_t[c];
    double at = beta_t[c] > 0.0 ? height_fog_distance_at(p, leg->origin.y, leg->dir.y, depth) : INFINITY;
    int collides = at < leg->length;
    double d_int = collides ? depth : height_fog_ray_density(p, leg->origin.y, leg->dir.y, leg->length);
    double pdf = 0.0, f[3];
    for (int k = 0; k < 3; ++k) {
        double transmitted = beta_t[k] > 0.0 ? exp(-beta_t[k] * d_int) : 1.0;
        f[k] = collides ? beta_t[k] * transmitted : transmitted;
        pdf += f[k] / 3.0;
    }
    for (int k = 0; k < 3; ++k)
        weight[k] = pdf > 0.0 ? f[k] / pdf : 0.0;
    *t = at;
    return collides;
}

/* The camera leg's collision, forced inside the medium (a path that leaves
 * the camera's segment without colliding carries no in-scattered light, so
 * that event only adds variance: rare on rays through a thick but finite
 * layer, it would leave the per-pixel standard error blind to it). With
 * D the leg's density integral, channel c* uniform and the optical depth
 * u in [0, D) from the truncated exponential of beta_t,c*,
 *   u = -log1p(xi expm1(-beta_t,c* D)) / beta_t,c*,
 * the mixture density is q(u) = (1/m) sum_k beta_t,k e^{-beta_t,k u} / (1 - e^{-beta_t,k D})
 * over the m channels with medium on the leg (c* uniform among them), and
 * weight[c] = beta_t,c e^{-beta_t,c u} / q(u): the same estimator as
 * free_flight's with the leaving event integrated out. Returns 0 (no
 * collision) only where the leg holds no medium. */
static int forced_flight(const height_fog_param *p, const double beta_t[3], const path_leg *leg, height_fog_rng *r,
                         double *t, double weight[3])
{
    double pick = rng_next(r), xi = rng_next(r), total = height_fog_ray_density(p, leg->origin.y, leg->dir.y, leg->length);
    double inside[3], pdf = 0.0;
    int with_medium[3], m = 0;
    for (int k = 0; k < 3; ++k) {
        inside[k] = beta_t[k] > 0.0 ? -expm1(-beta_t[k] * total) : 0.0; /* 1 - e^{-beta D}; 1 for D = inf */
        if (inside[k] > 0.0)
            with_medium[m++] = k;
    }
    if (m == 0) {
        weight[0] = weight[1] = weight[2] = 1.0; /* no medium: the leg transmits everything */
        return 0;
    }
    int c = with_medium[(int)fmin(m * pick, m - 1)];
    double depth = -log1p(-xi * inside[c]) / beta_t[c];
    for (int k = 0; k < 3; ++k)
        pdf += inside[k] > 0.0 ? beta_t[k] * exp(-beta_t[k] * depth) / inside[k] / m : 0.0;
    for (int k = 0; k < 3; ++k)
        weight[k] = beta_t[k] * exp(-beta_t[k] * depth) / pdf;
    double at = height_fog_distance_at(p, leg->origin.y, leg->dir.y, depth);
    *t = at < leg->length ? at : leg->length; /* rounding at the far end */
    return 1;
}

/* 1 when nothing of the scene lies between x and the sun. */
static double sun_visible(const embree_scene *occluders, vec3 x, vec3 sun, int *rays)
{
    if (!occluders)
        return 1.0;
    struct RTCRay ray;
    embree_ray_init(&ray, x, sun, INFINITY);
    ray.tnear = 1e-4f * (1.0f + v3_max_abs_component(x));
    embree_unoccluded_stream(occluders, &ray, 1);
    ++*rays;
    return ray.tfar >= 0.0f ? 1.0 : 0.0;
}

/* Next-event estimation of the sun at collision x, the path travelling
 * along w with throughput[c] (collision weight included). */
static void add_sun(const height_fog_path_settings *s, const double beta_t[3], vec3 x, vec3 w, const double throughput[3],
                    double radiance[3], int *rays)
{
    const height_fog_param *p = s->lighting.medium;
    double sun[3], t[3] = {1.0, 1.0, 1.0};
    height_fog_sun_scattering(p, v3_dot(p->sun_direction, w), sun);
    if (s->lighting.sun_extinction)
        height_fog_sun_transmittance(p, x.y, t);
    if (t[0] + t[1] + t[2] <= 0.0 || sun[0] + sun[1] + sun[2] <= 0.0)
        return;
    if (p->sun_color[0] + p->sun_color[1] + p->sun_color[2] <= 0.0)
        return;
    double v = sun_visible(s->lighting.occluders, x, p->sun_direction, rays);
    for (int c = 0; c < 3; ++c)
        if (beta_t[c] > 0.0) /* else the channel never collides: throughput 0 */
            radiance[c] += throughput[c] * p->sun_color[c] * sun[c] * t[c] * v / beta_t[c];
}

/* A new direction from the Rayleigh/HG mixture; multiplies the throughput
 * by (beta_Rs p_R + beta_Ms p_HG) / (beta_t pdf). */
static vec3 scatter(const height_fog_param *p, const double beta_t[3], vec3 w, height_fog_rng *r, double throughput[3])
{
    double mean_rs = (p->beta_rs[0] + p->beta_rs[1] + p->beta_rs[2]) / 3.0;
    double q = p->beta_ms > 0.0 ? p->beta_ms / (p->beta_ms + mean_rs) : 0.0;
    double u0 = rng_next(r), u1 = rng_next(r), u2 = rng_next(r);
    vec3 d;
    if (u0 < q) {
        d = henyey_greenstein_sample(w, p->mie_g, u1, u2);
    } else {
        double z = 1.0 - 2.0 * u1, s = sqrt(fmax(0.0, 1.0 - z * z)), phi = 2.0 * M_PI * u2;
        d = v3((float)(s * cos(phi)), (float)(s * sin(phi)), (float)z);
    }
    d = v3_normalize(d);
    double mu = v3_dot(w, d), p_hg = henyey_greenstein_phase(mu, p->mie_g), p_r = rayleigh_phase(mu);
    double pdf = q * p_hg + (1.0 - q) / (4.0 * M_PI);
    for (int c = 0; c < 3; ++c)
        throughput[c] = beta_t[c] > 0.0 ? throughput[c] * (p->beta_rs[c] * p_r + p->beta_ms * p_hg) / (beta_t[c] * pdf)
                                        : 0.0;
    return d;
}

/* The distance from x along d to the scene, +infinity without one. */
static double scene_distance(const embree_scene *occluders, vec3 x, vec3 d, int *rays)
{
    if (!occluders)
        return INFINITY;
    surface_hit hit;
    ++*rays;
    return embree_closest_hit(occluders, x, d, INFINITY, &hit) ? hit.t : INFINITY;
}

/* Russian roulette: 0 to stop, else the throughput is rescaled. */
static int survives(double throughput[3], int scatterings, height_fog_rng *r)
{
    if (scatterings < ROULETTE_AFTER)
        return 1;
    double m = fmax(throughput[0], fmax(throughput[1], throughput[2]));
    if (m >= 1.0)
        return 1;
    if (!(m > 0.0) || rng_next(r) >= m)
        return 0;
    for (int c = 0; c < 3; ++c)
        throughput[c] /= m;
    return 1;
}

int height_fog_path_sample(const height_fog_path_settings *s, vec3 o, vec3 w, double distance, uint32_t seed, uint32_t index,
                    double radiance[3])
{
    const height_fog_param *p = s->lighting.medium;
    double beta_t[3], beta_s[3], throughput[3] = {1.0, 1.0, 1.0};
    height_fog_extinction(p, beta_t);
    height_fog_scattering(p, beta_s);
    height_fog_rng r = {((uint64_t)hash_combine(seed, index) << 32) | hash_combine(index, ~seed)};
    path_leg leg = {o, w, distance};
    int rays = 0;
    radiance[0] = radiance[1] = radiance[2] = 0.0;
    for (int n = 0;; ++n) {
        double t, weight[3];
        int collides = n == 0 ? forced_flight(p, beta_t, &leg, &r, &t, weight)
                              : free_flight(p, beta_t, &leg, &r, &t, weight);
        for (int c = 0; c < 3; ++c)
            throughput[c] *= weight[c];
        if (!collides) {
            if (n > 0 && leg.length == INFINITY) /* out to the sky */
                for (int c = 0; c < 3; ++c)
                    radiance[c] += throughput[c] * p->amb_color[c];
            return rays;
        }
        vec3 x = v3_add(leg.origin, v3_scale(leg.dir, (float)t));
        add_sun(s, beta_t, x, leg.dir, throughput, radiance, &rays);
        if (s->max_scatterings == 1) {
            for (int c = 0; c < 3; ++c)
                if (beta_t[c] > 0.0)
                    radiance[c] += throughput[c] * beta_s[c] * p->amb_color[c] / beta_t[c];
            return rays;
        }
        if (n + 1 >= s->max_scatterings || !survives(throughput, n, &r))
            return rays;
        leg.origin = x;
        leg.dir = scatter(p, beta_t, leg.dir, &r, throughput);
        leg.length = scene_distance(s->lighting.occluders, x, leg.dir, &rays);
    }
}
