/* A glTF primitive's geometry for the reader (scene/gltf/gltf_loader.hpp): its
 * vertices from accessors or Draco, its triangles by mode, morph targets and
 * skins in the default pose, unwelded when it has no normals. */
#include "scene/gltf/gltf_loader.hpp"

#include <algorithm>
#include <cstring>

extern "C" {
#include "scene/gltf/draco_decode.h"
#include "scene/gltf/primitive_topology.h"
#include "scene/gltf/vertex_pose.h"
}

namespace gltf_detail {

int attribute(const tinygltf::Primitive &prim, const char *name)
{
    auto it = prim.attributes.find(name);
    return it == prim.attributes.end() ? -1 : it->second;
}

/* A vertex attribute with one element per vertex. */
int read_vertex_floats(Loader &L, const std::string &what, const RoleTypes &role, int index, size_t vertex_count,
                       std::vector<float> &out)
{
    if (read_floats(L, what, role, index, out) != 0)
        return -1;
    const size_t n = (size_t)tinygltf::GetNumComponentsInType((uint32_t)role.type);
    if (out.size() != vertex_count * n)
        return L.fail("%s: %s has %zu elements but POSITION has %zu", what.c_str(), role.name, out.size() / n,
                      vertex_count);
    return 0;
}

/* The primitive's vertex sequence (its indices, or 0, 1, 2, ... without),
 * made a triangle list by its mode (primitive_topology.h). */
int read_indices(Loader &L, const std::string &what, const tinygltf::Primitive &prim, size_t vertex_count,
                 std::vector<uint32_t> &out)
{
    std::vector<uint32_t> sequence;
    if (prim.indices < 0) {
        sequence.resize(vertex_count);
        for (size_t i = 0; i < vertex_count; ++i)
            sequence[i] = (uint32_t)i;
    } else if (read_uints(L, what, role_indices, prim.indices, sequence) != 0) {
        return -1;
    }
    for (size_t i = 0; i < sequence.size(); ++i)
        if (sequence[i] >= vertex_count)
            return L.fail("%s: index %u (entry %zu) is out of range (%zu vertices)", what.c_str(), sequence[i], i,
                          vertex_count);
    if (prim.mode == TINYGLTF_MODE_TRIANGLES && sequence.size() % 3 != 0)
        return L.fail("%s: %zu %s is not a whole number of triangles", what.c_str(), sequence.size(),
                      prim.indices < 0 ? "vertices without indices" : "indices");
    out.resize(3 * gltf_mode_triangle_count(prim.mode, sequence.size()));
    gltf_triangulate(prim.mode, sequence.size(), sequence.data(), out.data());
    return 0;
}

/* A primitive without normals is flat-shaded (glTF 2.0, "Meshes"): every
 * triangle gets its own three vertices, so each can carry the face normal. */
void unweld(Primitive &p)
{
    std::vector<float> positions, texcoords;
    positions.reserve(3 * p.indices.size());
    for (uint32_t i : p.indices) {
        positions.insert(positions.end(), &p.positions[3 * (size_t)i], &p.positions[3 * (size_t)i] + 3);
        if (!p.texcoords.empty())
            texcoords.insert(texcoords.end(), &p.texcoords[2 * (size_t)i], &p.texcoords[2 * (size_t)i] + 2);
    }
    for (size_t k = 0; k < p.indices.size(); ++k)
        p.indices[k] = (uint32_t)k;
    p.positions.swap(positions);
    p.texcoords.swap(texcoords);
}

/* ---------------------------------------------------------- Draco primitives */

/* The Draco attribute named `name` in the extension's attributes as
 * `components` floats per vertex; absent is fine (out stays empty). */
int read_draco_floats(Loader &L, const std::string &what, const draco_geometry *g, const tinygltf::Value &ext,
                      const char *name, int components, std::vector<float> &out)
{
    const int64_t id = member_count(member(ext, "attributes"), name, -2);
    if (id == -2)
        return 0;
    if (id < 0 || id > INT32_MAX)
        return L.fail("%s: KHR_draco_mesh_compression: attribute %s has no valid id", what.c_str(), name);
    out.resize((size_t)draco_geometry_vertex_count(g) * (size_t)components);
    const std::string where = std::string(L.path) + ": " + what;
    return draco_geometry_attribute(g, (int)id, components, out.data(), where.c_str(), L.e) != 0 ? -1 : 0;
}

int read_draco_geometry(Loader &L, const std::string &what, const draco_geometry *g, const tinygltf::Value &ext,
                        Primitive &out)
{
    if (read_draco_floats(L, what, g, ext, "POSITION", 3, out.positions) != 0 ||
        read_draco_floats(L, what, g, ext, "NORMAL", 3, out.normals) != 0 ||
        read_draco_floats(L, what, g, ext, "TEXCOORD_0", 2, out.texcoords) != 0)
        return -1;
    if (out.positions.empty())
        return L.fail("%s: KHR_draco_mesh_compression: no POSITION attribute", what.c_str());
    for (float v : out.positions)
        if (!std::isfinite(v))
            return L.fail("%s: KHR_draco_mesh_compression: a decoded POSITION is not finite", what.c_str());
    out.indices.resize(3 * (size_t)draco_geometry_triangle_count(g));
    draco_geometry_indices(g, out.indices.data());
    const size_t vertex_count = out.positions.size() / 3;
    for (uint32_t i : out.indices)
        if (i >= vertex_count)
            return L.fail("%s: KHR_draco_mesh_compression: index %u is out of range (%zu vertices)", what.c_str(),
                          i, vertex_count);
    return 0;
}

/* KHR_draco_mesh_compression: the primitive's geometry is the Draco mesh in
 * the extension's bufferView (always a triangle list once decoded). */
int read_draco_attributes(Loader &L, const std::string &what, const tinygltf::Primitive &prim,
                          const tinygltf::Value &ext, Primitive &out)
{
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP)
        return L.fail("%s: KHR_draco_mesh_compression on mode %d (%s)", what.c_str(), prim.mode,
                      mode_name(prim.mode));
    const int64_t view_index = member_count(ext, "bufferView", -1);
    if (view_index < 0 || (size_t)view_index >= L.model.bufferViews.size())
        return L.fail("%s: KHR_draco_mesh_compression: bufferView %lld does not exist", what.c_str(),
                      (long long)view_index);
    AccessorView v;
    const size_t length = L.model.bufferViews[(size_t)view_index].byteLength;
    if (view_elements(L, what, "Draco data", (int)view_index, 0, length, 1, false, &v) != 0)
        return -1;
    draco_geometry *g = nullptr;
    const std::string where = std::string(L.path) + ": " + what;
    if (draco_geometry_decode(v.base, length, &g, where.c_str(), L.e) != 0)
        return -1;
    const int rc = read_draco_geometry(L, what, g, ext, out);
    L.position_step = draco_geometry_step(g, (int)member_count(member(ext, "attributes"), "POSITION", -1));
    draco_geometry_free(g);
    L.report->draco_primitives += rc == 0;
    return rc;
}

/* -------------------------------------------------------------- primitives */

/* POSITION, NORMAL, TEXCOORD_0 and the triangles from the accessors. */
int read_accessor_attributes(Loader &L, const std::string &what, const tinygltf::Primitive &prim, Primitive &out)
{
    const int position = attribute(prim, "POSITION");
    if (position < 0)
        return L.fail("%s: no POSITION attribute", what.c_str());
    if (read_floats(L, what, role_position, position, out.positions) != 0)
        return -1;
    const size_t vertex_count = out.positions.size() / 3;
    if (vertex_count > UINT32_MAX / 3)
        return L.fail("%s: too many vertices (%zu)", what.c_str(), vertex_count);
    const int normal = attribute(prim, "NORMAL");
    if (normal >= 0 && read_vertex_floats(L, what, role_normal, normal, vertex_count, out.normals) != 0)
        return -1;
    const int texcoord = attribute(prim, "TEXCOORD_0");
    if (texcoord >= 0 && read_vertex_floats(L, what, role_texcoord, texcoord, vertex_count, out.texcoords) != 0)
        return -1;
    return read_indices(L, what, prim, vertex_count, out.indices);
}

/* Morph targets (glTF 2.0, "Morph Targets"): the node's weights, else the
 * mesh's, times each target's POSITION and NORMAL displacements. */
int apply_morph_targets(Loader &L, const std::string &what, const tinygltf::Node &node, const tinygltf::Mesh &mesh,
                        const tinygltf::Primitive &prim, Primitive &out)
{
    const std::vector<double> &weights = !node.weights.empty() ? node.weights : mesh.weights;
    if (prim.targets.empty() || weights.empty())
        return 0;
    if (weights.size() != prim.targets.size())
        return L.fail("%s: %zu morph weights for %zu morph targets", what.c_str(), weights.size(),
                      prim.targets.size());
    const size_t vertex_count = out.positions.size() / 3;
    for (size_t t = 0; t < prim.targets.size(); ++t) {
        if (!std::isfinite(weights[t]))
            return L.fail("%s: morph weight %zu is not finite", what.c_str(), t);
        if (weights[t] == 0.0)
            continue;
        std::vector<float> delta;
        const auto &target = prim.targets[t];
        auto p = target.find("POSITION"), n = target.find("NORMAL");
        if (p != target.end() && (read_vertex_floats(L, what, role_target_position, p->second, vertex_count, delta) != 0))
            return -1;
        pose_morph_add(out.positions.data(), delta.data(), (float)weights[t], delta.size());
        if (n != target.end() && !out.normals.empty()) {
            if (read_vertex_floats(L, what, role_target_normal, n->second, vertex_count, delta) != 0)
                return -1;
            pose_morph_add(out.normals.data(), delta.data(), (float)weights[t], delta.size());
        }
        L.morphed_primitive = true;
    }
    return 0;
}

/* ------------------------------------------------------------------- skins */

/* The node's own transform: its matrix, or T * R * S from its translation,
 * rotation (normalised) and scale, checked (glTF 2.0 "Transformations"). */
int node_local_matrix(Loader &L, int index, Mat4 *out)
{
    const tinygltf::Node &node = L.model.nodes[(size_t)index];
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16)
            return L.fail("node %d: matrix has %zu numbers, expected 16", index, node.matrix.size());
        std::copy(node.matrix.begin(), node.matrix.end(), out->m);
    } else {
        double t[3] = {0, 0, 0}, q[4] = {0, 0, 0, 1}, s[3] = {1, 1, 1};
        if (!node.translation.empty() && node.translation.size() != 3)
            return L.fail("node %d: translation has %zu numbers, expected 3", index, node.translation.size());
        if (!node.rotation.empty() && node.rotation.size() != 4)
            return L.fail("node %d: rotation has %zu numbers, expected 4", index, node.rotation.size());
        if (!node.scale.empty() && node.scale.size() != 3)
            return L.fail("node %d: scale has %zu numbers, expected 3", index, node.scale.size());
        std::copy(node.translation.begin(), node.translation.end(), t);
        std::copy(node.rotation.begin(), node.rotation.end(), q);
        std::copy(node.scale.begin(), node.scale.end(), s);
        /* The spec requires a unit quaternion; exporters round, so normalise. */
        const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(len > 0.0) || !std::isfinite(len))
            return L.fail("node %d: rotation quaternion has zero or non-finite length", index);
        for (double &c : q)
            c /= len;
        *out = mat4_trs(t, q, s);
    }
    if (!mat4_is_finite(*out))
        return L.fail("node %d: transform has non-finite values", index);
    return 0;
}

/* The node's global transform (parents' transforms times its own), computed
 * once per node by walking up to the first known ancestor (no recursion). */
int world_of(Loader &L, int node, Mat4 *out)
{
    std::vector<int> chain;
    for (int at = node; at >= 0 && !L.world_known[(size_t)at]; at = L.parent[(size_t)at])
        chain.push_back(at);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        Mat4 local;
        if (node_local_matrix(L, *it, &local) != 0)
            return -1;
        const int parent = L.parent[(size_t)*it];
        L.world[(size_t)*it] = parent >= 0 ? mat4_mul(L.world[(size_t)parent], local) : local;
        if (!mat4_is_finite(L.world[(size_t)*it]))
            return L.fail("node %d: world transform overflows", *it);
        L.world_known[(size_t)*it] = 1;
    }
    *out = L.world[(size_t)node];
    return 0;
}

/* J_j = G_j * IBM_j for every joint of the skin (vertex_pose.h). */
int joint_matrices(Loader &L, const std::string &what, const tinygltf::Skin &skin, std::vector<double> &out)
{
    std::vector<float> inverse_bind;
    if (skin.inverseBindMatrices >= 0 &&
        read_floats(L, what, role_bind_matrices, skin.inverseBindMatrices, inverse_bind) != 0)
        return -1;
    if (!inverse_bind.empty() && inverse_bind.size() != 16 * skin.joints.size())
        return L.fail("%s: skin has %zu joints but %zu inverse bind matrices", what.c_str(), skin.joints.size(),
                      inverse_bind.size() / 16);
    out.resize(16 * skin.joints.size());
    for (size_t j = 0; j < skin.joints.size(); ++j) {
        Mat4 global, bind = mat4_identity();
        const int joint = skin.joints[j];
        if (joint < 0 || (size_t)joint >= L.model.nodes.size())
            return L.fail("%s: skin joint %zu: node %d does not exist", what.c_str(), j, joint);
        if (world_of(L, joint, &global) != 0)
            return -1;
        if (!inverse_bind.empty())
            std::copy(&inverse_bind[16 * j], &inverse_bind[16 * j] + 16, bind.m);
        const Mat4 m = mat4_mul(global, bind);
        std::copy(m.m, m.m + 16, &out[16 * j]);
    }
    return 0;
}

/* JOINTS_n / WEIGHTS_n for n = 0, 1, ...: 4 influences per set and vertex,
 * interleaved per vertex in out.joints / out.weights. */
int read_influences(Loader &L, const std::string &what, const tinygltf::Primitive &prim, size_t joint_count,
                    Primitive &out)
{
    const size_t vertex_count = out.positions.size() / 3;
    std::vector<std::vector<uint32_t>> joints;
    std::vector<std::vector<float>> weights;
    for (int set = 0;; ++set) {
        const std::string j = "JOINTS_" + std::to_string(set), w = "WEIGHTS_" + std::to_string(set);
        const int ji = attribute(prim, j.c_str()), wi = attribute(prim, w.c_str());
        if (ji < 0 && wi < 0)
            break;
        joints.emplace_back();
        weights.emplace_back();
        if (ji < 0 || wi < 0)
            return L.fail("%s: %s without %s", what.c_str(), ji < 0 ? w.c_str() : j.c_str(),
                          ji < 0 ? j.c_str() : w.c_str());
        if (read_uints(L, what, role_joints, ji, joints.back()) != 0 ||
            read_vertex_floats(L, what, role_weights, wi, vertex_count, weights.back()) != 0)
            return -1;
        if (joints.back().size() != 4 * vertex_count)
            return L.fail("%s: %s has %zu elements but POSITION has %zu", what.c_str(), j.c_str(),
                          joints.back().size() / 4, vertex_count);
    }
    out.influences = 4 * (int)joints.size();
    out.joints.resize(vertex_count * (size_t)out.influences);
    out.weights.resize(out.joints.size());
    for (size_t v = 0; v < vertex_count; ++v)
        for (size_t s = 0; s < joints.size(); ++s)
            for (size_t k = 0; k < 4; ++k) {
                const size_t at = v * (size_t)out.influences + 4 * s + k;
                out.joints[at] = joints[s][4 * v + k];
                out.weights[at] = weights[s][4 * v + k];
                if (out.joints[at] >= joint_count)
                    return L.fail("%s: JOINTS_%zu %zu names joint %u (the skin has %zu)", what.c_str(), s, v,
                                  out.joints[at], joint_count);
            }
    return 0;
}

/* Skins in the default pose (vertex_pose.h): the vertices go to world space
 * by their joints; the skinned node's own transform is not applied. */
int apply_skin(Loader &L, const std::string &what, const tinygltf::Node &node, const tinygltf::Primitive &prim,
               Primitive &out)
{
    if (node.skin < 0)
        return 0;
    if ((size_t)node.skin >= L.model.skins.size())
        return L.fail("%s: skin %d does not exist", what.c_str(), node.skin);
    const tinygltf::Skin &skin = L.model.skins[(size_t)node.skin];
    if (read_influences(L, what, prim, skin.joints.size(), out) != 0)
        return -1;
    if (out.influences == 0) {
        gt_warn(L.path, "%s: its node has a skin but it has no JOINTS_0/WEIGHTS_0; drawn unskinned", what.c_str());
        return 0;
    }
    std::vector<double> matrices;
    if (joint_matrices(L, what, skin, matrices) != 0)
        return -1;
    pose_skin_vertices(matrices.data(), out.joints.data(), out.weights.data(), out.influences,
                       out.positions.size() / 3, out.positions.data(), out.normals.empty() ? nullptr : out.normals.data());
    out.skinned = true;
    return 0;
}

/* One primitive: its geometry (Draco or accessors), morphed, skinned, and
 * unwelded when it has no normals. */
int read_primitive(Loader &L, const std::string &what, const tinygltf::Node &node, const tinygltf::Mesh &mesh,
                   const tinygltf::Primitive &prim, Primitive &out)
{
    L.quantized_primitive = L.morphed_primitive = false;
    L.position_step = 0.0;
    const tinygltf::Value *draco = extension(prim.extensions, "KHR_draco_mesh_compression");
    if (draco && (node.skin >= 0 || !prim.targets.empty()))
        return L.fail("%s: KHR_draco_mesh_compression with %s is not supported", what.c_str(),
                      node.skin >= 0 ? "a skin" : "morph targets");
    if ((draco ? read_draco_attributes(L, what, prim, *draco, out) : read_accessor_attributes(L, what, prim, out)) != 0 ||
        apply_morph_targets(L, what, node, mesh, prim, out) != 0 || apply_skin(L, what, node, prim, out) != 0)
        return -1;
    gltf_report *r = L.report;
    r->quantized_primitives += L.quantized_primitive;
    r->morphed_primitives += L.morphed_primitive;
    r->skinned_primitives += out.skinned;
    r->primitives_without_normals += out.normals.empty();
    if (out.normals.empty())
        unweld(out);
    return 0;
}

} // namespace gltf_detail
