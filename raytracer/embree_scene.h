/* The scene as Embree sees it: one triangle geometry per scene mesh in one
 * RTCScene (robust build, so rays cannot slip through shared edges), plus the
 * ray queries every integrator shares: closest hit with its surface frame,
 * and occlusion along a ray leaving a surface without self-intersection. */
#ifndef GTLAB_RAYTRACER_EMBREE_SCENE_H
#define GTLAB_RAYTRACER_EMBREE_SCENE_H

#include <embree3/rtcore.h>

#include "core/error.h"
#include "core/vec3.h"
#include "scene/scene.h"

typedef struct {
    RTCDevice device;
    RTCScene rtc;
    const scene *source;
} embree_scene;

/* A surface point seen along a ray. Both normals face the side the ray came
 * from (surfaces are two-sided, DESIGN.md); the shading normal is flipped to
 * the geometric normal's side. */
typedef struct {
    vec3 p;         /* interpolated from the triangle's vertices (not o + t d) */
    vec3 ng;        /* geometric normal, unit */
    vec3 ns;        /* shading normal, unit */
    float t;        /* ray distance */
    float uv[2];    /* TEXCOORD_0, or 0 */
    int mesh, triangle;
} surface_hit;

int embree_scene_build(const scene *s, embree_scene *es, gt_error *e);
void embree_scene_release(embree_scene *es);

/* Closest hit along o + t d, t in (0, t_max]. Returns 1 and fills hit, or 0. */
int embree_closest_hit(const embree_scene *es, vec3 o, vec3 d, float t_max, surface_hit *hit);

/* The parts of a surface_hit a caller may skip: embree_surface_at always
 * fills p, ng, t, mesh and triangle, and ns and uv only when asked (else ns
 * is ng and uv is 0). What it fills has the same bits as embree_closest_hit's. */
enum { SURFACE_SHADING_NORMAL = 1u, SURFACE_TEXCOORDS = 2u, SURFACE_ALL = 3u };

/* The surface of a hit that Embree found (rh->hit.geomID valid). */
void embree_surface_at(const embree_scene *es, const struct RTCRayHit *rh, unsigned parts, surface_hit *hit);

/* Closest hits of a stream of incoherent rays, in one Embree call
 * (rtcIntersect1M): afterwards rays[i].hit.geomID is RTC_INVALID_GEOMETRY_ID
 * where ray i found nothing. The rays' hit fields need no initialisation. */
void embree_closest_hit_stream(const embree_scene *es, struct RTCRayHit *rays, unsigned count);

/* The origin for rays leaving surface point p on the side of ng (unit, facing
 * the outgoing side): p pushed along ng by a distance proportional to p's
 * magnitude, above the rounding error of p, so no ray restarts below the
 * surface it leaves. */
vec3 offset_ray_origin(vec3 p, vec3 ng);

/* A ray o + t d, t in [0, t_max], in Embree's layout. Inline: the AO loop
 * fills 128 of these per batch. */
static inline void embree_ray_init(struct RTCRay *r, vec3 o, vec3 d, float t_max)
{
    r->org_x = o.x, r->org_y = o.y, r->org_z = o.z;
    r->dir_x = d.x, r->dir_y = d.y, r->dir_z = d.z;
    r->tnear = 0.0f;
    r->tfar = t_max;
    r->time = 0.0f;
    r->mask = 0xffffffffu;
    r->id = 0;
    r->flags = 0;
}

/* Visibility of a stream of incoherent rays, in one Embree call
 * (rtcOccluded1M): afterwards rays[i].tfar < 0 where ray i was blocked,
 * i.e. something lies within (tnear, tfar]. */
void embree_unoccluded_stream(const embree_scene *es, struct RTCRay *rays, unsigned count);

#endif
