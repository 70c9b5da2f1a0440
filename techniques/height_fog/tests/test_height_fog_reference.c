/* The height-fog references (techniques/height_fog/height_fog_single_scatter.h,
 * techniques/height_fog/height_fog_path_tracer.h) against closed forms and each other:
 *
 *   - homogeneous medium (H = 1e12 m): T = exp(-beta_t d) and single
 *     scattering (E S_sun(mu) + beta_s L_amb) / beta_t (1 - T), by quadrature
 *     and by Monte Carlo within 4 standard errors;
 *   - a downward ray in the exponential medium: the quadrature's ambient term
 *     beta_s/beta_t L_amb (1 - exp(-beta_t D)) with D written out by hand,
 *     H / |v_y| (e^{-y1/H} - e^{-y0/H});
 *   - quadrature vs Monte Carlo single scattering with the attenuated sun,
 *     rays down, horizontal and up, within 4 standard errors;
 *   - energy: no absorption, no sun, a uniform white sky of radiance 1 and a
 *     fog floor (so light can leave below): multiple scattering conserves
 *     radiance, L + T = 1, within 4 standard errors, although light scatters
 *     many times (column optical depth 3);
 *   - the transmittance is symmetric under swapped endpoints. */
#include <math.h>
#include <string.h>

#include "core/optics/phase_function.h"
#include "height_fog/height_fog_path_tracer.h"
#include "tests/check.h"

typedef struct {
    double mean[3], stderr_[3];
} mc_result;

static mc_result estimate(const height_fog_path_settings *s, vec3 o, vec3 w, double distance, int n, uint32_t seed)
{
    double sum[3] = {0}, sum2[3] = {0};
    for (int i = 0; i < n; ++i) {
        double l[3];
        height_fog_path_sample(s, o, w, distance, seed, (uint32_t)i, l);
        for (int c = 0; c < 3; ++c)
            sum[c] += l[c], sum2[c] += l[c] * l[c];
    }
    mc_result r;
    for (int c = 0; c < 3; ++c) {
        r.mean[c] = sum[c] / n;
        r.stderr_[c] = sqrt(fmax(0.0, sum2[c] / n - r.mean[c] * r.mean[c]) / (n - 1));
    }
    return r;
}

static height_fog_param medium(double h, double beta_ms, double elevation_deg)
{
    height_fog_param p = height_fog_param_default();
    p.scale_height = h;
    p.beta_ms = beta_ms;
    p.beta_ma = 0.1 * beta_ms;
    for (int c = 0; c < 3; ++c)
        p.beta_rs[c] *= 100.0;
    p.sun_color[0] = 1.0, p.sun_color[1] = 0.8, p.sun_color[2] = 0.6;
    double e = elevation_deg * M_PI / 180.0;
    p.sun_direction = v3(0.0f, (float)sin(e), (float)cos(e));
    return p;
}

static void check_homogeneous(void)
{
    height_fog_param p = medium(1e12, 2e-3, 30.0);
    vec3 o = v3(0.0f, 10.0f, 0.0f), w = v3_normalize(v3(0.3f, -0.01f, 1.0f));
    double d = 700.0, beta_t[3], beta_s[3], sun[3];
    height_fog_extinction(&p, beta_t);
    height_fog_scattering(&p, beta_s);
    height_fog_sun_scattering(&p, v3_dot(p.sun_direction, w), sun);
    height_fog_path_settings s = {{&p, 0, NULL, 0}, 1};
    height_fog_ray_estimate q;
    height_fog_single_scatter(&s.lighting, o, w, d, 1e-10, &q);
    mc_result m = estimate(&s, o, w, d, 20000, 11u);
    for (int c = 0; c < 3; ++c) {
        double t = exp(-beta_t[c] * d);
        double l = (p.sun_color[c] * sun[c] + beta_s[c] * p.amb_color[c]) / beta_t[c] * (1.0 - t);
        CHECK_NEAR(q.transmittance[c], t, 1e-9 * t); /* rho = 1 - 1e-11 at y = 10 */
        CHECK_NEAR(q.inscatter[c], l, 1e-9 * l);
        CHECK_MSG(fabs(m.mean[c] - l) <= 4.0 * m.stderr_[c], "MC %.6g +- %.2g vs %.6g", m.mean[c], m.stderr_[c], l);
    }
}

static void check_downward(void)
{
    height_fog_param p = medium(200.0, 1e-3, 30.0);
    p.sun_color[0] = p.sun_color[1] = p.sun_color[2] = 0.0;
    double y0 = 400.0, vy = -0.6, d = 900.0, y1 = y0 + vy * d;
    vec3 o = v3(5.0f, (float)y0, 0.0f), w = v3(0.0f, (float)vy, 0.8f);
    double by_hand = 200.0 / -vy * (exp(-y1 / 200.0) - exp(-y0 / 200.0));
    double beta_t[3], beta_s[3];
    height_fog_extinction(&p, beta_t);
    height_fog_scattering(&p, beta_s);
    height_fog_lighting l = {&p, 1, NULL, 0};
    height_fog_ray_estimate q;
    height_fog_single_scatter(&l, o, w, d, 1e-10, &q);
    for (int c = 0; c < 3; ++c) {
        double t = exp(-beta_t[c] * by_hand);
        CHECK_NEAR(q.transmittance[c], t, 1e-6 * t);
        CHECK_NEAR(q.inscatter[c], beta_s[c] / beta_t[c] * p.amb_color[c] * (1.0 - t), 1e-7);
    }
}

/* The attenuated sun and the ambient, single scattering, both ways. */
static void check_single_agree(double vy, double elevation)
{
    height_fog_param p = medium(150.0, 3e-3, elevation);
    vec3 o = v3(0.0f, 60.0f, 0.0f), w = v3_normalize(v3(0.2f, (float)vy, 1.0f));
    height_fog_path_settings s = {{&p, 1, NULL, 0}, 1};
    height_fog_ray_estimate q;
    height_fog_single_scatter(&s.lighting, o, w, 1500.0, 1e-9, &q);
    mc_result m = estimate(&s, o, w, 1500.0, 20000, 23u);
    for (int c = 0; c < 3; ++c) {
        CHECK(q.error[c] < 1e-6 * (q.inscatter[c] + 1e-3));
        CHECK_MSG(fabs(m.mean[c] - q.inscatter[c]) <= 4.0 * m.stderr_[c] && m.stderr_[c] < 0.02 * q.inscatter[c],
                  "v_y=%g elevation %g c=%d: MC %.6g +- %.2g vs quadrature %.6g", vy, elevation, c, m.mean[c],
                  m.stderr_[c], q.inscatter[c]);
    }
}

/* No absorption, no sun, sky radiance 1: what enters the camera is 1. */
static void check_energy(double vy)
{
    height_fog_param p = medium(100.0, 0.03, 30.0);
    p.beta_ma = 0.0;
    p.sun_color[0] = p.sun_color[1] = p.sun_color[2] = 0.0;
    p.amb_color[0] = p.amb_color[1] = p.amb_color[2] = 1.0;
    p.floor_y = 0.0;
    vec3 o = v3(0.0f, 40.0f, 0.0f), w = v3_normalize(v3(0.0f, (float)vy, 1.0f));
    height_fog_path_settings s = {{&p, 1, NULL, 0}, 4096};
    mc_result m = estimate(&s, o, w, INFINITY, 20000, 5u);
    double beta_t[3];
    height_fog_extinction(&p, beta_t);
    double d_int = height_fog_ray_density(&p, o.y, w.y, INFINITY);
    for (int c = 0; c < 3; ++c) {
        double t = exp(-beta_t[c] * d_int);
        CHECK_MSG(fabs(m.mean[c] + t - 1.0) <= 4.0 * m.stderr_[c] && m.stderr_[c] < 0.01,
                  "v_y=%g c=%d: L %.6g +- %.2g + T %.6g != 1", vy, c, m.mean[c], m.stderr_[c], t);
    }
}

static void check_symmetry(void)
{
    height_fog_param p = medium(120.0, 2e-3, 30.0);
    vec3 a = v3(3.0f, 10.0f, -4.0f), b = v3(250.0f, 330.0f, 400.0f);
    vec3 ab = v3_sub(b, a);
    double d = v3_length(ab);
    height_fog_lighting l = {&p, 1, NULL, 0};
    height_fog_ray_estimate qa, qb;
    height_fog_single_scatter(&l, a, v3_scale(ab, (float)(1.0 / d)), d, 1e-6, &qa);
    height_fog_single_scatter(&l, b, v3_scale(ab, (float)(-1.0 / d)), d, 1e-6, &qb);
    for (int c = 0; c < 3; ++c)
        CHECK_NEAR(qa.transmittance[c], qb.transmittance[c], 1e-6 * qa.transmittance[c]);
    CHECK(height_fog_segment_density(&p, 10.0, 330.0, d) == height_fog_segment_density(&p, 330.0, 10.0, d));
}

int main(void)
{
    check_homogeneous();
    check_downward();
    const double dirs[] = {-0.3, 0.0, 0.25};
    for (int i = 0; i < 3; ++i) {
        check_single_agree(dirs[i], 12.0);
        check_single_agree(dirs[i], 60.0);
        check_energy(dirs[i]);
    }
    check_symmetry();
    return check_report("test_height_fog_reference");
}
