#include "sphere_light/sphere_light_reference.h"

#include <math.h>

#include "core/sampling/cone_sampling.h"
#include "core/optics/ggx.h"
#include "core/sampling/hemisphere_sampling.h"
#include "core/sampling/sobol.h"

sphere_light_config sphere_light_config_make(double n_dot_v, double theta_l, double phi_l, double sin_sigma,
                                             double roughness)
{
    double sin_v = sqrt(fmax(0.0, 1.0 - n_dot_v * n_dot_v));
    sphere_light_config c;
    c.v = v3((float)sin_v, 0.0f, (float)n_dot_v);
    c.lc = v3((float)(sin(theta_l) * cos(phi_l)), (float)(sin(theta_l) * sin(phi_l)), (float)cos(theta_l));
    c.sin_sigma = sin_sigma;
    c.alpha = ggx_alpha(roughness);
    return c;
}

sphere_light_config sphere_light_config_near_mirror(double n_dot_v, double delta, double psi, double sin_sigma,
                                                    double roughness)
{
    double sin_v = sqrt(fmax(0.0, 1.0 - n_dot_v * n_dot_v));
    /* R = (-sin theta_v, 0, cos theta_v); (t, b) completes a frame, t towards n. */
    const double r[3] = {-sin_v, 0.0, n_dot_v}, t[3] = {n_dot_v, 0.0, sin_v}, b[3] = {0.0, 1.0, 0.0};
    double d[3];
    for (int k = 0; k < 3; ++k)
        d[k] = cos(delta) * r[k] + sin(delta) * (cos(psi) * t[k] + sin(psi) * b[k]);
    double theta = fmin(acos(fmin(1.0, fmax(-1.0, d[2]))), 0.5 * M_PI - M_PI / 180.0), phi = atan2(d[1], d[0]);
    return sphere_light_config_make(n_dot_v, theta, phi, sin_sigma, roughness);
}

/* Mean and sum of squared deviations of one estimator (Welford's update:
 * no cancellation when the variance is tiny next to the mean, as for a
 * Lambert plane under a small light). */
typedef struct {
    double n, mean, m2;
} moments;

static void moments_add(moments *m, double x)
{
    m->n += 1.0;
    double delta = x - m->mean;
    m->mean += delta / m->n;
    m->m2 += delta * (x - m->mean);
}

static void moments_result(const moments *m, double *mean, double *stderr_out)
{
    *mean = m->mean, *stderr_out = sqrt(m->m2 / (m->n - 1.0) / m->n);
}

/* The contribution of a direction drawn by the technique of density
 * pdf_self, the other having pdf_other there, under the power heuristic
 * (beta = 2): f cos w / pdf_self with w = pdf_self^2 / (pdf_self^2 + pdf_other^2).
 * Not the balance heuristic: with a sun-sized light the BRDF sampler lands
 * in the cap about once in 10^5 samples and under the balance heuristic
 * carries ~1e-5 of the result, missed (and absent from the standard
 * error) in most runs; the power heuristic leaves it ~1e-10. */
static double mis_term(double f_cos, double pdf_self, double pdf_other)
{
    if (!(f_cos > 0.0))
        return 0.0;
    double r = pdf_other / pdf_self;
    return f_cos / (pdf_self * (1.0 + r * r));
}

void sphere_light_mis_sample(const sphere_light_config *c, const float u_cap[2], const float u_brdf[2],
                             sphere_light_mis_terms *t)
{
    const double pdf_cap = 1.0 / cone_solid_angle(c->sin_sigma);
    /* Technique 1: uniform in the cap, shared by both integrals. */
    vec3 l = cone_sample_uniform(c->lc, c->sin_sigma, u_cap);
    double cos_l = fmax(0.0, (double)l.z);
    t->l_cap = l;
    t->spec_cap = mis_term(ggx_brdf(c->v, l, c->alpha) * cos_l, pdf_cap, ggx_reflection_pdf(c->v, l, c->alpha));
    t->diff_cap = mis_term(cos_l / M_PI, pdf_cap, cos_l / M_PI);
    /* Technique 2: GGX visible normals (specular), cosine (diffuse). */
    vec3 m = ggx_sample_visible_normal(c->v, c->alpha, u_brdf);
    vec3 ls = ggx_reflect(c->v, m);
    t->l_brdf = ls;
    t->spec_brdf = 0.0;
    if (ls.z > 0.0f && cone_contains(c->lc, c->sin_sigma, ls))
        t->spec_brdf = mis_term(ggx_brdf(c->v, ls, c->alpha) * ls.z, ggx_reflection_pdf(c->v, ls, c->alpha), pdf_cap);
    vec3 ld = sample_cosine_hemisphere(u_brdf);
    t->l_diff = ld;
    t->diff_brdf = cone_contains(c->lc, c->sin_sigma, ld) ? mis_term(ld.z / M_PI, ld.z / M_PI, pdf_cap) : 0.0;
}

void sphere_light_reference(const sphere_light_config *c, uint32_t samples, uint32_t seed,
                            sphere_light_estimate *out)
{
    sobol_pair_seeds cap_seeds = sobol_owen_pair_seeds(seed, 0);
    sobol_pair_seeds brdf_seeds = sobol_owen_pair_seeds(seed, 1);
    moments spec = {0, 0, 0}, diff = {0, 0, 0};
    for (uint32_t i = 0; i < samples; ++i) {
        float u_cap[2], u_brdf[2];
        sobol_owen_point(&cap_seeds, i, u_cap);
        sobol_owen_point(&brdf_seeds, i, u_brdf);
        sphere_light_mis_terms t;
        sphere_light_mis_sample(c, u_cap, u_brdf, &t);
        moments_add(&spec, t.spec_cap + t.spec_brdf);
        moments_add(&diff, t.diff_cap + t.diff_brdf);
    }
    moments_result(&spec, &out->spec, &out->spec_stderr);
    moments_result(&diff, &out->diff, &out->diff_stderr);
}

/* ---- Brute-force maximum of (N.H)^2 ---- */

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void normalize3(double a[3])
{
    double inv = 1.0 / sqrt(dot3(a, a));
    a[0] *= inv, a[1] *= inv, a[2] *= inv;
}

sphere_noh_config sphere_noh_config_make(double n_dot_v, double theta_l, double phi_l, double radius_tan)
{
    sphere_noh_config c = {{sqrt(fmax(0.0, 1.0 - n_dot_v * n_dot_v)), 0.0, n_dot_v},
                           {sin(theta_l) * cos(phi_l), sin(theta_l) * sin(phi_l), cos(theta_l)},
                           radius_tan};
    return c;
}

void sphere_noh_config_dots(const sphere_noh_config *c, float *n_dot_l, float *n_dot_v, float *v_dot_l)
{
    *n_dot_l = (float)c->lc[2], *n_dot_v = (float)c->v[2], *v_dot_l = (float)dot3(c->v, c->lc);
}

static void mirror_of_v(const sphere_noh_config *c, double r[3])
{
    r[0] = -c->v[0], r[1] = -c->v[1], r[2] = c->v[2];
}

static double cos_sigma(const sphere_noh_config *c) { return 1.0 / sqrt(1.0 + c->radius_tan * c->radius_tan); }

int sphere_noh_r_inside(const sphere_noh_config *c)
{
    double r[3];
    mirror_of_v(c, r);
    return dot3(r, c->lc) >= cos_sigma(c);
}

/* The frame (T, B) of the rim. */
static void rim_frame(const sphere_noh_config *c, double t[3], double b[3])
{
    double r[3];
    mirror_of_v(c, r);
    double rl = dot3(r, c->lc);
    for (int i = 0; i < 3; ++i)
        t[i] = r[i] - rl * c->lc[i];
    normalize3(t);
    b[0] = t[1] * c->lc[2] - t[2] * c->lc[1];
    b[1] = t[2] * c->lc[0] - t[0] * c->lc[2];
    b[2] = t[0] * c->lc[1] - t[1] * c->lc[0];
    if (b[2] < 0.0)
        b[0] = -b[0], b[1] = -b[1], b[2] = -b[2];
}

/* (N.H)^2 of the direction at angle theta from lc towards cos(phi) T + sin(phi) B. */
static double noh_squared_at(const sphere_noh_config *c, const double t[3], const double b[3], double sin_t,
                             double cos_t, double phi)
{
    double h[3];
    for (int i = 0; i < 3; ++i)
        h[i] = cos_t * c->lc[i] + sin_t * (cos(phi) * t[i] + sin(phi) * b[i]) + c->v[i];
    double hh = dot3(h, h);
    return hh > 0.0 ? h[2] * h[2] / hh : 0.0;
}

double sphere_rim_noh_squared_at(const sphere_noh_config *c, double phi)
{
    double t[3], b[3], cs = cos_sigma(c);
    rim_frame(c, t, b);
    return noh_squared_at(c, t, b, c->radius_tan * cs, cs, phi);
}

/* Golden-section refinement of a maximum of g(phi) bracketed by [lo, hi]. */
static double refine_max(const sphere_noh_config *c, const double t[3], const double b[3], double sin_t,
                         double cos_t, double lo, double hi, double *phi_out)
{
    const double k = 0.5 * (sqrt(5.0) - 1.0);
    double x1 = hi - k * (hi - lo), x2 = lo + k * (hi - lo);
    double f1 = noh_squared_at(c, t, b, sin_t, cos_t, x1), f2 = noh_squared_at(c, t, b, sin_t, cos_t, x2);
    for (int i = 0; i < 60; ++i) {
        if (f1 > f2)
            hi = x2, x2 = x1, f2 = f1, x1 = hi - k * (hi - lo), f1 = noh_squared_at(c, t, b, sin_t, cos_t, x1);
        else
            lo = x1, x1 = x2, f1 = f2, x2 = lo + k * (hi - lo), f2 = noh_squared_at(c, t, b, sin_t, cos_t, x2);
    }
    *phi_out = 0.5 * (lo + hi);
    return fmax(f1, f2);
}

/* The best of `steps` angles on the circle at angle theta from lc, refined. */
static double circle_max(const sphere_noh_config *c, const double t[3], const double b[3], double theta, int steps,
                         double *phi_out)
{
    double sin_t = sin(theta), cos_t = cos(theta), step = 2.0 * M_PI / steps;
    double best = -1.0;
    int best_k = 0;
    for (int k = 0; k < steps; ++k) {
        double f = noh_squared_at(c, t, b, sin_t, cos_t, k * step);
        if (f > best)
            best = f, best_k = k;
    }
    double phi;
    double refined = refine_max(c, t, b, sin_t, cos_t, (best_k - 1) * step, (best_k + 1) * step, &phi);
    if (refined < best)
        refined = best, phi = best_k * step;
    *phi_out = phi;
    return refined;
}

double sphere_noh_squared_max(const sphere_noh_config *c, int steps, int over_disc, double *phi_out)
{
    double t[3], b[3], phi;
    rim_frame(c, t, b);
    double sigma = atan(c->radius_tan);
    double best = circle_max(c, t, b, sigma, steps, &phi);
    if (phi_out)
        *phi_out = phi;
    for (int j = 0; over_disc && j < steps; ++j) {
        double ring = circle_max(c, t, b, sigma * j / steps, steps, &phi);
        best = fmax(best, ring);
    }
    return best;
}
