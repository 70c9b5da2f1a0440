#include "raytracer/ao_integrator.h"

#include "core/frame.h"
#include "core/hemisphere_sampling.h"

enum { AO_V, AO_VUNIFORM, BENT_X, BENT_Y, BENT_Z, AO_QUANTITY_COUNT };

/* All AO estimates lie in [-1, 1]: scale exponent 0. */
static const mc_quantity ao_quantities[AO_QUANTITY_COUNT] = {
    {"ao.V", 0}, {"ao.Vuniform", 0}, {"bent.X", 0}, {"bent.Y", 0}, {"bent.Z", 0}};

/* V(w) seen from the surface: 0 below the geometric surface, else the ray. */
static int visible(const embree_scene *es, const surface_hit *s, vec3 origin, vec3 w, float max_distance)
{
    if (v3_dot(w, s->ng) <= 0.0f)
        return 0;
    return embree_unoccluded(es, origin, w, max_distance);
}

static int ao_sample(const integrator *self, const sample_point *sp, float *values)
{
    const ao_settings *settings = self->settings;
    const surface_hit *s = sp->surface;
    frame f = frame_from_normal(s->ns);
    vec3 origin = offset_ray_origin(s->p, s->ng);
    float u[2];

    sample_point_2d(sp, 0, u);
    vec3 w_cos = frame_to_world(&f, sample_cosine_hemisphere(u));
    float v_cos = (float)visible(self->scene, s, origin, w_cos, settings->max_distance);

    sample_point_2d(sp, 1, u);
    vec3 w_uni = frame_to_world(&f, sample_uniform_hemisphere(u));
    float v_uni = (float)visible(self->scene, s, origin, w_uni, settings->max_distance);

    values[AO_V] = v_cos;
    values[AO_VUNIFORM] = v_uni;
    values[BENT_X] = v_cos * w_cos.x;
    values[BENT_Y] = v_cos * w_cos.y;
    values[BENT_Z] = v_cos * w_cos.z;
    return 2;
}

integrator ao_integrator(const embree_scene *es, const ao_settings *settings)
{
    integrator it = {"ao", AO_QUANTITY_COUNT, ao_quantities, "bent", ao_sample, es, settings};
    return it;
}
