/* The AO decal scenes (issue 17, item 1): INSIDE's occluders as real
 * geometry, so gtlab's cosine AO reference counts their union exactly and
 * the AO decals study (techniques/ao_decals/) can score each decal against
 * it. Four scenes, all outside the studies' scene list (scene/builtin_scenes.h):
 *   pill-on-plane     a stretched ellipsoid (the "pill" of the point decal) over the floor;
 *   box-on-plane      a crate standing on the floor;
 *   box-in-corner     a crate in builtin:corner's three walls;
 *   overlap-on-plane  two overlapping spheres, a box pierced by a third sphere, and a
 *                     fourth sphere sunk into the floor (partly below every floor point's horizon).
 * The same numbers build the meshes and describe the occluders to the
 * study (ao_decal_scene_find), so decals and geometry cannot drift apart.
 * Ellipsoids are latitude-longitude meshes (AO_DECAL_SCENE_RINGS rings of
 * AO_DECAL_SCENE_SEGMENTS quads, triangle fans at the poles) with every
 * vertex on the ellipsoid and the exact ellipsoid normal normalize((x - c) / r^2);
 * the inscribed mesh lies within 1 - cos(pi / 256) = 7.5e-5 of the radii. */
#ifndef GTLAB_SCENE_BUILTIN_SCENE_AO_DECALS_H
#define GTLAB_SCENE_BUILTIN_SCENE_AO_DECALS_H

#include "core/vec3.h"
#include "scene/scene.h"

enum { AO_DECAL_SCENE_RINGS = 128, AO_DECAL_SCENE_SEGMENTS = 256, AO_DECAL_SCENE_MAX_OCCLUDERS = 5 };

/* An axis-aligned ellipsoid (a sphere when the radii are equal) or box, by
 * its centre and its radii / half extents: the occluder's unit space is
 * (x - centre) / half per axis. */
typedef enum { AO_OCCLUDER_ELLIPSOID, AO_OCCLUDER_BOX } ao_occluder_kind;

typedef struct {
    ao_occluder_kind kind;
    vec3 centre, half;
} ao_occluder;

typedef struct {
    const char *name;   /* the built-in scene's name */
    int corner;         /* 1: receivers are builtin:corner's walls (x, y, z in [0, 10]); 0: the 100 x 100 floor */
    int occluder_count;
    ao_occluder occluders[AO_DECAL_SCENE_MAX_OCCLUDERS];
} ao_decal_scene;

int ao_decal_scene_count(void);
const ao_decal_scene *ao_decal_scene_at(int index);
const ao_decal_scene *ao_decal_scene_find(const char *name);

/* The builders builtin_scenes.c lists. 0, or -1 when out of memory. */
int builtin_scene_build_pill_on_plane(scene *s);
int builtin_scene_build_box_on_plane(scene *s);
int builtin_scene_build_box_in_corner(scene *s);
int builtin_scene_build_overlap_on_plane(scene *s);

#endif
