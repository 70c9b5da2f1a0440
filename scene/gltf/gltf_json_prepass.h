/* Rewrites the parts of a glTF JSON document that tinygltf (2.7) cannot
 * parse although the glTF extensions gtlab decodes make them valid, before
 * tinygltf sees it (the C++ adapter is gltf_json_prepass.cpp):
 *  - an EXT_meshopt_compression fallback buffer ("fallback": true) need not
 *    have a uri or any bytes: tinygltf would look for them (in the GLB's BIN
 *    chunk, or a missing file). It becomes a 4-byte data: buffer; the
 *    bufferViews into it are then decoded from their compressed source.
 *  - a KHR_draco_mesh_compression primitive's indices accessor has no
 *    bufferView (the indices are in the Draco data): tinygltf refuses it.
 *    The primitive's "indices" is dropped; the Draco data provides them.
 * The text has passed the JSON gate (core/files/json_check.h). */
#ifndef GTLAB_SCENE_GLTF_GLTF_JSON_PREPASS_H
#define GTLAB_SCENE_GLTF_GLTF_JSON_PREPASS_H

#include <stddef.h>

/* Returns 1 and *out (malloc'd, *out_length bytes, not NUL-terminated) when
 * the document needed a rewrite, 0 when it is fine as it is, -1 when out of
 * memory. */
int gltf_json_prepass(const unsigned char *json, size_t length, char **out, size_t *out_length);

#endif
