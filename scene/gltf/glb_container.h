/* The GLB container of binary glTF (glTF 2.0, "GLB File Format
 * Specification"), split before any parser sees it: a 12-byte header
 * (magic "glTF", version 2, total length), a JSON chunk, and an optional
 * BIN chunk, each chunk an 8-byte header (length, type) and its data. Every
 * length is checked against the bytes actually there, in 64-bit arithmetic,
 * so the chunks returned lie inside the file. tinygltf's own GLB reader
 * (2.7.0) lets a BIN chunk run 8 bytes past the file; files it would read
 * that way are refused here. */
#ifndef GTLAB_SCENE_GLTF_GLB_CONTAINER_H
#define GTLAB_SCENE_GLTF_GLB_CONTAINER_H

#include <stddef.h>

#include "core/error.h"

typedef struct {
    const unsigned char *json, *bin; /* bin: NULL when the file has no BIN chunk */
    size_t json_length, bin_length;
} glb_chunks;

/* Whether the bytes start with the GLB magic "glTF". */
int glb_has_magic(const unsigned char *bytes, size_t size);

/* Splits bytes[0, size) into its chunks. Returns 0, or -1 with
 * e = "<what>: <problem>" ("GLB header gives a length of 900 bytes but the
 * file has 300 (truncated?)"). */
int glb_split(const unsigned char *bytes, size_t size, const char *what, glb_chunks *out, gt_error *e);

/* The GLB file of the chunks (JSON padded with spaces, BIN with zeros, to 4
 * bytes): malloc'd, its size in *out_size; NULL when out of memory or 4 GiB
 * or more. */
unsigned char *glb_join(const glb_chunks *chunks, size_t *out_size);

#endif
