/* The equirectangular environment as the engines' lighting approximations
 * (environment/sh_irradiance.h, environment/irradiance_map.h, environment/prefiltered_radiance.h)
 * take it: a float RGB image of width x height texels, row-major, three
 * floats per texel, read as piecewise-constant radiance (each texel's value
 * over its whole solid angle). The mapping is core/optics/environment_map.h's
 * (Blender's world mapping through the glTF axes, world up +Y): a texel
 * (i, j) covers
 *
 *   phi   in [2 pi (i / W - 1/2), 2 pi ((i + 1) / W - 1/2)]   (u = i / W .. (i + 1) / W)
 *   theta in [pi j / H, pi (j + 1) / H]                         (polar angle from +Y; row 0 at the zenith)
 *
 * and a direction is w = (sin theta cos phi, cos theta, sin theta sin phi),
 * dw = sin theta dtheta dphi. So a texel's solid angle is
 *   Omega_j = (2 pi / W) (cos theta_j - cos theta_{j+1})
 * (the rows sum to 4 pi exactly), and every integral of a polynomial of
 * degree <= 2 in w over a texel factors into a theta part and a phi part
 * with closed forms (equirect_texel_moments): what makes the SH projection
 * and the irradiance map's quadrature exact per texel.
 *
 * The map's own levels (irradiance, pre-filtered radiance, the filtered
 * pyramid of the source) use the same convention; a lookup is bilinear with
 * texel centres at ((i + 0.5) / W, (j + 0.5) / H), wrapping in phi and
 * clamped in theta, as a GPU samples a lat-long texture. */
#ifndef GTLAB_ENVIRONMENT_ENVIRONMENT_EQUIRECT_H
#define GTLAB_ENVIRONMENT_ENVIRONMENT_EQUIRECT_H

/* A view of an environment (not owned). */
typedef struct {
    int width, height;
    const float *rgb; /* width * height * 3 */
} environment_equirect;

/* The direction at image coordinates (u, v) in [0, 1]^2: phi = 2 pi (u - 1/2), theta = pi v. */
void equirect_direction(double u, double v, double w[3]);
/* Its inverse for a unit direction: u in [0, 1), v in [0, 1]. */
void equirect_coordinates(const double w[3], double *u, double *v);
/* The centre direction of texel (i, j). */
void equirect_texel_direction(int width, int height, int i, int j, double w[3]);
/* Omega_j of a texel of row j. */
double equirect_texel_solid_angle(int width, int height, int j);

/* The integrals of the ten monomials of degree <= 2 over texel (i, j):
 * m = {1, x, y, z, xy, yz, xz, x^2, y^2, z^2} integrated over its solid angle. */
enum { EQUIRECT_MONOMIALS = 10 };
enum { MONO_1, MONO_X, MONO_Y, MONO_Z, MONO_XY, MONO_YZ, MONO_XZ, MONO_XX, MONO_YY, MONO_ZZ };
void equirect_texel_moments(int width, int height, int i, int j, double m[EQUIRECT_MONOMIALS]);

/* The bilinear lookup above into out[3]. */
void equirect_bilinear(const float *rgb, int width, int height, const double w[3], float out[3]);

/* A filtered pyramid of an environment: level 0 is the source (copied),
 * level k + 1 averages 2 x 2 texels of level k weighted by their solid
 * angles (so every level holds the same integral of radiance), down to a
 * width of EQUIRECT_PYRAMID_MIN_WIDTH or an odd size. */
enum { EQUIRECT_PYRAMID_MAX_LEVELS = 16, EQUIRECT_PYRAMID_MIN_WIDTH = 4 };
typedef struct {
    int levels;
    int width[EQUIRECT_PYRAMID_MAX_LEVELS], height[EQUIRECT_PYRAMID_MAX_LEVELS];
    float *rgb[EQUIRECT_PYRAMID_MAX_LEVELS];
} equirect_pyramid;

/* Returns 0, or -1 when out of memory or the environment is empty. */
int equirect_pyramid_build(equirect_pyramid *p, const environment_equirect *env);
void equirect_pyramid_free(equirect_pyramid *p);
/* Trilinear lookup at a fractional level (clamped to the pyramid). */
void equirect_pyramid_lookup(const equirect_pyramid *p, const double w[3], double level, float out[3]);

#endif
