/* KHR_draco_mesh_compression through libdraco: the thin C++ adapter behind
 * scene/gltf/draco_decode.h. */
#include <draco/attributes/attribute_quantization_transform.h>
#include <draco/compression/decode.h>

#include <memory>
#include <new>

extern "C" {
#include "scene/gltf/draco_decode.h"
}

struct draco_geometry {
    std::unique_ptr<draco::Mesh> mesh;
    const unsigned char *bytes; /* the encoded mesh (the caller's, alive as long as this) */
    size_t size;
};

extern "C" int draco_geometry_decode(const unsigned char *bytes, size_t size, draco_geometry **out, const char *what,
                                     gt_error *e)
{
    *out = nullptr;
    try {
        draco::DecoderBuffer buffer;
        buffer.Init(reinterpret_cast<const char *>(bytes), size);
        draco::Decoder decoder;
        auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
        if (!decoded.ok())
            return gt_error_set(e, what, "KHR_draco_mesh_compression: the Draco data does not decode (%s)",
                                decoded.status().error_msg());
        if (!decoded.value())
            return gt_error_set(e, what, "KHR_draco_mesh_compression: the Draco data holds no triangle mesh");
        *out = new draco_geometry{std::move(decoded).value(), bytes, size};
        return 0;
    } catch (const std::bad_alloc &) {
        return gt_error_set(e, what, "out of memory");
    }
}

extern "C" uint32_t draco_geometry_vertex_count(const draco_geometry *g)
{
    return g->mesh->num_points();
}

extern "C" uint32_t draco_geometry_triangle_count(const draco_geometry *g)
{
    return g->mesh->num_faces();
}

extern "C" void draco_geometry_indices(const draco_geometry *g, uint32_t *out)
{
    for (uint32_t f = 0; f < g->mesh->num_faces(); ++f)
        for (int k = 0; k < 3; ++k)
            out[3 * (size_t)f + (size_t)k] = g->mesh->face(draco::FaceIndex(f))[k].value();
}

extern "C" int draco_geometry_attribute(const draco_geometry *g, int id, int components, float *out,
                                        const char *what, gt_error *e)
{
    const draco::PointAttribute *a = id >= 0 ? g->mesh->GetAttributeByUniqueId((uint32_t)id) : nullptr;
    if (!a)
        return gt_error_set(e, what, "KHR_draco_mesh_compression: Draco attribute %d does not exist", id);
    if (a->num_components() < components)
        return gt_error_set(e, what, "KHR_draco_mesh_compression: Draco attribute %d has %d components, expected %d",
                            id, (int)a->num_components(), components);
    for (uint32_t i = 0; i < g->mesh->num_points(); ++i)
        if (!a->ConvertValue<float>(a->mapped_index(draco::PointIndex(i)), (int8_t)components,
                                    &out[(size_t)i * (size_t)components]))
            return gt_error_set(e, what, "KHR_draco_mesh_compression: Draco attribute %d does not convert to float",
                                id);
    return 0;
}

/* The decoder applies the quantization transform and drops its parameters;
 * decoded again without applying it to positions, the attribute keeps them. */
extern "C" double draco_geometry_step(const draco_geometry *g, int id)
{
    try {
        draco::DecoderBuffer buffer;
        buffer.Init(reinterpret_cast<const char *>(g->bytes), g->size);
        draco::Decoder decoder;
        decoder.SetSkipAttributeTransform(draco::GeometryAttribute::POSITION);
        auto raw = decoder.DecodeMeshFromBuffer(&buffer);
        const draco::PointAttribute *a =
            raw.ok() && raw.value() && id >= 0 ? raw.value()->GetAttributeByUniqueId((uint32_t)id) : nullptr;
        draco::AttributeQuantizationTransform q;
        if (!a || !q.InitFromAttribute(*a) || q.quantization_bits() <= 0 || q.quantization_bits() > 30)
            return 0.0;
        return (double)q.range() / (double)((1u << q.quantization_bits()) - 1u);
    } catch (const std::bad_alloc &) {
        return 0.0;
    }
}

extern "C" void draco_geometry_free(draco_geometry *g)
{
    delete g;
}
