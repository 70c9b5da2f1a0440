#include "core/optics/environment_map.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/image_io.h"
#include "core/optics/sky_environment.h"

/* ---- Texel geometry ------------------------------------------------------ */

double environment_row_solid_angle(int row, int width, int height)
{
    double top = M_PI * row / height, bottom = M_PI * (row + 1) / height;
    return 2.0 * M_PI / width * (cos(top) - cos(bottom));
}

void environment_direction_to_uv(vec3 w, float *u, float *v)
{
    *u = 0.5f + atan2f(w.z, w.x) * (float)(0.5 / M_PI);
    *v = acosf(fminf(fmaxf(w.y, -1.0f), 1.0f)) * (float)(1.0 / M_PI);
}

vec3 environment_uv_to_direction(float u, float v)
{
    float phi = (float)(2.0 * M_PI) * (u - 0.5f), theta = (float)M_PI * v;
    float sin_theta = sinf(theta);
    return v3(sin_theta * cosf(phi), cosf(theta), sin_theta * sinf(phi));
}

/* world = R_y(a) map: x' = x cos a + z sin a, z' = -x sin a + z cos a. */
vec3 environment_map_to_world(const environment_map *env, vec3 m)
{
    float c = env->rotation_cos, s = env->rotation_sin;
    return v3(m.x * c + m.z * s, m.y, -m.x * s + m.z * c);
}

vec3 environment_world_to_map(const environment_map *env, vec3 w)
{
    float c = env->rotation_cos, s = env->rotation_sin;
    return v3(w.x * c - w.z * s, w.y, w.x * s + w.z * c);
}

static int clamp_index(float t, int n)
{
    int i = (int)t;
    return i < 0 ? 0 : (i >= n ? n - 1 : i);
}

int environment_texel_of(const environment_map *env, vec3 m)
{
    float u, v;
    environment_direction_to_uv(m, &u, &v);
    return clamp_index(v * (float)env->height, env->height) * env->width + clamp_index(u * (float)env->width, env->width);
}

void environment_map_radiance(const environment_map *env, vec3 w, float rgb[3])
{
    const float *texel = env->constant;
    if (!environment_map_is_constant(env))
        texel = env->rgb + 3 * (size_t)environment_texel_of(env, environment_world_to_map(env, w));
    for (int c = 0; c < 3; ++c)
        rgb[c] = texel[c] * env->intensity;
}

/* ---- Construction -------------------------------------------------------- */

static void set_name(environment_map *env, const char *name)
{
    snprintf(env->name, sizeof env->name, "%s", name);
    env->intensity = 1.0f;
    env->rotation_cos = 1.0f;
}

/* The first value (3 pixel + channel) that is not finite or is below
 * `floor`, or -1. */
static long first_bad_value(const float *rgb, size_t count, double floor)
{
    for (size_t i = 0; i < 3 * count; ++i)
        if (!(isfinite(rgb[i]) && rgb[i] >= floor))
            return (long)i;
    return -1;
}

/* The mean luminance of the finite texels. */
static double mean_luminance(const float *rgb, size_t count)
{
    double sum = 0.0;
    for (size_t i = 0; i < count; ++i) {
        double l = environment_luminance(rgb + 3 * i);
        sum += isfinite(l) ? l : 0.0;
    }
    return sum / (double)count;
}

/* Refuses a size that is not 2:1 and any value that is not finite or is
 * below -ENVIRONMENT_RINGING times the mean luminance; the small negative
 * values above that (lossy compression's ringing) become 0. Returns the
 * number of values so clamped, or -1 with e. */
static long check_texels(const char *name, int width, int height, float *rgb, gt_error *e)
{
    if (width < 2 || height < 1 || width != 2 * height)
        return gt_error_set(e, name, "an equirectangular environment must be 2:1, not %d x %d", width, height);
    size_t count = (size_t)width * (size_t)height;
    double floor = -ENVIRONMENT_RINGING * mean_luminance(rgb, count);
    long bad = first_bad_value(rgb, count, floor);
    if (bad >= 0)
        return gt_error_set(e, name,
                            "pixel (%ld, %ld) channel %c is %g: radiance must be finite and non-negative "
                            "(down to %g, %g times the mean luminance, is read as 0)",
                            bad / 3 % width, bad / 3 / width, "RGB"[bad % 3], (double)rgb[bad], floor,
                            ENVIRONMENT_RINGING);
    long clamped = 0;
    for (size_t i = 0; i < 3 * count; ++i)
        if (rgb[i] < 0.0f)
            rgb[i] = 0.0f, ++clamped;
    return clamped;
}

/* Takes ownership of rgb (freed on error) and tabulates the row solid angles. */
static int adopt_texels(environment_map *env, const char *name, int width, int height, float *rgb, gt_error *e)
{
    memset(env, 0, sizeof *env);
    long clamped = check_texels(name, width, height, rgb, e);
    if (clamped < 0) {
        free(rgb);
        return -1;
    }
    env->row_solid_angle = malloc(sizeof(double) * (size_t)height);
    if (!env->row_solid_angle) {
        free(rgb);
        return gt_error_set(e, name, "out of memory");
    }
    for (int r = 0; r < height; ++r)
        env->row_solid_angle[r] = environment_row_solid_angle(r, width, height);
    set_name(env, name);
    env->width = width, env->height = height, env->rgb = rgb;
    env->clamped_values = clamped;
    return 0;
}

int environment_map_load(environment_map *env, const char *path, gt_error *e)
{
    int width = 0, height = 0;
    float *rgb = NULL;
    int floating_point = 0;
    memset(env, 0, sizeof *env);
    if (image_read_rgb_float(path, &width, &height, &rgb, &floating_point, e) != 0)
        return -1;
    if (!floating_point) { /* issue 41: an 8-bit JPEG was taken as radiance */
        free(rgb);
        return gt_error_set(e, path, "stores integer (8- or 16-bit, display-referred) texels, not radiance: an "
                                     "environment must be an HDR image with floating-point texels (OpenEXR, Radiance "
                                     ".hdr)");
    }
    return adopt_texels(env, path, width, height, rgb, e);
}

int environment_map_from_pixels(environment_map *env, const char *name, int width, int height, const float *rgb,
                                gt_error *e)
{
    memset(env, 0, sizeof *env);
    size_t bytes = sizeof(float) * 3 * (size_t)(width > 0 ? width : 0) * (size_t)(height > 0 ? height : 0);
    float *copy = malloc(bytes ? bytes : 1);
    if (!copy)
        return gt_error_set(e, name, "out of memory");
    if (bytes)
        memcpy(copy, rgb, bytes);
    return adopt_texels(env, name, width, height, copy, e);
}

int environment_map_constant(environment_map *env, const char *name, const float rgb[3], gt_error *e)
{
    memset(env, 0, sizeof *env);
    if (first_bad_value(rgb, 1, 0.0) >= 0)
        return gt_error_set(e, name, "a constant environment's radiance must be finite and non-negative");
    set_name(env, name);
    memcpy(env->constant, rgb, sizeof env->constant);
    return 0;
}

/* The mean of radiance over texel (x, y): s x s points at the centres of
 * equal strata of phi and cos theta. */
static void texel_mean(int x, int y, int width, int height, int s, environment_radiance_fn radiance, void *ctx,
                       float out[3])
{
    double sum[3] = {0.0, 0.0, 0.0};
    double cos_top = cos(M_PI * y / height), cos_bottom = cos(M_PI * (y + 1) / height);
    for (int j = 0; j < s; ++j) {
        double cos_theta = cos_top + (cos_bottom - cos_top) * (j + 0.5) / s;
        double sin_theta = sqrt(fmax(0.0, 1.0 - cos_theta * cos_theta));
        for (int i = 0; i < s; ++i) {
            double phi = 2.0 * M_PI * ((x + (i + 0.5) / s) / width - 0.5);
            float rgb[3];
            radiance(v3((float)(sin_theta * cos(phi)), (float)cos_theta, (float)(sin_theta * sin(phi))), ctx, rgb);
            for (int c = 0; c < 3; ++c)
                sum[c] += rgb[c];
        }
    }
    for (int c = 0; c < 3; ++c)
        out[c] = (float)(sum[c] / ((double)s * s));
}

int environment_map_procedural(environment_map *env, const char *name, int width, int height, int s,
                               environment_radiance_fn radiance, void *ctx, gt_error *e)
{
    memset(env, 0, sizeof *env);
    if (width < 2 || width != 2 * height || s < 1)
        return gt_error_set(e, name, "a procedural environment needs a 2:1 size and s >= 1, not %d x %d, s = %d",
                            width, height, s);
    float *rgb = malloc(sizeof(float) * 3 * (size_t)width * (size_t)height);
    if (!rgb)
        return gt_error_set(e, name, "out of memory");
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            texel_mean(x, y, width, height, s, radiance, ctx, rgb + 3 * ((size_t)y * width + x));
    return adopt_texels(env, name, width, height, rgb, e);
}

static void sky_texel(vec3 w, void *ctx, float rgb[3])
{
    (void)ctx;
    rgb[0] = rgb[1] = rgb[2] = (float)sky_radiance(w);
}

int environment_map_sky(environment_map *env, gt_error *e)
{
    return environment_map_procedural(env, "sky", 1024, 512, 4, sky_texel, NULL, e);
}

environment_sun environment_sun_default(void)
{
    const double elevation = 30.0 * M_PI / 180.0, azimuth = 35.0 * M_PI / 180.0;
    environment_sun sun;
    sun.direction = v3((float)(cos(elevation) * sin(azimuth)), (float)sin(elevation),
                       (float)(cos(elevation) * cos(azimuth)));
    sun.radius = 0.5 * M_PI / 180.0;
    sun.radiance = M_PI / (2.0 * M_PI * (1.0 - cos(sun.radius)));
    sun.sky = 0.1;
    return sun;
}

static void sun_texel(vec3 w, void *ctx, float rgb[3])
{
    const environment_sun *sun = ctx;
    double inside = v3_dot(w, sun->direction) >= cos(sun->radius);
    rgb[0] = rgb[1] = rgb[2] = (float)(inside ? sun->radiance : sun->sky);
}

int environment_map_sun(environment_map *env, const environment_sun *sun, gt_error *e)
{
    memset(env, 0, sizeof *env);
    if (!(sun->radius > 0.0 && sun->radius < M_PI / 2 && sun->radiance >= 0.0 && sun->sky >= 0.0 &&
          isfinite(sun->radiance) && isfinite(sun->sky) && fabsf(v3_length(sun->direction) - 1.0f) < 1e-4f))
        return gt_error_set(e, "sun", "needs a unit direction, a radius in (0, 90) degrees and finite radiances >= 0");
    environment_sun copy = *sun;
    return environment_map_procedural(env, "sun", 1024, 512, 8, sun_texel, &copy, e);
}

int environment_map_transform(environment_map *env, float rotation_degrees, float intensity, gt_error *e)
{
    if (!isfinite(rotation_degrees))
        return gt_error_set(e, env->name, "rotation %g is not a finite angle", (double)rotation_degrees);
    if (!(isfinite(intensity) && intensity >= 0.0f))
        return gt_error_set(e, env->name, "intensity %g is not finite and >= 0", (double)intensity);
    double a = fmod((double)rotation_degrees, 360.0) * M_PI / 180.0;
    env->rotation_degrees = rotation_degrees;
    env->rotation_cos = rotation_degrees == 0.0f ? 1.0f : (float)cos(a);
    env->rotation_sin = rotation_degrees == 0.0f ? 0.0f : (float)sin(a);
    env->intensity = intensity;
    return 0;
}

void environment_map_free(environment_map *env)
{
    free(env->rgb);
    free(env->row_solid_angle);
    memset(env, 0, sizeof *env);
}
