/* glTF 2.0 out through tinygltf: the thin C++ adapter behind
 * scene/gltf/gltf_writer.h. The scene becomes a tinygltf model (one buffer, one
 * bufferView and accessor per attribute, one mesh and root node per scene
 * mesh, its materials, textures and camera) that tinygltf serialises as a
 * .glb, written atomically. Reference: the glTF 2.0 specification (Khronos,
 * version 2.0.1), sections "Accessors", "Data Alignment", "Meshes",
 * "Materials", "Cameras" and "GLB File Format Specification". */
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <new>
#include <sstream>
#include <string>
#include <vector>

extern "C" {
#include "core/files/atomic_file.h"
#include "scene/gltf/gltf_writer.h"
}

namespace {

/* Appends raw bytes as a new bufferView of the single buffer, 4-byte aligned
 * (glTF 2.0 "Data Alignment": accessor data aligned to its component size). */
int add_buffer_view(tinygltf::Model &model, const void *data, size_t size, int target)
{
    std::vector<unsigned char> &buffer = model.buffers[0].data;
    buffer.resize((buffer.size() + 3) & ~(size_t)3, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = size;
    view.target = target;
    const unsigned char *bytes = static_cast<const unsigned char *>(data);
    buffer.insert(buffer.end(), bytes, bytes + size);
    model.bufferViews.push_back(view);
    return (int)model.bufferViews.size() - 1;
}

int add_accessor(tinygltf::Model &model, const void *data, size_t count, int type, int component_type, int target)
{
    const size_t size = count * (size_t)tinygltf::GetNumComponentsInType((uint32_t)type) *
                        (size_t)tinygltf::GetComponentSizeInBytes((uint32_t)component_type);
    tinygltf::Accessor a;
    a.bufferView = add_buffer_view(model, data, size, target);
    a.byteOffset = 0;
    a.componentType = component_type;
    a.count = count;
    a.type = type;
    model.accessors.push_back(a);
    return (int)model.accessors.size() - 1;
}

void write_mesh(tinygltf::Model &model, const scene_mesh *m)
{
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = m->material;
    const int position = add_accessor(model, m->positions, m->vertex_count, TINYGLTF_TYPE_VEC3,
                                      TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
    /* POSITION must carry its bounds (glTF 2.0 "Meshes"). */
    tinygltf::Accessor &pa = model.accessors[(size_t)position];
    pa.minValues.assign(3, INFINITY);
    pa.maxValues.assign(3, -INFINITY);
    for (uint32_t v = 0; v < m->vertex_count; ++v)
        for (int k = 0; k < 3; ++k) {
            pa.minValues[(size_t)k] = std::min(pa.minValues[(size_t)k], (double)m->positions[3 * v + (uint32_t)k]);
            pa.maxValues[(size_t)k] = std::max(pa.maxValues[(size_t)k], (double)m->positions[3 * v + (uint32_t)k]);
        }
    prim.attributes["POSITION"] = position;
    if (m->normals) /* none: the reader shades the primitive flat */
        prim.attributes["NORMAL"] = add_accessor(model, m->normals, m->vertex_count, TINYGLTF_TYPE_VEC3,
                                                 TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
    if (m->texcoords)
        prim.attributes["TEXCOORD_0"] = add_accessor(model, m->texcoords, m->vertex_count, TINYGLTF_TYPE_VEC2,
                                                     TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
    prim.indices = add_accessor(model, m->indices, 3 * (size_t)m->triangle_count, TINYGLTF_TYPE_SCALAR,
                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(prim);
    model.meshes.push_back(mesh);
}

void write_material(tinygltf::Model &model, const scene_material &sm, float alpha_cutoff)
{
    tinygltf::Material mat;
    tinygltf::PbrMetallicRoughness &pbr = mat.pbrMetallicRoughness;
    pbr.baseColorFactor.assign(sm.base_color, sm.base_color + 4);
    pbr.metallicFactor = sm.metallic;
    pbr.roughnessFactor = sm.roughness;
    pbr.baseColorTexture.index = sm.base_color_texture;
    pbr.metallicRoughnessTexture.index = sm.metallic_roughness_texture;
    mat.doubleSided = true; /* gtlab's surfaces are two-sided (DESIGN.md) */
    if (alpha_cutoff > 0.0f)
        mat.alphaMode = "MASK", mat.alphaCutoff = alpha_cutoff;
    model.materials.push_back(mat);
}

/* Texture i becomes image i, raw RGBA that tinygltf's writer encodes to PNG
 * (stb_image_write) and embeds as a data: URI because of the mime type. */
void write_texture(tinygltf::Model &model, const scene_texture &t)
{
    tinygltf::Image image;
    image.width = t.width;
    image.height = t.height;
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.mimeType = "image/png";
    image.image.assign(t.rgba, t.rgba + 4 * (size_t)t.width * (size_t)t.height);
    model.images.push_back(image);
    tinygltf::Texture texture;
    texture.source = (int)model.images.size() - 1;
    model.textures.push_back(texture);
}

/* Rotation quaternion (x, y, z, w) of the orthonormal basis with columns
 * (right, up, back): Shepperd's method, choosing the largest diagonal term
 * for accuracy (Shepperd 1978, J. Guidance and Control 1(3)). */
void quaternion_from_basis(vec3 x_axis, vec3 y_axis, vec3 z_axis, double q[4])
{
    const double m00 = x_axis.x, m10 = x_axis.y, m20 = x_axis.z;
    const double m01 = y_axis.x, m11 = y_axis.y, m21 = y_axis.z;
    const double m02 = z_axis.x, m12 = z_axis.y, m22 = z_axis.z;
    const double trace = m00 + m11 + m22;
    if (trace > 0.0) {
        const double s = 2.0 * std::sqrt(trace + 1.0);
        q[0] = (m21 - m12) / s, q[1] = (m02 - m20) / s, q[2] = (m10 - m01) / s, q[3] = 0.25 * s;
    } else if (m00 > m11 && m00 > m22) {
        const double s = 2.0 * std::sqrt(1.0 + m00 - m11 - m22);
        q[0] = 0.25 * s, q[1] = (m01 + m10) / s, q[2] = (m02 + m20) / s, q[3] = (m21 - m12) / s;
    } else if (m11 > m22) {
        const double s = 2.0 * std::sqrt(1.0 + m11 - m00 - m22);
        q[0] = (m01 + m10) / s, q[1] = 0.25 * s, q[2] = (m12 + m21) / s, q[3] = (m02 - m20) / s;
    } else {
        const double s = 2.0 * std::sqrt(1.0 + m22 - m00 - m11);
        q[0] = (m02 + m20) / s, q[1] = (m12 + m21) / s, q[2] = 0.25 * s, q[3] = (m10 - m01) / s;
    }
}

/* The camera node: translation = position, rotation taking local -Z to the
 * view direction and local +Y to the (orthogonalised) up vector. */
int write_camera(tinygltf::Model &model, const scene *s, const char *path, gt_error *e, int *node_out)
{
    const camera &c = s->camera;
    const vec3 view = v3_sub(c.target, c.position);
    const vec3 side = v3_cross(view, c.up);
    if (!v3_is_finite(c.position) || !v3_is_finite(c.target) || !(v3_length(view) > 0.0f) ||
        !(v3_length(side) > 0.0f) || !(c.yfov > 0.0f && c.yfov < (float)M_PI) || c.width <= 0 || c.height <= 0)
        return gt_error_set(e, path, "the scene camera is degenerate; cannot write it");
    const vec3 forward = v3_normalize(view), right = v3_normalize(side);
    const vec3 up = v3_cross(right, forward);
    double q[4];
    quaternion_from_basis(right, up, v3_neg(forward), q);

    /* Near and far planes are required by glTF but unused by a path tracer:
     * place them relative to the scene's extent around the camera. */
    vec3 lo, hi;
    scene_bounds(s, &lo, &hi);
    const vec3 centre = v3_scale(v3_add(lo, hi), 0.5f);
    const double extent = std::max(1e-6, (double)v3_length(v3_sub(hi, lo)) + v3_length(v3_sub(centre, c.position)));

    tinygltf::Camera cam;
    cam.type = "perspective";
    cam.perspective.yfov = c.yfov;
    cam.perspective.aspectRatio = (double)c.width / (double)c.height;
    cam.perspective.znear = 1e-4 * extent;
    cam.perspective.zfar = 1e3 * extent;
    model.cameras.push_back(cam);

    tinygltf::Node node;
    node.name = "camera";
    node.camera = (int)model.cameras.size() - 1;
    node.translation = {c.position.x, c.position.y, c.position.z};
    node.rotation.assign(q, q + 4);
    model.nodes.push_back(node);
    *node_out = (int)model.nodes.size() - 1;
    return 0;
}

int check_writable_scene(const scene *s, const char *path, gt_error *e)
{
    for (int i = 0; i < s->mesh_count; ++i)
        if (s->meshes[i].material < -1 || s->meshes[i].material >= s->material_count)
            return gt_error_set(e, path, "mesh %d: material %d does not exist", i, s->meshes[i].material);
    for (int i = 0; i < s->material_count; ++i) {
        const scene_material &m = s->materials[i];
        if (m.base_color_texture < -1 || m.base_color_texture >= s->texture_count ||
            m.metallic_roughness_texture < -1 || m.metallic_roughness_texture >= s->texture_count)
            return gt_error_set(e, path, "material %d refers to a texture that does not exist", i);
    }
    for (int i = 0; i < s->texture_count; ++i)
        if (s->textures[i].width <= 0 || s->textures[i].height <= 0 || !s->textures[i].rgba)
            return gt_error_set(e, path, "texture %d is empty", i);
    return 0;
}

int build_model(const scene *s, const char *path, gt_error *e, tinygltf::Model &model)
{
    if (check_writable_scene(s, path, e) != 0)
        return -1;
    model.asset.version = "2.0";
    model.asset.generator = "gtlab";
    model.buffers.resize(1);
    tinygltf::Scene root;
    for (int i = 0; i < s->mesh_count; ++i) {
        const scene_mesh *m = &s->meshes[i];
        if (m->vertex_count == 0 || m->triangle_count == 0) /* glTF accessors must not be empty */
            continue;
        write_mesh(model, m);
        tinygltf::Node node;
        node.mesh = (int)model.meshes.size() - 1;
        model.nodes.push_back(node);
        root.nodes.push_back((int)model.nodes.size() - 1);
    }
    for (int i = 0; i < s->material_count; ++i)
        write_material(model, s->materials[i], s->alpha_cutoff ? s->alpha_cutoff[i] : 0.0f);
    for (int i = 0; i < s->texture_count; ++i)
        write_texture(model, s->textures[i]);
    if (s->has_camera) {
        int node;
        if (write_camera(model, s, path, e, &node) != 0)
            return -1;
        root.nodes.push_back(node);
    }
    model.scenes.push_back(root);
    model.defaultScene = 0;
    if (model.buffers[0].data.size() > UINT32_MAX - 1024)
        return gt_error_set(e, path, "scene too large for a .glb (4 GiB limit)");
    return 0;
}

int write_atomically(const char *path, const std::string &bytes, gt_error *e)
{
    return atomic_write_bytes(path, bytes.data(), bytes.size(), e);
}

} // namespace

extern "C" int gltf_write_glb(const char *path, const scene *s, gt_error *e)
{
    try {
        tinygltf::Model model;
        if (build_model(s, path, e, model) != 0)
            return -1;
        std::ostringstream out;
        tinygltf::TinyGLTF gltf;
        if (!gltf.WriteGltfSceneToStream(&model, out, false, true))
            return gt_error_set(e, path, "tinygltf could not serialise the scene");
        return write_atomically(path, out.str(), e);
    } catch (const std::bad_alloc &) {
        return gt_error_set(e, path, "out of memory");
    } catch (const std::exception &x) {
        return gt_error_set(e, path, "cannot write glTF: %s", x.what());
    }
}
