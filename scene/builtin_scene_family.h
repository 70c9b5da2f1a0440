/* The procedural family of built-in scenes (issue 46): the content screen-
 * space techniques meet in games, in kinds, each member deterministic from
 * its seed. A member is named "KIND-SEED" (builtin:room-3, builtin:street-0):
 *
 *   room     an open-topped room (floor, three walls) with furniture-like
 *            clutter: tables and chairs on legs, shelves, crates;
 *   railing  a balcony: a floor slab against a wall, a railing of thin bars
 *            and a handrail, a bench;
 *   street   a street between two rows of buildings of varied heights and
 *            setbacks, kerbs, bins and bollards;
 *   props    small props on a floor by a wall: crates, stacks, steps,
 *            turned boxes, a low platform;
 *   foliage  ground with clusters of thin vertical cards (grass and bush
 *            "cards", crossed pairs) and trunks;
 *   edges    concave and convex edges: stairs, an L-shaped wall, a trench,
 *            ridges and a plinth;
 *   terrain  metre-scale rolling ground (a flat-shaded height grid) with
 *            rocks (turned boxes half sunk).
 *
 * Every surface is white (albedo 0.8, roughness 0.5), as the studies'
 * built-in scenes; every camera looks at the content from outside and above
 * it (never inside geometry: its position is above every surface the kind
 * can build). The same name builds the same scene, hence the same .glb
 * bytes (`gtlab scene write`), on any machine: the layout comes from a
 * 32-bit PCG hash of the seed (scene/quad_mesh.h), the coordinates from
 * float arithmetic in a fixed order. */
#ifndef GTLAB_SCENE_BUILTIN_SCENE_FAMILY_H
#define GTLAB_SCENE_BUILTIN_SCENE_FAMILY_H

#include <stdint.h>
#include <stdio.h>

#include "scene/scene.h"

enum { FAMILY_KINDS = 7, FAMILY_MAX_SEED = 9999 };

/* The kind's name ("room", ...), kind in [0, FAMILY_KINDS). */
const char *family_kind_name(int kind);

/* Whether name is a member ("KIND-SEED", SEED a decimal in [0, FAMILY_MAX_SEED]
 * without leading zeros): 1 with kind and seed set, else 0. */
int family_member_parse(const char *name, int *kind, uint32_t *seed);

/* The i-th member of the family's scene set, kinds in turn (room-0,
 * railing-0, ..., terrain-0, room-1, ...), into name. */
void family_member_name(int index, char *name, size_t size);

/* Builds the member (its camera included). 0, or -1 out of memory. */
int family_member_build(int kind, uint32_t seed, scene *s);

/* `gtlab scene list`'s paragraph on the family. */
void family_describe(FILE *f);

#endif
