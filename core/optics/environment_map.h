/* Distant lighting from every direction: an equirectangular (latitude-
 * longitude) environment of linear RGB radiance, piecewise constant per
 * texel, with a rotation about the up axis and an intensity factor. The
 * references lit by an environment (raytracer/environment_*) and the
 * engine approximations of the same light (luts/, realtime/) read it.
 *
 * Directions and texels. World up is +Y (glTF). For a unit direction
 * w = (x, y, z) in the map's frame:
 *
 *   u = 1/2 + atan2(z, x) / (2 pi)     in [0, 1], the column: x_t = u W
 *   v = acos(y) / pi                   in [0, 1], the row from the top: y_t = v H
 *
 * so row 0 is the zenith (+Y) and the last row the nadir; u runs left to
 * right through -X (u = 0, the image's left edge, seam), -Z (u = 1/4),
 * +X (u = 1/2, the image centre), +Z (u = 3/4) and -X again (u = 1).
 * Conversely phi = 2 pi (u - 1/2), theta = pi v and
 * w = (sin theta cos phi, cos theta, sin theta sin phi).
 * This is Blender's own mapping of a world texture (Cycles'
 * direction_to_equirectangular: u = 1/2 - atan2(y_b, x_b) / (2 pi), Z up)
 * carried through the glTF exporter's axes (x, y, z)_glTF = (x_b, z_b, -y_b),
 * and three.js's equirectUv: a camera at the origin looking at +X with +Y up
 * sees the image centre, with +Z to its right and u growing to the right, so
 * a photograph is not mirrored.
 *
 * Rotation: rotation_degrees = a turns the environment right-handedly about
 * +Y (+Z towards +X), i.e. world = R_y(a) map: what the file shows at u
 * appears at u - a / 360. Intensity multiplies every radiance.
 *
 * Texels and solid angle. Row r spans theta in [pi r / H, pi (r + 1) / H],
 * so each of its W texels subtends exactly
 *   Omega_r = (2 pi / W) (cos(pi r / H) - cos(pi (r + 1) / H))
 * (sum over the sphere: 4 pi). The radiance is the texel's value over the
 * whole texel (no filtering): the environment sampler
 * (core/optics/environment_sampler.h) draws directions uniformly in solid angle
 * within texels, so its density is exactly proportional to this lookup.
 *
 * Kinds: a file (any format OIIO reads: EXR including DWAB-compressed, as
 * Blender's studio lights are, Radiance .hdr, ...; width = 2 height,
 * finite, non-negative pixels; see ENVIRONMENT_RINGING); a constant (one radiance everywhere: the
 * white dome is constant 1; no texels); and a procedural map, a callback
 * averaged over each texel on a regular grid of s x s points, uniform in
 * phi and cos theta (the mean over the texel's solid angle to O(1/s^2)):
 * the analytic sky of core/optics/sky_environment.h, and a synthetic sun
 * (environment_sun below). */
#ifndef GTLAB_CORE_OPTICS_ENVIRONMENT_MAP_H
#define GTLAB_CORE_OPTICS_ENVIRONMENT_MAP_H

#include "core/error.h"
#include "core/vec3.h"

#define ENVIRONMENT_NAME_MAX 256

/* Lossy compression rings: every one of Blender's DWAB studio lights has
 * values slightly below 0 (down to -0.0039; at most 2.4% of the image's mean
 * luminance, night.exr's blue). Negative values no lower than
 * -ENVIRONMENT_RINGING times the mean luminance are read as 0 (counted in
 * clamped_values); anything lower is refused as a bad file. */
#define ENVIRONMENT_RINGING 0.05

/* Rec. 709 luminance of linear RGB (the weights of the sampler). */
static inline float environment_luminance(const float rgb[3])
{
    return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
}

typedef struct {
    char name[ENVIRONMENT_NAME_MAX]; /* the file, or "white", "sky", "sun", ... */
    int width, height;               /* texels, width = 2 height; 0 x 0 for a constant */
    float *rgb;                      /* 3 width height, row 0 at the zenith, as stored (intensity 1) */
    double *row_solid_angle;         /* Omega_r per texel of row r (height entries) */
    float constant[3];               /* a constant environment's radiance (intensity 1) */
    float rotation_degrees, intensity;
    float rotation_cos, rotation_sin;
    long clamped_values;             /* ringing values read as 0 (ENVIRONMENT_RINGING) */
} environment_map;

/* Every constructor starts from a zeroed environment_map and returns 0, or
 * -1 with e (one line naming the file or the environment) and nothing
 * allocated. Rotation 0 and intensity 1 until environment_map_transform. */

/* Reads path (any format OIIO reads). Refused: missing or unreadable, an
 * image of integer texels (8- or 16-bit: not radiance), not 2:1, non-finite
 * or negative pixels beyond ringing (the first such value is named). */
int environment_map_load(environment_map *env, const char *path, gt_error *e);

/* A copy of width x height interleaved RGB texels (row 0 at the zenith),
 * validated as a file is; name labels errors. */
int environment_map_from_pixels(environment_map *env, const char *name, int width, int height, const float *rgb,
                                gt_error *e);

/* Radiance rgb everywhere (finite, non-negative). */
int environment_map_constant(environment_map *env, const char *name, const float rgb[3], gt_error *e);

/* radiance(w, ctx, rgb): the radiance arriving from unit direction w (the
 * map's frame). */
typedef void (*environment_radiance_fn)(vec3 w, void *ctx, float rgb[3]);

/* A width x height map whose texels are the means of radiance over s x s
 * points per texel (above). */
int environment_map_procedural(environment_map *env, const char *name, int width, int height, int s,
                               environment_radiance_fn radiance, void *ctx, gt_error *e);

/* core/optics/sky_environment.h's L_sky on a 1024 x 512 map, 4 x 4 points per texel. */
int environment_map_sky(environment_map *env, gt_error *e);

/* A synthetic sun: a disc of angular radius `radius` (radians) about the
 * unit direction `direction`, of uniform radiance `radiance` (grey), over a
 * uniform grey sky of radiance `sky` (0: a sun-only environment). The
 * disc's solid angle is 2 pi (1 - cos radius); its irradiance on a surface
 * facing it is radiance times that. */
typedef struct {
    vec3 direction;
    double radius, radiance, sky;
} environment_sun;

/* The defaults of `--environment sun`: the sky's sun direction (30 degrees
 * up, turned 35 degrees from +Z towards +X: core/optics/sky_environment.h), radius
 * 0.5 degrees (solid angle 2.3925e-4 sr, 3.5 times the real sun's), radiance
 * pi / that solid angle = 13131 (a surface facing it receives irradiance pi,
 * what the white dome gives an open surface), sky 0.1. */
environment_sun environment_sun_default(void);

/* The sun on a 1024 x 512 map, 8 x 8 points per texel: the disc is
 * rasterised (its edge texels hold partial coverage). */
int environment_map_sun(environment_map *env, const environment_sun *sun, gt_error *e);

/* Sets the rotation about +Y (degrees, finite) and the intensity (finite,
 * >= 0). Returns 0 or -1 with e. */
int environment_map_transform(environment_map *env, float rotation_degrees, float intensity, gt_error *e);

void environment_map_free(environment_map *env);

static inline int environment_map_is_constant(const environment_map *env) { return env->width == 0; }

/* ---- Directions, texels and radiance ----------------------------------- */

/* (u, v) of a unit direction in the map's frame, and back (above). */
void environment_direction_to_uv(vec3 w, float *u, float *v);
vec3 environment_uv_to_direction(float u, float v);

/* World <-> map frame under the rotation. */
vec3 environment_world_to_map(const environment_map *env, vec3 world);
vec3 environment_map_to_world(const environment_map *env, vec3 map);

/* The texel (row-major index y W + x) holding a unit direction in the
 * map's frame. Not for a constant environment. */
int environment_texel_of(const environment_map *env, vec3 map_direction);

/* Omega_r, the solid angle of each texel of row r. */
double environment_row_solid_angle(int row, int width, int height);

/* The radiance arriving from unit world direction w, intensity included. */
void environment_map_radiance(const environment_map *env, vec3 w, float rgb[3]);

#endif
