/* The numbers an accessor's components stand for (glTF 2.0, "Accessor Data
 * Types"; KHR_mesh_quantization). A component is read from its little-endian
 * bytes; a normalized integer c becomes a float by the spec's formulas
 *   signed byte    f = max(c / 127, -1)      unsigned byte   f = c / 255
 *   signed short   f = max(c / 32767, -1)    unsigned short  f = c / 65535
 * and an integer that is not normalized stands for its own value
 * (KHR_mesh_quantization: "the values are converted to float as is"; the
 * node transform then carries the dequantization scale and offset). */
#ifndef GTLAB_SCENE_GLTF_ACCESSOR_DECODE_H
#define GTLAB_SCENE_GLTF_ACCESSOR_DECODE_H

#include <stddef.h>
#include <stdint.h>

/* glTF componentType codes. */
enum {
    GLTF_BYTE = 5120,
    GLTF_UNSIGNED_BYTE = 5121,
    GLTF_SHORT = 5122,
    GLTF_UNSIGNED_SHORT = 5123,
    GLTF_UNSIGNED_INT = 5125,
    GLTF_FLOAT = 5126
};

/* Bytes per component, or 0 for an unknown code. */
int gltf_component_size(int component_type);

/* Component k of the element at p, as the float it stands for. */
float gltf_component_float(const unsigned char *p, int k, int component_type, int normalized);

/* The float one integer step stands for: 1 unnormalized, 1 / 127, 1 / 255,
 * 1 / 32767 or 1 / 65535 normalized; 0 for float. */
float gltf_component_unit(int component_type, int normalized);

/* An unsigned integer component (indices, joints, sparse indices). */
uint32_t gltf_component_uint(const unsigned char *p, int k, int component_type);

#endif
