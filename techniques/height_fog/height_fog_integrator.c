/* The height-fog reference over the G-buffer; see height_fog_integrator.h. */
#include "height_fog/height_fog_integrator.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/reference_schema.h"

static const char *const scattering_names[] = {"quadrature", "single", "multiple"};

const char *height_fog_scattering_name(height_fog_scattering_mode s)
{
    return s >= HEIGHT_FOG_QUADRATURE && s <= HEIGHT_FOG_MULTIPLE ? scattering_names[s] : "unknown";
}

int height_fog_scattering_parse(const char *name, height_fog_scattering_mode *s)
{
    for (int i = 0; i < 3; ++i)
        if (strcmp(name, scattering_names[i]) == 0) {
            *s = (height_fog_scattering_mode)i;
            return 0;
        }
    return -1;
}

/* Names and scales: samples of L stay below a few times the unattenuated
 * single scattering J / beta_t (multiple scattering adds at most the sky
 * and sun again); T <= 1. */
static void name_quantities(height_fog_plan *plan)
{
    static const char *const names[HEIGHT_FOG_QUANTITIES] = {CH_FOG_L_R, CH_FOG_L_G, CH_FOG_L_B, CH_FOG_T_R, CH_FOG_T_G,
                                                      CH_FOG_T_B, CH_FOG_L_ERROR_R, CH_FOG_L_ERROR_G,
                                                      CH_FOG_L_ERROR_B};
    const height_fog_param *p = &plan->medium;
    double bound = 1.0;
    for (int c = 0; c < 3; ++c)
        bound = fmax(bound, p->sun_color[c] * (3.0 / (8.0 * M_PI) + 1.0 / (1.0 - fabs(p->mie_g)) / (1.0 - fabs(p->mie_g)))
                                + p->amb_color[c]);
    plan->quantity_count = plan->scattering == HEIGHT_FOG_QUADRATURE ? 9 : 6;
    for (int q = 0; q < plan->quantity_count; ++q) {
        snprintf(plan->quantities[q].name, sizeof plan->quantities[q].name, "%s", names[q]);
        plan->quantities[q].scale_exponent = q < 3 ? (int)ceil(log2(4.0 * bound)) : 0;
    }
}

int height_fog_plan_init(height_fog_plan *plan, const height_fog_settings *settings, const embree_scene *es, const camera_view *view,
                  gt_error *e)
{
    memset(plan, 0, sizeof *plan);
    if (height_fog_weather(settings->weather, settings->sun_elevation_deg, &plan->medium) != 0)
        return gt_error_set(e, "fog", "unknown weather '%s' (sunny or dense)", settings->weather);
    if (!(fabs(settings->sun_elevation_deg) <= 90.0))
        return gt_error_set(e, "fog", "the sun's elevation must be in [-90, 90] degrees");
    if (height_fog_param_validate(&plan->medium, "fog", e) != 0)
        return -1;
    if (settings->scattering == HEIGHT_FOG_MULTIPLE && settings->max_scatterings < 1)
        return gt_error_set(e, "fog", "the most scatterings per path must be >= 1");
    plan->scattering = settings->scattering;
    plan->view = *view;
    plan->path.lighting.medium = &plan->medium;
    plan->path.lighting.sun_extinction = !settings->no_sun_extinction;
    plan->path.lighting.occluders = settings->no_shadows ? NULL : es;
    plan->path.max_scatterings = settings->scattering == HEIGHT_FOG_MULTIPLE ? settings->max_scatterings : 1;
    name_quantities(plan);
    return 0;
}

/* The transmittance and, by quadrature, L and its error estimate. */
static int quadrature_values(const height_fog_plan *plan, vec3 dir, double distance, height_fog_ray_estimate *q)
{
    if (plan->scattering == HEIGHT_FOG_QUADRATURE) {
        /* Relative to the unattenuated bound: far below the studies' noise floors. */
        height_fog_single_scatter(&plan->path.lighting, plan->view.origin, dir, distance, 1e-6, q);
        return (int)q->rays;
    }
    double beta_t[3];
    height_fog_extinction(&plan->medium, beta_t);
    double d_int = height_fog_ray_density(&plan->medium, plan->view.origin.y, dir.y, distance);
    for (int c = 0; c < 3; ++c)
        q->transmittance[c] = beta_t[c] > 0.0 ? exp(-beta_t[c] * d_int) : 1.0;
    return 0;
}

/* The ray of a pixel: towards its surface, or, for a background pixel,
 * its primary ray out to infinity. */
static void pixel_ray(const height_fog_plan *plan, const pixel_context *px, vec3 *dir, double *distance)
{
    if (isinf(px->surface->t)) {
        vec3 origin;
        int x = px->pixel % plan->view.width, y = px->pixel / plan->view.width;
        camera_ray(&plan->view, (float)x + 0.5f, (float)y + 0.5f, &origin, dir);
        *distance = INFINITY;
        return;
    }
    vec3 to_surface = v3_sub(px->surface->p, plan->view.origin);
    *distance = v3_length(to_surface);
    *dir = v3_scale(to_surface, (float)(1.0 / *distance));
}

static int height_fog_sample_batch(const integrator *self, const pixel_context *px, uint32_t first_index, int count,
                            float *values)
{
    const height_fog_plan *plan = self->settings;
    vec3 dir;
    double distance;
    pixel_ray(plan, px, &dir, &distance);
    height_fog_ray_estimate q;
    int rays = quadrature_values(plan, dir, distance, &q);
    for (int k = 0; k < count; ++k) {
        double l[3] = {q.inscatter[0], q.inscatter[1], q.inscatter[2]};
        uint32_t index = first_index + (uint32_t)k;
        if (plan->scattering != HEIGHT_FOG_QUADRATURE)
            rays += height_fog_path_sample(&plan->path, plan->view.origin, dir, distance, px->half_seed[index & 1u], index, l);
        for (int c = 0; c < 3; ++c) {
            values[c * SAMPLE_BATCH + k] = (float)l[c];
            values[(3 + c) * SAMPLE_BATCH + k] = (float)q.transmittance[c];
            if (plan->scattering == HEIGHT_FOG_QUADRATURE)
                values[(6 + c) * SAMPLE_BATCH + k] = (float)q.error[c];
        }
    }
    return rays;
}

integrator height_fog_integrator(const embree_scene *es, const height_fog_plan *plan)
{
    integrator it = {"fog", plan->quantity_count, plan->quantities, NULL, height_fog_sample_batch, es, plan, 1};
    return it;
}
