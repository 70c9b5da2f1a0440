/* Accessor data for the glTF reader (scene/gltf/gltf_loader.hpp): checked views
 * onto bufferViews, sparse substitution, component types per attribute role
 * (core glTF 2.0 and KHR_mesh_quantization), extension values, and
 * EXT_meshopt_compression views decoded into buffers of their own. */
#include "scene/gltf/gltf_loader.hpp"

#include <algorithm>
#include <cstring>

extern "C" {
#include "scene/gltf/accessor_decode.h"
#include "scene/gltf/meshopt_decode.h"
}

namespace gltf_detail {

/* Largest accessor gtlab materialises (bytes): an accessor without a
 * bufferView (all zeros but for its sparse values) has a count no buffer
 * bounds. (Lower in the fuzz build, as max_texture_side.) */
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
const uint64_t max_accessor_bytes = (uint64_t)1 << 24;
#else
const uint64_t max_accessor_bytes = (uint64_t)1 << 32;
#endif

/* The bufferView `view_index` at byte `offset` holds count elements
 * (tightly packed, or at the view's byteStride when use_stride). */
int view_elements(Loader &L, const std::string &what, const char *role, int view_index, size_t offset, size_t count,
                  size_t element_size, bool use_stride, AccessorView *v)
{
    const tinygltf::Model &m = L.model;
    if (view_index < 0 || (size_t)view_index >= m.bufferViews.size())
        return L.fail("%s: %s: bufferView %d does not exist", what.c_str(), role, view_index);
    const tinygltf::BufferView &view = m.bufferViews[(size_t)view_index];
    if (view.buffer < 0 || (size_t)view.buffer >= m.buffers.size())
        return L.fail("%s: %s: bufferView %d: buffer %d does not exist", what.c_str(), role, view_index, view.buffer);
    const tinygltf::Buffer &buffer = m.buffers[(size_t)view.buffer];
    if (!range_inside(view.byteOffset, view.byteLength, buffer.data.size()))
        return L.fail("%s: bufferView %d (bytes %zu + %zu) exceeds buffer %d (%zu bytes)", what.c_str(), view_index,
                      view.byteOffset, view.byteLength, view.buffer, buffer.data.size());
    v->stride = element_size;
    v->count = count;
    if (use_stride && view.byteStride != 0) {
        if (view.byteStride < element_size)
            return L.fail("%s: bufferView %d: byteStride %zu is smaller than a %s element (%zu bytes)", what.c_str(),
                          view_index, view.byteStride, role, element_size);
        v->stride = view.byteStride;
    }
    /* The last element ends at offset + (count - 1) * stride + element_size. */
    const bool fits = count == 0 || (range_inside(offset, element_size, view.byteLength) &&
                                     (count - 1) <= (view.byteLength - offset - element_size) / v->stride);
    if (!fits)
        return L.fail("%s: %s (%zu elements from byte %zu, stride %zu) exceeds bufferView %d (%zu bytes)",
                      what.c_str(), role, count, offset, v->stride, view_index, view.byteLength);
    v->base = buffer.data.data() + view.byteOffset + offset;
    return 0;
}

size_t element_size_of(const tinygltf::Accessor &a)
{
    const int components = tinygltf::GetNumComponentsInType((uint32_t)a.type);
    return components > 0 ? (size_t)components * (size_t)gltf_component_size(a.componentType) : 0;
}

/* Sparse substitution (glTF 2.0, "Sparse Accessors"): `count` strictly
 * increasing indices, each < the accessor's count, and as many values
 * replacing those elements of `elements`. */
int apply_sparse(Loader &L, const std::string &what, const std::string &role, const tinygltf::Accessor &a,
                 size_t element_size, std::vector<unsigned char> &elements)
{
    const auto &sp = a.sparse;
    const int index_type = sp.indices.componentType;
    if (index_type != GLTF_UNSIGNED_BYTE && index_type != GLTF_UNSIGNED_SHORT && index_type != GLTF_UNSIGNED_INT)
        return L.fail("%s: %s: sparse indices are %s; expected unsigned byte/short/int", what.c_str(), role.c_str(),
                      component_type_name(index_type));
    if (sp.count < 0 || (size_t)sp.count > a.count)
        return L.fail("%s: %s: sparse count %d exceeds the accessor's %zu elements", what.c_str(), role.c_str(),
                      sp.count, a.count);
    AccessorView iv, vv;
    const std::string sparse_role = role + " sparse";
    if (view_elements(L, what, sparse_role.c_str(), sp.indices.bufferView, (size_t)sp.indices.byteOffset,
                      (size_t)sp.count, (size_t)gltf_component_size(index_type), false, &iv) != 0 ||
        view_elements(L, what, sparse_role.c_str(), sp.values.bufferView, (size_t)sp.values.byteOffset,
                      (size_t)sp.count, element_size, false, &vv) != 0)
        return -1;
    for (size_t k = 0; k < (size_t)sp.count; ++k) {
        const uint32_t i = gltf_component_uint(iv.base + k * iv.stride, 0, index_type);
        if (i >= a.count || (k > 0 && i <= gltf_component_uint(iv.base + (k - 1) * iv.stride, 0, index_type)))
            return L.fail("%s: %s: sparse index %u (entry %zu) is out of range or not increasing", what.c_str(),
                          role.c_str(), i, k);
        std::memcpy(&elements[i * element_size], vv.base + k * vv.stride, element_size);
    }
    return 0;
}

/* The accessor's elements, tightly packed, with any sparse substitution
 * applied; an accessor without a bufferView starts as zeros. */
int accessor_elements(Loader &L, const std::string &what, const char *role, int index,
                      std::vector<unsigned char> &elements)
{
    const tinygltf::Accessor &a = L.model.accessors[(size_t)index];
    const size_t element_size = element_size_of(a);
    const std::string name = std::string(role) + " accessor " + std::to_string(index);
    if (element_size == 0)
        return L.fail("%s: %s has an unknown type", what.c_str(), name.c_str());
    if (a.bufferView < 0 && !a.sparse.isSparse)
        return L.fail("%s: %s has no bufferView (and no sparse data)", what.c_str(), name.c_str());
    AccessorView v = {nullptr, element_size, a.count};
    if (a.bufferView >= 0 &&
        view_elements(L, what, name.c_str(), a.bufferView, a.byteOffset, a.count, element_size, true, &v) != 0)
        return -1;
    if ((uint64_t)a.count > max_accessor_bytes / element_size)
        return L.fail("%s: %s has %zu elements, more than gtlab reads", what.c_str(), name.c_str(), a.count);
    elements.assign(a.count * element_size, 0);
    for (size_t i = 0; v.base && i < a.count; ++i)
        std::memcpy(&elements[i * element_size], v.base + i * v.stride, element_size);
    if (!a.sparse.isSparse)
        return 0;
    L.sparse_seen.insert(index);
    return apply_sparse(L, what, name, a, element_size, elements);
}

/* Component types an accessor role accepts: bit (1 << k) of type_flag(). */
enum : unsigned {
    F32 = 1u << 0, I8 = 1u << 1, I8N = 1u << 2, U8 = 1u << 3, U8N = 1u << 4,
    I16 = 1u << 5, I16N = 1u << 6, U16 = 1u << 7, U16N = 1u << 8, U32 = 1u << 9
};

unsigned type_flag(int component_type, bool normalized)
{
    switch (component_type) {
    case GLTF_FLOAT: return F32;
    case GLTF_BYTE: return normalized ? I8N : I8;
    case GLTF_UNSIGNED_BYTE: return normalized ? U8N : U8;
    case GLTF_SHORT: return normalized ? I16N : I16;
    case GLTF_UNSIGNED_SHORT: return normalized ? U16N : U16;
    case GLTF_UNSIGNED_INT: return normalized ? 0u : (unsigned)U32;
    default: return 0;
    }
}

/* "float or normalized unsigned byte" for a set of flags. */
std::string flags_text(unsigned flags)
{
    static const char *names[] = {"float", "byte", "normalized byte", "unsigned byte", "normalized unsigned byte",
                                  "short", "normalized short", "unsigned short", "normalized unsigned short",
                                  "unsigned int"};
    std::string out;
    for (int k = 0; k < 10; ++k)
        if (flags & (1u << k))
            out += (out.empty() ? "" : " or ") + std::string(names[k]);
    return out;
}


const RoleTypes role_position = {"POSITION", TINYGLTF_TYPE_VEC3, F32, I8 | I8N | U8 | U8N | I16 | I16N | U16 | U16N};
const RoleTypes role_normal = {"NORMAL", TINYGLTF_TYPE_VEC3, F32, I8N | I16N};
const RoleTypes role_texcoord = {"TEXCOORD_0", TINYGLTF_TYPE_VEC2, F32 | U8N | U16N, I8 | I8N | U8 | I16 | I16N | U16};
const RoleTypes role_target_position = {"POSITION target", TINYGLTF_TYPE_VEC3, F32, I8 | I8N | I16 | I16N};
const RoleTypes role_target_normal = {"NORMAL target", TINYGLTF_TYPE_VEC3, F32, I8N | I16N};
const RoleTypes role_weights = {"WEIGHTS", TINYGLTF_TYPE_VEC4, F32 | U8N | U16N, 0};
const RoleTypes role_joints = {"JOINTS", TINYGLTF_TYPE_VEC4, U8 | U16, 0};
const RoleTypes role_indices = {"indices", TINYGLTF_TYPE_SCALAR, U8 | U16 | U32, 0};
const RoleTypes role_bind_matrices = {"inverseBindMatrices", TINYGLTF_TYPE_MAT4, F32, 0};

/* Checks that accessor `index` exists and has a type the role accepts. */
int expect_type(Loader &L, const std::string &what, const RoleTypes &role, int index)
{
    if (index < 0 || (size_t)index >= L.model.accessors.size())
        return L.fail("%s: %s accessor %d does not exist", what.c_str(), role.name, index);
    const tinygltf::Accessor &a = L.model.accessors[(size_t)index];
    const unsigned allowed = role.core | (L.quantization ? role.quantized : 0u);
    const unsigned flag = type_flag(a.componentType, a.normalized);
    if (a.type == role.type && (flag & allowed))
        return 0;
    const bool hint = !L.quantization && (flag & role.quantized);
    return L.fail("%s: %s accessor %d is %s%s %s; expected %s %s%s", what.c_str(), role.name, index,
                  a.normalized ? "normalized " : "", component_type_name(a.componentType), type_name(a.type),
                  flags_text(allowed).c_str(), type_name(role.type),
                  hint ? " (KHR_mesh_quantization allows it, but the file does not declare it)" : "");
}

/* The accessor as floats (accessor_decode.h), components per element in *n. */
int read_floats(Loader &L, const std::string &what, const RoleTypes &role, int index, std::vector<float> &out)
{
    std::vector<unsigned char> bytes;
    if (expect_type(L, what, role, index) != 0 || accessor_elements(L, what, role.name, index, bytes) != 0)
        return -1;
    const tinygltf::Accessor &a = L.model.accessors[(size_t)index];
    const int n = tinygltf::GetNumComponentsInType((uint32_t)a.type);
    const size_t element_size = element_size_of(a);
    out.resize(a.count * (size_t)n);
    for (size_t i = 0; i < a.count; ++i)
        for (int k = 0; k < n; ++k) {
            const float value = gltf_component_float(&bytes[i * element_size], k, a.componentType, a.normalized);
            if (!std::isfinite(value))
                return L.fail("%s: %s %zu is not finite", what.c_str(), role.name, i);
            out[i * (size_t)n + (size_t)k] = value;
        }
    if (role.quantized && type_flag(a.componentType, a.normalized) != F32)
        L.quantized_primitive = true;
    if (&role == &role_position && a.componentType != GLTF_FLOAT) /* the integer unit, normalized or not */
        L.position_step = gltf_component_unit(a.componentType, a.normalized);
    return 0;
}

/* The accessor as unsigned integers (indices, joints). */
int read_uints(Loader &L, const std::string &what, const RoleTypes &role, int index, std::vector<uint32_t> &out)
{
    std::vector<unsigned char> bytes;
    if (expect_type(L, what, role, index) != 0 || accessor_elements(L, what, role.name, index, bytes) != 0)
        return -1;
    const tinygltf::Accessor &a = L.model.accessors[(size_t)index];
    const int n = tinygltf::GetNumComponentsInType((uint32_t)a.type);
    const size_t element_size = element_size_of(a);
    out.resize(a.count * (size_t)n);
    for (size_t i = 0; i < a.count; ++i)
        for (int k = 0; k < n; ++k)
            out[i * (size_t)n + (size_t)k] = gltf_component_uint(&bytes[i * element_size], k, a.componentType);
    return 0;
}

/* ---------------------------------------------------- extension objects */

/* o[key] when o is an object holding it, else a null Value. */
const tinygltf::Value &member(const tinygltf::Value &o, const char *key)
{
    static const tinygltf::Value null_value;
    return o.IsObject() && o.Has(key) ? o.Get(key) : null_value;
}

/* o[key] as a whole number in [0, 2^53), or `absent` when missing; -1 when
 * present but not such a number. */
int64_t member_count(const tinygltf::Value &o, const char *key, int64_t absent)
{
    const tinygltf::Value &v = member(o, key);
    if (v.Type() == tinygltf::NULL_TYPE)
        return absent;
    const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    return d >= 0.0 && d < 9007199254740992.0 && d == std::floor(d) ? (int64_t)d : -1;
}

std::string member_string(const tinygltf::Value &o, const char *key, const char *absent)
{
    const tinygltf::Value &v = member(o, key);
    return v.IsString() ? v.Get<std::string>() : v.Type() == tinygltf::NULL_TYPE ? absent : "(not a string)";
}

const tinygltf::Value *extension(const tinygltf::ExtensionMap &extensions, const char *name)
{
    auto it = extensions.find(name);
    return it == extensions.end() ? nullptr : &it->second;
}

/* o[key] as `n` numbers (a number when n is 1), or `fallback` when absent. */
bool member_numbers(const tinygltf::Value &o, const char *key, int n, const double *fallback, double *out)
{
    const tinygltf::Value &v = member(o, key);
    std::copy(fallback, fallback + n, out);
    if (v.Type() == tinygltf::NULL_TYPE)
        return true;
    if (n == 1 && v.IsNumber()) {
        out[0] = v.GetNumberAsDouble();
        return true;
    }
    if (n == 1 || !v.IsArray() || v.ArrayLen() != (size_t)n)
        return false;
    for (int k = 0; k < n; ++k) {
        if (!v.Get(k).IsNumber())
            return false;
        out[k] = v.Get(k).GetNumberAsDouble();
    }
    return true;
}

/* ----------------------------------------------------------- meshopt views */

/* One bufferView carrying EXT_meshopt_compression (meshopt_decode.h),
 * decoded from its compressed range into a buffer of its own; the view then
 * points there and is read like any other. */
int decode_meshopt_view(Loader &L, size_t index, const tinygltf::Value &ext)
{
    const std::string what = std::string(L.path) + ": bufferView " + std::to_string(index);
    const int64_t buffer = member_count(ext, "buffer", -1), offset = member_count(ext, "byteOffset", 0),
                  length = member_count(ext, "byteLength", -1), stride = member_count(ext, "byteStride", -1),
                  count = member_count(ext, "count", -1);
    if (buffer < 0 || (size_t)buffer >= L.model.buffers.size() || offset < 0 || length < 0 || stride <= 0 ||
        count < 0)
        return gt_error_set(L.e, what.c_str(), "EXT_meshopt_compression: buffer, byteOffset, byteLength, "
                                               "byteStride or count is missing or invalid");
    const std::vector<unsigned char> &source = L.model.buffers[(size_t)buffer].data;
    if (!range_inside((uint64_t)offset, (uint64_t)length, source.size()))
        return gt_error_set(L.e, what.c_str(), "EXT_meshopt_compression: bytes %lld + %lld exceed buffer %lld (%zu bytes)",
                            (long long)offset, (long long)length, (long long)buffer, source.size());
    if ((uint64_t)count > max_accessor_bytes / (uint64_t)stride)
        return gt_error_set(L.e, what.c_str(), "EXT_meshopt_compression: %lld elements of %lld bytes, more than gtlab reads",
                            (long long)count, (long long)stride);
    const std::string mode = member_string(ext, "mode", ""), filter = member_string(ext, "filter", "NONE");
    const meshopt_view v = {(size_t)count, (size_t)stride, mode.c_str(), filter.c_str()};
    tinygltf::Buffer decoded;
    decoded.data.resize(v.count * v.stride);
    if (meshopt_decode_view(&v, source.data() + offset, (size_t)length, decoded.data.data(), what.c_str(), L.e) != 0)
        return -1;
    L.model.buffers.push_back(std::move(decoded));
    tinygltf::BufferView &view = L.model.bufferViews[index];
    view.buffer = (int)L.model.buffers.size() - 1;
    view.byteOffset = 0;
    view.byteLength = v.count * v.stride;
    ++L.report->meshopt_views;
    return 0;
}

int decode_meshopt_views(Loader &L)
{
    for (size_t i = 0; i < L.model.bufferViews.size(); ++i) {
        const tinygltf::Value *ext = extension(L.model.bufferViews[i].extensions, "EXT_meshopt_compression");
        if (ext && decode_meshopt_view(L, i, *ext) != 0)
            return -1;
    }
    return 0;
}

} // namespace gltf_detail
