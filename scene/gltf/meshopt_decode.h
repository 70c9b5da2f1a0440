/* EXT_meshopt_compression (glTF extension; meshoptimizer's codecs, libmeshoptimizer):
 * a bufferView whose bytes are `count` elements of `byteStride` bytes,
 * stored compressed in another buffer range and decoded by mode:
 *   "ATTRIBUTES"  meshopt_decodeVertexBuffer; byteStride a multiple of 4, at most 256
 *   "TRIANGLES"   meshopt_decodeIndexBuffer;  byteStride 2 or 4, count a multiple of 3
 *   "INDICES"     meshopt_decodeIndexSequence; byteStride 2 or 4
 * then, for attributes, a filter applied in place:
 *   "NONE", "OCTAHEDRAL" (byteStride 4 or 8: unit vectors), "QUATERNION"
 *   (byteStride 8), "EXPONENTIAL" (byteStride a multiple of 4: 2^e * m floats).
 * The decoders are safe on untrusted bytes (they fail or produce garbage
 * values, which the glTF reader then checks like any other data). */
#ifndef GTLAB_SCENE_GLTF_MESHOPT_DECODE_H
#define GTLAB_SCENE_GLTF_MESHOPT_DECODE_H

#include <stddef.h>

#include "core/error.h"

typedef struct {
    size_t count, stride; /* elements and bytes per element of the decoded view */
    const char *mode;     /* "ATTRIBUTES", "TRIANGLES" or "INDICES" */
    const char *filter;   /* "NONE", "OCTAHEDRAL", "QUATERNION" or "EXPONENTIAL" */
} meshopt_view;

/* Checks v's mode, filter, stride and count against each other. Returns 0,
 * or -1 with e = "<what>: <problem>". */
int meshopt_check_view(const meshopt_view *v, const char *what, gt_error *e);

/* Decodes src[0, src_size) into dst (v->count * v->stride bytes) per a
 * checked view. Returns 0, or -1 with e = "<what>: <problem>". */
int meshopt_decode_view(const meshopt_view *v, const unsigned char *src, size_t src_size, unsigned char *dst,
                        const char *what, gt_error *e);

#endif
