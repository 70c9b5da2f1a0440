/* Accessor components as numbers: see accessor_decode.h. */
#include "scene/gltf/accessor_decode.h"

#include <math.h>
#include <string.h>

int gltf_component_size(int component_type)
{
    switch (component_type) {
    case GLTF_BYTE:
    case GLTF_UNSIGNED_BYTE: return 1;
    case GLTF_SHORT:
    case GLTF_UNSIGNED_SHORT: return 2;
    case GLTF_UNSIGNED_INT:
    case GLTF_FLOAT: return 4;
    default: return 0;
    }
}

static int16_t load_i16(const unsigned char *p)
{
    int16_t v;
    memcpy(&v, p, 2);
    return v;
}

static uint16_t load_u16(const unsigned char *p)
{
    uint16_t v;
    memcpy(&v, p, 2);
    return v;
}

/* Normalized: the spec's formulas (accessor_decode.h); else the value itself. */
static float integer_float(int32_t c, float max_value, int is_signed, int normalized)
{
    if (!normalized)
        return (float)c;
    const float f = (float)c / max_value;
    return is_signed ? fmaxf(f, -1.0f) : f;
}

float gltf_component_float(const unsigned char *p, int k, int component_type, int normalized)
{
    switch (component_type) {
    case GLTF_BYTE: return integer_float((int8_t)p[k], 127.0f, 1, normalized);
    case GLTF_UNSIGNED_BYTE: return integer_float(p[k], 255.0f, 0, normalized);
    case GLTF_SHORT: return integer_float(load_i16(p + 2 * k), 32767.0f, 1, normalized);
    case GLTF_UNSIGNED_SHORT: return integer_float(load_u16(p + 2 * k), 65535.0f, 0, normalized);
    default: {
        float f;
        memcpy(&f, p + 4 * k, 4);
        return f;
    }
    }
}

float gltf_component_unit(int component_type, int normalized)
{
    static const unsigned char one[4] = {1, 0, 0, 0};
    return component_type == GLTF_FLOAT ? 0.0f : gltf_component_float(one, 0, component_type, normalized);
}

uint32_t gltf_component_uint(const unsigned char *p, int k, int component_type)
{
    switch (component_type) {
    case GLTF_UNSIGNED_BYTE: return p[k];
    case GLTF_UNSIGNED_SHORT: return load_u16(p + 2 * k);
    default: {
        uint32_t u;
        memcpy(&u, p + 4 * k, 4);
        return u;
    }
    }
}
