/* The analytic height fog, published and corrected; see height_fog.h. The
 * arithmetic is float, as in the shader. */
#include "height_fog/height_fog.h"

#include <math.h>

#include "height_fog/height_fog_published.h"

void height_fog_uniforms_init(const height_fog_param *p, height_fog_uniforms *u)
{
    float g = (float)p->mie_g, ms = (float)p->beta_ms;
    u->scale_height = (float)p->scale_height;
    for (int c = 0; c < 3; ++c) {
        float rs = (float)p->beta_rs[c];
        u->beta_t[c] = rs + (ms + (float)p->beta_ma);
        u->rayleigh_weight[c] = (float)p->albedo_r[c] * rs;
        u->mie_weight[c] = (float)p->albedo_m[c] * ms;
        u->sun[c] = (float)p->sun_color[c];
        u->ambient[c] = (float)p->amb_color[c] * (rs + ms);
    }
    u->hg_numerator = 1.0f - g * g;
    u->hg_base = 1.0f + g * g;
    u->hg_slope = 2.0f * g;
}

/* (E_sun S_sun(mu) + L_amb beta_s) / beta_t per channel: the source term
 * over extinction, and its sun part E_sun S_sun(mu) / beta_t. */
static void source_over_extinction(const height_fog_uniforms *u, float sov, float source[3], float sun[3])
{
    float pr = height_fog_rayleigh(sov), pm = height_fog_henyey_greenstein(u, sov);
    for (int c = 0; c < 3; ++c) {
        float single = height_fog_single(u, c, pr, pm);
        source[c] = height_fog_source(u, c, single);
        sun[c] = u->sun[c] * single / u->beta_t[c];
    }
}

void height_fog_published(const height_fog_param *p, float distance, float camera_y, float world_y, float sov,
                          float inscatter[3], float transmittance[3])
{
    height_fog_uniforms u;
    height_fog_uniforms_init(p, &u);
    float source[3], sun[3];
    float t = height_fog_published_density(&u, height_fog_clamped_t(&u, camera_y, world_y), world_y);
    source_over_extinction(&u, sov, source, sun);
    for (int c = 0; c < 3; ++c) {
        transmittance[c] = expf(-distance * t * u.beta_t[c]);
        inscatter[c] = source[c] * (1.0f - transmittance[c]);
    }
}

/* f(x) = (1 - e^-x) / x, x >= 0 (core/optics/height_fog_medium.h). */
static float mean_factor_f(float x)
{
    return x > 0.0f ? -expm1f(-x) / x : 1.0f;
}

/* e^{-A} tau f(m tau) = e^{-A} (1 - e^{-m tau}) / m for any sign of m,
 * without overflow and finite as tau -> infinity (height_fog.h). */
static float attenuated_sun_integral(float a, float m, float tau)
{
    if (m > 0.0f)
        return expf(-a) * -expm1f(-m * tau) / m;
    if (m == 0.0f)
        return expf(-a) * tau;
    return expf(-(a + m * tau)) * -expm1f(m * tau) / -m; /* a + m tau = tau_v + tau_sun at the end >= 0 */
}

/* 6-point Gauss-Legendre on [0, 1] (Abramowitz and Stegun 1964, table 25.4,
 * mapped from [-1, 1]): nodes (1 + x_i) / 2, weights w_i / 2. */
static const float sky_mu[6] = {0.0337652429f, 0.1693953068f, 0.3806904070f,
                                0.6193095930f, 0.8306046932f, 0.9662347571f};
static const float sky_weight[6] = {0.0856622462f, 0.1803807865f, 0.2339569673f,
                                    0.2339569673f, 0.1803807865f, 0.0856622462f};

/* (1/2) \int_0^1 e^{-A/mu} tau f((1 - v_y/mu) tau) dmu (height_fog.h), with
 * A = beta_t times the column above the camera. */
static float attenuated_sky_integral(float a, float view_y, float tau)
{
    float sum = 0.0f;
    for (int k = 0; k < 6; ++k)
        sum += sky_weight[k] * attenuated_sun_integral(a / sky_mu[k], 1.0f - view_y / sky_mu[k], tau);
    return 0.5f * sum;
}

void height_fog_corrected(const height_fog_param *p, height_fog_correction level, float distance, float camera_y,
                          float world_y, float sov, float inscatter[3], float transmittance[3])
{
    height_fog_uniforms u;
    height_fog_uniforms_init(p, &u);
    float h = u.scale_height, source[3], sun[3];
    const float *beta_t = u.beta_t;
    float delta = world_y - camera_y, low = fminf(camera_y, world_y);
    float density = expf(-low / h) * mean_factor_f(fabsf(delta) / h); /* mean rho along the ray */
    source_over_extinction(&u, sov, source, sun);
    float mu_s = p->sun_direction.y, view_y = distance > 0.0f ? delta / distance : 0.0f;
    float column = h * expf(-camera_y / h), m = mu_s > 0.0f ? 1.0f - view_y / mu_s : 0.0f;
    for (int c = 0; c < 3; ++c) {
        float tau = distance * density * beta_t[c];
        transmittance[c] = expf(-tau);
        if (beta_t[c] == 0.0f) { /* clear air (the published form divides 0 by 0) */
            inscatter[c] = 0.0f;
            continue;
        }
        inscatter[c] = source[c] * -expm1f(-tau);
        if (level >= HEIGHT_FOG_ATTENUATE_SUN) {
            float attenuated = mu_s > 0.0f ? attenuated_sun_integral(beta_t[c] * column / mu_s, m, tau) : 0.0f;
            inscatter[c] += sun[c] * (attenuated - -expm1f(-tau));
        }
        if (level >= HEIGHT_FOG_ATTENUATE_SKY) {
            float ambient = u.ambient[c] / beta_t[c];
            inscatter[c] += ambient * (attenuated_sky_integral(beta_t[c] * column, view_y, tau) - -expm1f(-tau));
        }
    }
}
