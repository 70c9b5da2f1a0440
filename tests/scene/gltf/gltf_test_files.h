/* Helpers the glTF tests share: crafting .gltf text and .glb bytes by hand
 * (so that the loader is checked against files written independently of the
 * writer), and loading a file while capturing what the library prints. */
#ifndef GTLAB_TESTS_GLTF_TEST_FILES_H
#define GTLAB_TESTS_GLTF_TEST_FILES_H

#include <stddef.h>

#include "scene/scene.h"

/* "<GTLAB_TEST_TMP>/<name>" in a static buffer (valid until the next call). */
const char *tmp_path(const char *name);
/* Writes bytes to a file; returns 0 or -1. */
int write_bytes(const char *path, const void *data, size_t size);
/* RFC 4648 base64 (malloc'd, NUL-terminated). */
char *base64_encode(const void *data, size_t size);
/* "data:application/octet-stream;base64,..." of the bytes (malloc'd). */
char *data_uri(const void *data, size_t size);
/* A binary glTF: 12-byte header, JSON chunk (space-padded) and, if bin_size > 0,
 * a BIN chunk (zero-padded), as the GLB format of glTF 2.0 lays it out. malloc'd. */
unsigned char *glb_bytes(const char *json, const void *bin, size_t bin_size, size_t *out_size);

/* gltf_load with stderr captured into `printed` (NUL-terminated, truncated to
 * printed_size). Returns gltf_load's result. */
int load_capturing(const char *path, scene *s, gt_error *e, char *printed, size_t printed_size);
/* 1 when every line printed is a gt_warn line ("gtlab: warning: ..."). */
int only_warnings(const char *printed);

#endif
