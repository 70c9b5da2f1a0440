/* Orthonormal frames around a unit vector, for turning local hemisphere
 * samples (z up) into world directions.
 * Construction: Duff et al. 2017, "Building an Orthonormal Basis, Revisited"
 * (JCGT 6(1)), Listing 3 — branch-free, continuous except at n.z = -1 sign flip. */
#ifndef GTLAB_CORE_FRAME_H
#define GTLAB_CORE_FRAME_H

#include "core/vec3.h"

typedef struct { vec3 t, b, n; } frame;

static inline frame frame_from_normal(vec3 n)
{
    float sign = copysignf(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    frame f;
    f.t = v3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.b = v3(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

static inline vec3 frame_to_world(const frame *f, vec3 local)
{
    return v3_add(v3_add(v3_scale(f->t, local.x), v3_scale(f->b, local.y)), v3_scale(f->n, local.z));
}

static inline vec3 frame_to_local(const frame *f, vec3 world)
{
    return v3(v3_dot(world, f->t), v3_dot(world, f->b), v3_dot(world, f->n));
}

#endif
