/* The split-sum DFG LUT (Karis 2013): the quadrature in GGX's own
 * coordinates, the table and its bilinear lookup (luts/table_lookup.inc, the
 * text the generated shaders carry). See the header for the integrals, the
 * coordinates and the axes. */
#include "luts/dfg_lut.h"

#include <math.h>
#include <stdlib.h>

#include "core/optics/ggx.h"
#include "core/sampling/quadrature.h"
#include "core/vec3.h" /* M_PI */
#include "luts/table_lookup_c.h"
#include "luts/table_lookup.inc"

enum { MAX_BREAKS = 64 };
static const double OUTER_TOLERANCE = 1e-7; /* absolute, on A and on B */
/* Relative to the inner integrand's bound pi / (n.v cos theta_h) (G2, v.h and the weight are at most 1). */
static const double INNER_TOLERANCE = 1e-8;

const char *dfg_lut_description(void)
{
    return "split-sum DFG (Karis 2013) at data[(j*N + i)*3 + c]; texel centres: "
           "i: n.v = (i + 0.5)/N (clamped to >= 1e-4), j: r = (j + 0.5)/N perceptual roughness (GGX alpha = r^2, "
           "height-correlated Smith G2); c = 0: A (scale), 1: B (bias), 2: E = A + B (white single-scattering albedo); "
           "specular = (F0*A + B) * prefiltered * (1 + F0*(1/E - 1)), Schlick Fc = (1 - v.h)^5";
}

double dfg_energy_compensation(double albedo, double f0) { return 1.0 + f0 * (1.0 / albedo - 1.0); }

/* The view direction v = (sin_v, 0, mu) and the half vector's polar angle
 * (theta_h) while the inner integral over phi runs. */
typedef struct {
    double mu, sin_v, alpha;
    int channel; /* DFG_SCALE: weight 1 - Fc; DFG_BIAS: weight Fc */
    double tan_h, cos_h, sin_h;
    double max_inner_error; /* the largest inner error estimate (of inner / pi) in the current panel */
} dfg_integrand;

static double pow5(double x) { return x * x * x * x * x; }

/* G2 (v.h) w / (mu cos theta_h) at azimuth phi (header: the Jacobians). */
static double over_phi(double phi, void *ctx)
{
    const dfg_integrand *q = ctx;
    double vh = q->sin_v * q->sin_h * cos(phi) + q->mu * q->cos_h;
    double nl = 2.0 * vh * q->cos_h - q->mu;
    if (nl <= 0.0)
        return 0.0;
    double fc = pow5(1.0 - vh), w = q->channel == DFG_BIAS ? fc : 1.0 - fc;
    return ggx_smith_g2(q->mu, fmin(nl, 1.0), q->alpha) * vh * w / (q->mu * q->cos_h);
}

/* tan theta_h of the GGX cumulative coordinate s (Walter 2007, eq. 35). */
static double tan_theta_of_s(double s, double alpha) { return alpha > 0.0 ? alpha * sqrt(s / (1.0 - s)) : 0.0; }

/* Its inverse s(theta_h) = tan^2 / (alpha^2 + tan^2). */
static double s_of_theta(double theta, double alpha)
{
    double t = tan(theta);
    return alpha > 0.0 ? t * t / (alpha * alpha + t * t) : 1.0;
}

/* acos c, c = mu (tan^2 - 1) / (2 tan sin_v): where l meets the horizon. */
static double phi_max(const dfg_integrand *q)
{
    double t = q->tan_h, num = q->mu * (t * t - 1.0), den = 2.0 * t * q->sin_v;
    if (den <= 0.0)
        return num < 0.0 ? M_PI : 0.0;
    double c = num / den;
    return c <= -1.0 ? M_PI : c >= 1.0 ? 0.0 : acos(c);
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The scale of the horizon's boundary layer: G2(v, l) falls to 0 as n.l -> 0
 * once n.l is below ~alpha (Lambda(l) ~ alpha / (2 n.l)) or ~n.v (where
 * Lambda(l) overtakes Lambda(v)); break points at n.l = scale 8^k grade the
 * panels towards it, so each is analytic well beyond its ends. */
static double layer_scale(const dfg_integrand *q) { return 0.25 * fmax(1e-7, fmin(q->mu, q->alpha)); }

/* Break points of [0, top] in phi: 0, where n.l = K (cos phi - c) equals
 * layer_scale 8^k (K = 2 cos theta_h sin theta_h sin theta_v), top. */
static int phi_break_points(const dfg_integrand *q, double top, double *points)
{
    double t = q->tan_h, k_slope = 2.0 * q->cos_h * q->sin_h * q->sin_v;
    double c = k_slope > 0.0 ? q->mu * (t * t - 1.0) / (2.0 * t * q->sin_v) : -INFINITY;
    int n = 0;
    points[n++] = 0.0;
    for (double nl = layer_scale(q); k_slope > 0.0 && nl < 2.0 && n < MAX_BREAKS - 1; nl *= 8.0) {
        double x = c + nl / k_slope;
        if (x > -1.0 && x < 1.0 && acos(x) < top)
            points[n++] = acos(x);
    }
    points[n++] = top;
    qsort(points, (size_t)n, sizeof *points, compare_doubles);
    return n;
}

/* (1/pi) \int_0^{phi_max} over_phi: the outer integrand at s. */
static double over_s(double s, void *ctx)
{
    dfg_integrand *q = ctx;
    q->tan_h = tan_theta_of_s(s, q->alpha);
    q->cos_h = 1.0 / sqrt(1.0 + q->tan_h * q->tan_h);
    q->sin_h = q->tan_h * q->cos_h;
    double top = phi_max(q), err = 0.0, points[MAX_BREAKS];
    if (top <= 0.0)
        return 0.0;
    int n = phi_break_points(q, top, points);
    double bound = M_PI / (q->mu * q->cos_h);
    double inner = quadrature_gk15_split(over_phi, q, points, n, INNER_TOLERANCE * bound, &err);
    q->max_inner_error = fmax(q->max_inner_error, err / M_PI);
    return inner / M_PI;
}

/* Below this s-measure times the integrand's bound 1 / n.v, a piece of the
 * outer integral is below the tolerance and needs no break point of its own. */
static const double NEGLIGIBLE_TAIL = 1e-10;

/* Adds theta to the break points if inside (0, end) and the mass of GGX
 * beyond it, 1 - s(theta) = alpha^2 / (alpha^2 + tan^2 theta), matters. */
static void add_theta(const dfg_integrand *q, double theta, double end, double *thetas, int *n)
{
    double t = tan(theta), tail = q->alpha * q->alpha / (q->alpha * q->alpha + t * t);
    if (theta > 0.0 && theta < end && tail > NEGLIGIBLE_TAIL * q->mu && *n < MAX_BREAKS)
        thetas[(*n)++] = theta;
}

static int s_break_points(const dfg_integrand *q, double theta_v, double *points)
{
    double full = 0.25 * M_PI - 0.5 * theta_v, end = 0.25 * M_PI + 0.5 * theta_v, thetas[MAX_BREAKS];
    int n = 0;
    add_theta(q, full, end, thetas, &n);
    for (double theta = 2.0 * q->alpha; q->alpha > 0.0 && theta < full; theta *= 8.0)
        add_theta(q, theta, end, thetas, &n);
    for (double d = 0.5 * layer_scale(q); d < 0.5; d *= 8.0) {
        add_theta(q, full - d, end, thetas, &n), add_theta(q, full + d, end, thetas, &n);
        add_theta(q, end - d, end, thetas, &n);
    }
    qsort(thetas, (size_t)n, sizeof *thetas, compare_doubles);
    points[0] = 0.0;
    for (int i = 0; i < n; ++i)
        points[i + 1] = s_of_theta(thetas[i], q->alpha);
    points[n + 1] = s_of_theta(end, q->alpha);
    return n + 2;
}

/* One channel (A or B); *error receives its error estimate: the outer
 * panels' |K15 - G7| plus, per panel, its width times the largest inner
 * error estimate in it (the panels follow the integrand's scales, so this
 * bound is not spoilt by large integrands on negligible s-measure). */
static double integrate_channel(double mu, double alpha, int channel, double *error)
{
    dfg_integrand q = {mu, sqrt(fmax(0.0, 1.0 - mu * mu)), alpha, channel, 0.0, 1.0, 0.0, 0.0};
    double points[MAX_BREAKS + 2], value = 0.0;
    int n = s_break_points(&q, acos(mu), points);
    *error = 0.0;
    for (int i = 0; i + 1 < n; ++i) {
        double panel_error = 0.0;
        q.max_inner_error = 0.0;
        if (points[i + 1] > points[i])
            value += quadrature_gk15(over_s, &q, points[i], points[i + 1], OUTER_TOLERANCE / (n - 1), &panel_error);
        *error += panel_error + (points[i + 1] - points[i]) * q.max_inner_error;
    }
    return value;
}

double dfg_integrate(double n_dot_v, double roughness, double out[3])
{
    double mu = fmin(1.0, fmax(DFG_MIN_N_DOT_V, n_dot_v));
    double alpha = ggx_alpha(fmin(1.0, fmax(0.0, roughness))), error_a, error_b;
    out[DFG_SCALE] = integrate_channel(mu, alpha, DFG_SCALE, &error_a);
    out[DFG_BIAS] = integrate_channel(mu, alpha, DFG_BIAS, &error_b);
    out[DFG_ALBEDO] = out[DFG_SCALE] + out[DFG_BIAS];
    return fmax(error_a, error_b);
}

int dfg_lut_size_valid(int size) { return size >= DFG_MIN_SIZE && size <= DFG_MAX_SIZE; }

int dfg_lut_build(dfg_lut *lut, int size, int threads)
{
    if (!dfg_lut_size_valid(size)) {
        lut->size = 0, lut->data = NULL, lut->error_estimate = NULL, lut->max_error_estimate = 0.0;
        return -1;
    }
    return dfg_lut_build_any_size(lut, size, threads);
}

int dfg_lut_build_any_size(dfg_lut *lut, int size, int threads)
{
    size_t texels = (size_t)size * (size_t)size;
    lut->size = size, lut->max_error_estimate = 0.0;
    lut->data = malloc(sizeof *lut->data * texels * DFG_CHANNELS);
    lut->error_estimate = malloc(sizeof *lut->error_estimate * texels);
    if (size < 2 || !lut->data || !lut->error_estimate) {
        dfg_lut_free(lut);
        return -1;
    }
    double max_error = 0.0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) reduction(max : max_error)
    for (int t = 0; t < (int)texels; ++t) {
        double value[3], nv = (t % size + 0.5) / size, r = (t / size + 0.5) / size;
        double err = dfg_integrate(nv, r, value);
        for (int c = 0; c < DFG_CHANNELS; ++c)
            lut->data[(size_t)t * DFG_CHANNELS + c] = (float)value[c];
        lut->error_estimate[t] = (float)err;
        max_error = fmax(max_error, err);
    }
    lut->max_error_estimate = max_error;
    return 0;
}

void dfg_lut_free(dfg_lut *lut)
{
    free(lut->data);
    free(lut->error_estimate);
    lut->data = NULL, lut->error_estimate = NULL;
}

void dfg_lut_sample(const dfg_lut *lut, float n_dot_v, float roughness, float out[3])
{
    for (int c = 0; c < DFG_CHANNELS; ++c) {
        dfg_table table = {lut->data, lut->size, DFG_CHANNELS, c};
        out[c] = dfg_lookup(table, n_dot_v, roughness);
    }
}
