/* A scene's identity by content: SHA-256 (OpenSSL) of everything a reference
 * sees of it, after loading, in world space: every mesh's counts, positions,
 * normals, texture coordinates, indices, material and flat flag, every
 * material and texture. The same file under two paths has one hash; two
 * different files of one name have two. References record it
 * (gtlab.scene_hash), and `gtlab merge` compares it instead of the path. */
#ifndef GTLAB_SCENE_SCENE_HASH_H
#define GTLAB_SCENE_SCENE_HASH_H

#include "scene/scene.h"

#define SCENE_HASH_HEX 65 /* 64 hex digits and the NUL */

/* Writes the hash as lowercase hex; returns 0, or -1 if OpenSSL failed. */
int scene_content_hash(const scene *s, char hex[SCENE_HASH_HEX]);

#endif
