/* A planet's atmosphere for the Decima height-fog LUTs (Kojima Productions,
 * "Height fog", SIGGRAPH 2017 Advances; issue 16 item 3): the parameters,
 * the two weathers and their blend, the ray/sphere geometry and the optical
 * depth of a segment by quadrature.
 *
 * Model (Bruneton 2017, "Precomputed Atmospheric Scattering: a New
 * Implementation", its demo's defaults; Bruneton & Neyret 2008 eqs. 1-2):
 * a black ground sphere of radius R_b = 6360 km under an atmosphere ending at
 * R_t = 6420 km; at altitude h = r - R_b two species with exponential density
 *   Rayleigh: beta_s^R(h) = beta_R exp(-h / H_R), no absorption,
 *             beta_R = (5.802, 13.558, 33.1) 1e-6 /m at (680, 550, 440) nm, H_R = 8 km;
 *   Mie:      beta_s^M(h) = beta_Ms exp(-h / H_M), beta_t^M = beta_Me exp(-h / H_M),
 *             beta_Ms = 3.996e-6 /m, beta_Me = 4.440e-6 /m (grey), H_M = 1.2 km,
 *             phase Cornette-Shanks with g = 0.8 (core/optics/phase_function.h).
 * No ozone (Bruneton's optional layer): the sunset sky is less blue than his.
 * Solar irradiance E_sun = (1.474, 1.8504, 1.91198) W m^-2 nm^-1 at the three
 * wavelengths (Bruneton 2017 demo, kSolarIrradiance), angular radius 0.004675.
 *
 * Two weathers (the talk: "sunny and dense fog conditions as a base"):
 *   weather 0, clear: the defaults above;
 *   weather 1, dense fog: Rayleigh unchanged, Mie scattering and extinction
 *             x50 (beta_Ms = 1.998e-4, beta_Me = 2.22e-4 /m: visibility
 *             3.912 / beta_t = 17 km at the ground, Koschmieder) with H_M =
 *             0.6 km: a hazy, low layer of vertical optical depth 0.13 (25x the
 *             clear Mie layer's 0.0053) whose horizontal one from the ground
 *             (17, sqrt(pi R_b H_M / 2) beta_Me) hides the setting sun. Same g = 0.8 (fog droplets:
 *             0.8-0.85), so the Mie phase is one function of both.
 * The weather blend t in [0, 1] mixes the two atmospheres' coefficient
 * profiles, beta(h; t) = (1 - t) beta_clear(h) + t beta_fog(h) for every
 * species and channel (a mixture of the two media: every t is itself a
 * physical atmosphere, unlike a blend of scale heights). */
#ifndef GTLAB_ATMOSPHERE_MODEL_H
#define GTLAB_ATMOSPHERE_MODEL_H

#include <stddef.h>

enum { ATMOSPHERE_CHANNELS = 3 }; /* R, G, B at 680, 550, 440 nm */
enum { ATMOSPHERE_RAYLEIGH, ATMOSPHERE_MIE, ATMOSPHERE_SPECIES };
enum { ATMOSPHERE_CLEAR, ATMOSPHERE_DENSE_FOG, ATMOSPHERE_WEATHERS };

typedef struct {
    double rayleigh_scattering[ATMOSPHERE_CHANNELS]; /* at the ground [1/m] */
    double rayleigh_scale_height;                    /* [m] */
    double mie_scattering[ATMOSPHERE_CHANNELS];      /* at the ground [1/m] */
    double mie_extinction[ATMOSPHERE_CHANNELS];      /* at the ground [1/m] */
    double mie_scale_height;                         /* [m] */
} atmosphere_weather;

typedef struct {
    double bottom_radius, top_radius; /* [m] */
    double solar_irradiance[ATMOSPHERE_CHANNELS];
    double sun_angular_radius; /* [rad] */
    double mie_g;
    atmosphere_weather weathers[ATMOSPHERE_WEATHERS];
} atmosphere_model;

atmosphere_weather atmosphere_weather_clear(void);
atmosphere_weather atmosphere_weather_dense_fog(void);
/* The defaults above with the clear and the dense-fog weathers. */
atmosphere_model atmosphere_model_default(void);

/* 0 when the model is usable: finite, non-negative coefficients, positive
 * scale heights, 0 < R_b < R_t, extinction >= scattering, |g| < 1; else -1
 * with one line naming the parameter in msg. */
int atmosphere_model_check(const atmosphere_model *m, char *msg, size_t size);

/* The coefficients at altitude h for weather blend t [1/m]. */
typedef struct {
    double scattering[ATMOSPHERE_SPECIES][ATMOSPHERE_CHANNELS];
    double extinction[ATMOSPHERE_CHANNELS]; /* both species */
} atmosphere_coefficients;
atmosphere_coefficients atmosphere_coefficients_at(const atmosphere_model *m, double t, double altitude);

/* Ray/sphere geometry of a ray from radius r with zenith cosine mu
 * (Bruneton 2017, DistanceToTopAtmosphereBoundary, RayIntersectsGround):
 *   top:    d = -r mu + sqrt(r^2 (mu^2 - 1) + R_t^2)
 *   ground: d = -r mu - sqrt(r^2 (mu^2 - 1) + R_b^2), hit when mu < 0 and the root is real;
 * and the radius and zenith cosines at distance d along it:
 *   r_d = sqrt(d^2 + 2 r mu d + r^2), mu_d = (r mu + d) / r_d,
 *   mu_s,d = (r mu_s + d nu) / r_d  (nu = cosine between the ray and the sun). */
double atmosphere_distance_to_top(const atmosphere_model *m, double r, double mu);
double atmosphere_distance_to_ground(const atmosphere_model *m, double r, double mu);
int atmosphere_ray_hits_ground(const atmosphere_model *m, double r, double mu);
/* The distance to the ground if the ray hits it, else to the top. */
double atmosphere_distance_to_boundary(const atmosphere_model *m, double r, double mu);
double atmosphere_radius_at(double r, double mu, double d);

/* The optical depth tau of the segment [0, d] of the ray (r, mu), per
 * channel, for blend t, by adaptive quadrature (core/sampling/quadrature.h) of the
 * species' column densities, split at the closest approach to the centre;
 * tolerance `tol` relative to each column's scale height. *error (may be
 * NULL) receives the largest channel's error estimate. */
void atmosphere_optical_depth(const atmosphere_model *m, double t, double r, double mu, double d, double tol,
                              double tau[ATMOSPHERE_CHANNELS], double *error);

/* The visible fraction of the sun's disc at radius r with sun zenith cosine
 * mu_s: the planet's horizon cuts it (Bruneton 2017, GetTransmittanceToSun's
 * smoothstep over the disc's angular diameter). */
double atmosphere_sun_visibility(const atmosphere_model *m, double r, double mu_s);

#endif
