/* The multi-bounce reference of the height-field world; see
 * heightfield_multibounce_integrator.h. */
#include "multibounce/heightfield_multibounce_integrator.h"

/* multibounce_world over the height field: each ray marched on its own. */
static void heightfield_trace(const void *data, struct RTCRayHit *rays, int n, int last, unsigned parts,
                              unsigned char *escaped, surface_hit *hits)
{
    (void)parts; /* a G-buffer hit holds every part */
    const heightfield_settings *hs = data;
    for (int r = 0; r < n; ++r) {
        const struct RTCRay *ray = &rays[r].ray;
        vec3 o = v3(ray->org_x, ray->org_y, ray->org_z), d = v3(ray->dir_x, ray->dir_y, ray->dir_z);
        escaped[r] = !heightfield_first_hit(hs, o, d, last ? NULL : &hits[r]);
    }
}

integrator heightfield_multibounce_integrator(const embree_scene *es, const heightfield_settings *hs,
                                              multibounce_plan *plan)
{
    plan->world = (multibounce_world){heightfield_trace, hs};
    integrator it = multibounce_integrator(es, plan);
    it.label = "heightfield-multibounce";
    return it;
}
