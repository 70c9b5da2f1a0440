/* The combination images' pixels (height_fog/aerial_perspective_study.h): the rays,
 * the reference along each, the LUT + HeightFog model, and the fog's
 * parameters from the atmosphere. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/vec3.h"
#include "height_fog/aerial_perspective_parts.h"

int aerial_rays_alloc(aerial_rays *rays, int width, int height)
{
    size_t n = (size_t)width * height;
    memset(rays, 0, sizeof *rays);
    rays->width = width, rays->height = height;
    rays->dir = calloc(3 * n, sizeof(float));
    rays->inside = calloc(n, sizeof(float)), rays->terrain = calloc(n, sizeof(float));
    rays->length = calloc(n, sizeof(float)), rays->surface_y = calloc(n, sizeof(float));
    if (rays->dir && rays->inside && rays->terrain && rays->length && rays->surface_y)
        return 0;
    aerial_rays_free(rays);
    return -1;
}

void aerial_rays_free(aerial_rays *rays)
{
    free(rays->dir), free(rays->inside), free(rays->terrain), free(rays->length), free(rays->surface_y);
    memset(rays, 0, sizeof *rays);
}

void aerial_fisheye_rays(aerial_rays *rays)
{
    int n = rays->width;
    rays->camera_y = 0.0;
    for (int j = 0; j < rays->height; ++j)
        for (int i = 0; i < n; ++i) {
            size_t k = (size_t)j * n + i;
            double u = 2.0 * (i + 0.5) / n - 1.0, v = 1.0 - 2.0 * (j + 0.5) / rays->height, rho = hypot(u, v);
            double theta = 0.5 * M_PI * rho, s = rho > 0.0 ? sin(theta) / rho : 0.5 * M_PI;
            rays->inside[k] = rho <= 1.0 ? 1.0f : 0.0f;
            rays->dir[3 * k] = (float)(s * u), rays->dir[3 * k + 1] = (float)cos(theta);
            rays->dir[3 * k + 2] = (float)(-s * v);
        }
}

int aerial_planes_alloc(aerial_planes *p, size_t n)
{
    memset(p, 0, sizeof *p);
    float *block = calloc((AERIAL_MODELS + 1) * 3 * n, sizeof(float));
    if (!block)
        return -1;
    for (int c = 0; c < 3; ++c) {
        p->reference[c] = block + c * n;
        for (int m = 0; m < AERIAL_MODELS; ++m)
            p->model[m][c] = block + ((m + 1) * 3 + c) * n;
    }
    return 0;
}

void aerial_planes_free(aerial_planes *p)
{
    free(p->reference[0]);
    memset(p, 0, sizeof *p);
}

/* ---- The fog's parameters from the atmosphere -------------------------- */

/* The green extinction column \int_0^y beta_t dy of blend t, and beta_t(0). */
static double green_column(const atmosphere_model *m, double t, double y, double *at_ground)
{
    double weight[2] = {1.0 - t, t}, column = 0.0;
    *at_ground = 0.0;
    for (int w = 0; w < ATMOSPHERE_WEATHERS; ++w) {
        const atmosphere_weather *x = &m->weathers[w];
        double hr = x->rayleigh_scale_height, hm = x->mie_scale_height;
        column += weight[w] * (x->rayleigh_scattering[1] * hr * -expm1(-y / hr) +
                               x->mie_extinction[1] * hm * -expm1(-y / hm));
        *at_ground += weight[w] * (x->rayleigh_scattering[1] + x->mie_extinction[1]);
    }
    return column;
}

double aerial_fog_scale_height(const atmosphere_model *m, double t, double camera_y)
{
    double y = fmax(camera_y, 1.0), beta, column = green_column(m, t, y, &beta);
    double lo = log(1.0), hi = log(1e7); /* beta H (1 - e^{-y/H}) grows with H */
    for (int k = 0; k < 80; ++k) {
        double mid = 0.5 * (lo + hi), H = exp(mid);
        if (beta * H * -expm1(-y / H) < column)
            lo = mid;
        else
            hi = mid;
    }
    return exp(0.5 * (lo + hi));
}

void aerial_fog_param(const atmosphere_luts *luts, double t, double camera_y, vec3 sun_dir, height_fog_param *p)
{
    const atmosphere_model *m = &luts->model;
    atmosphere_coefficients k = atmosphere_coefficients_at(m, t, 0.0);
    *p = height_fog_param_default();
    for (int c = 0; c < 3; ++c)
        p->beta_rs[c] = k.scattering[ATMOSPHERE_RAYLEIGH][c];
    p->beta_ms = k.scattering[ATMOSPHERE_MIE][1];
    p->beta_ma = fmax(0.0, k.extinction[1] - k.scattering[ATMOSPHERE_RAYLEIGH][1] - p->beta_ms);
    p->mie_g = m->mie_g;
    p->scale_height = aerial_fog_scale_height(m, t, camera_y);
    p->sun_direction = sun_dir;
    float theta_s = acosf(sun_dir.y), sun[3], sky[3];
    atmosphere_lut_light(luts, ATMOSPHERE_TABLE_SUN, theta_s, (float)camera_y, (float)t, sun);
    atmosphere_lut_light(luts, ATMOSPHERE_TABLE_SKY, theta_s, (float)camera_y, (float)t, sky);
    for (int c = 0; c < 3; ++c)
        p->sun_color[c] = sun[c], p->amb_color[c] = sky[c];
}

/* ---- The pixels -------------------------------------------------------- */

/* The reference along pixel k's ray: the whole ray, or up to the terrain. */
static double pixel_reference(const aerial_light *light, const aerial_rays *rays, const aerial_perspective_request *rq,
                              size_t k, double L[3])
{
    const atmosphere_model *m = &light->solution->model;
    const float *w = rays->dir + 3 * k;
    double r = m->bottom_radius + rays->camera_y, mu = w[1];
    double nu = w[0] * light->sun.x + w[1] * light->sun.y + w[2] * light->sun.z;
    double length = atmosphere_distance_to_boundary(m, r, mu);
    if (rays->terrain[k] > 0.5f)
        length = fmin(length, rays->length[k]);
    atmosphere_view_ray ray = {r, mu, light->sun.y, fmax(-1.0, fmin(1.0, nu)), length};
    return atmosphere_view_radiance(light->solution, rq->method, &ray, rq->tolerance, L, NULL, NULL);
}

/* The models at pixel k: the LUTs' background, or HeightFog on the terrain. */
static void pixel_model(const aerial_light *light, const height_fog_param *p, const aerial_rays *rays, size_t k,
                        float out[AERIAL_MODELS][3])
{
    const float *w = rays->dir + 3 * k;
    float nu = w[0] * light->sun.x + w[1] * light->sun.y + w[2] * light->sun.z, y = (float)rays->camera_y;
    if (rays->terrain[k] < 0.5f) {
        float theta_v = acosf(fmaxf(-1.0f, fminf(1.0f, w[1]))), theta_s = acosf(light->sun.y);
        atmosphere_lut_background(light->luts, theta_s, theta_v, y, (float)light->t, nu, out[0]);
        memcpy(out[1], out[0], sizeof out[0]);
        return;
    }
    float transmittance[3];
    height_fog_published(p, rays->length[k], y, rays->surface_y[k], nu, out[AERIAL_MODEL_PUBLISHED], transmittance);
    height_fog_corrected(p, HEIGHT_FOG_ATTENUATE_SKY, rays->length[k], y, rays->surface_y[k], nu,
                         out[AERIAL_MODEL_SKY_ATTENUATED], transmittance);
}

void aerial_render_models(const aerial_light *light, const aerial_rays *rays, int threads, aerial_planes *out)
{
    height_fog_param p;
    aerial_fog_param(light->luts, light->t, rays->camera_y, light->sun, &p);
    long n = (long)rays->width * rays->height;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long k = 0; k < n; ++k) {
        float model[AERIAL_MODELS][3];
        if (rays->inside[k] < 0.5f)
            continue;
        pixel_model(light, &p, rays, (size_t)k, model);
        for (int m = 0; m < AERIAL_MODELS; ++m)
            for (int c = 0; c < 3; ++c)
                out->model[m][c][k] = model[m][c];
    }
}

void aerial_render(const aerial_light *light, const aerial_rays *rays, const aerial_perspective_request *rq,
                   int threads, aerial_planes *out)
{
    long n = (long)rays->width * rays->height;
    double worst = 0.0;
#pragma omp parallel for schedule(dynamic, 8) num_threads(threads) reduction(max : worst)
    for (long k = 0; k < n; ++k) {
        double L[3];
        if (rays->inside[k] < 0.5f)
            continue;
        worst = fmax(worst, pixel_reference(light, rays, rq, (size_t)k, L));
        for (int c = 0; c < 3; ++c)
            out->reference[c][k] = (float)L[c];
    }
    out->reference_error = worst;
    aerial_render_models(light, rays, threads, out);
}
