/* glTF 2.0 in through tinygltf: the thin C++ adapter behind
 * scene/gltf/gltf_reader.h (the writer is gltf_writer.cpp; the two share no code).
 * This file parses (the JSON gate, the prepass, tinygltf), checks the node
 * tree, converts materials and walks the scene; accessor data is read in
 * gltf_accessors.cpp and a primitive's geometry in gltf_primitive.cpp, with
 * the shared parts in gltf_loader.hpp.
 *
 * tinygltf parses the JSON, the buffers (external, data: URI, GLB chunk) and
 * decodes images with stb_image, but it validates little of what the indices
 * and byte ranges in the file point at (node children, mesh and accessor
 * indices, accessor and bufferView extents). Everything taken from the model
 * is therefore checked here before it is used, so that a broken file gives one
 * error naming the file and the problem instead of undefined behaviour.
 * Reference: the glTF 2.0 specification (Khronos, version 2.0.1), sections
 * "Nodes and Hierarchy", "Transformations", "Accessors", "Meshes",
 * "Materials", "Cameras" and "GLB File Format Specification". */
#include <nlohmann/json.hpp>
#include <stb/stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

extern "C" {
#include "core/files/input_file.h"
#include "core/files/json_check.h"
#include "scene/gltf/glb_container.h"
#include "scene/gltf/gltf_json_prepass.h"
#include "scene/gltf/primitive_topology.h"
}
#include "scene/gltf/gltf_loader.hpp"

namespace gltf_detail {

/* ------------------------------------------------------------ small helpers */

/* Input that tinygltf quotes in its messages ("Got \"<type>\"") is cut to
 * GT_QUOTE_MAX characters, as gtlab's own messages cut it (core/error.h), and
 * so is any run of text without spaces. */
std::string shorten_quotes(const std::string &text)
{
    std::string out;
    size_t run = 0;        /* characters since the last space or quote */
    bool quoted = false;   /* inside "..." */
    bool cut = false;      /* the current run or quote has been cut */
    for (char c : text) {
        const bool boundary = c == '"' || (!quoted && c == ' ');
        if (boundary) {
            quoted = c == '"' ? !quoted : quoted;
            run = 0, cut = false;
        } else if ((c & 0xC0) != 0x80 && ++run > GT_QUOTE_MAX) {
            if (!cut)
                out += "...";
            cut = true;
        }
        if (!cut || boundary)
            out += c;
    }
    return out;
}

/* tinygltf's messages are multi-line and may quote a whole data: URI; the
 * CLI prints errors as one short line. */
std::string one_line(const std::string &text)
{
    std::string out, line;
    std::istringstream lines(text);
    while (std::getline(lines, line)) {
        while (!line.empty() && std::isspace((unsigned char)line.back()))
            line.pop_back();
        if (line.empty())
            continue;
        out += (out.empty() ? "" : "; ") + line;
    }
    for (size_t at = out.find("base64,"); at != std::string::npos; at = out.find("base64,", at + 1)) {
        const size_t begin = at + 7, keep = 16;
        size_t end = begin;
        while (end < out.size() && (std::isalnum((unsigned char)out[end]) || out[end] == '+' || out[end] == '/' ||
                                    out[end] == '='))
            ++end;
        if (end - begin > keep)
            out.replace(begin + keep, end - begin - keep, "...");
    }
    return shorten_quotes(out);
}

std::string directory_of(const char *path)
{
    const char *slash = std::strrchr(path, '/');
    if (!slash)
        return "";
    if (slash == path)
        return "/";
    return std::string(path, (size_t)(slash - path));
}

bool has_extension(const char *path, const char *ext)
{
    size_t n = std::strlen(path), k = std::strlen(ext);
    if (n < k)
        return false;
    for (size_t i = 0; i < k; ++i)
        if (std::tolower((unsigned char)path[n - k + i]) != ext[i])
            return false;
    return true;
}

/* Largest glTF/GLB file gtlab reads: a GLB's length field is 32-bit and
 * tinygltf takes the size as an unsigned int. */
const size_t max_gltf_bytes = (size_t)UINT32_MAX;

/* tinygltf's FileExists opens the file (fopen), which blocks on a FIFO. */
bool named_file_exists(const std::string &path, void *) { return access(path.c_str(), F_OK) == 0; }

/* tinygltf's ReadWholeFile for the buffers and images a .gltf names: only
 * regular files (core/files/input_file.h), so a `"uri": "/dev/zero"` cannot grow
 * gtlab without end, nor a FIFO hang it. */
bool read_named_file(std::vector<unsigned char> *out, std::string *err, const std::string &path, void *)
{
    char *bytes;
    size_t size;
    gt_error e;
    if (input_file_read(path.c_str(), max_gltf_bytes, "larger than 4 GiB", &bytes, &size, &e) != 0) {
        if (err)
            *err += e.message;
        return false;
    }
    out->assign(bytes, bytes + size);
    std::free(bytes);
    return true;
}

/* Largest texture side gtlab decodes: a crafted header cannot make the
 * decoder allocate gigabytes for one image. (Lower in the fuzz build, see
 * cmake/gtlab_fuzz.cmake, so that such headers cost the fuzzer no time.) */
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
const int max_texture_side = 1024;
#else
const int max_texture_side = 16384;
#endif

/* Whether the encoded image is one gtlab hands to stb_image: PNG or JPEG
 * (the only image formats of core glTF 2.0, "Images"), of a sane size by its
 * header. Otherwise *why says what it is not. */
bool image_decodable(const unsigned char *bytes, int size, std::string *why)
{
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char jpeg[3] = {0xff, 0xd8, 0xff};
    const bool is_png = size >= 8 && std::memcmp(bytes, png, 8) == 0;
    const bool is_jpeg = size >= 3 && std::memcmp(bytes, jpeg, 3) == 0;
    int width = 0, height = 0, components = 0;
    if (!is_png && !is_jpeg)
        *why = "is neither PNG nor JPEG";
    else if (!stbi_info_from_memory(bytes, size, &width, &height, &components))
        *why = std::string("has a broken ") + (is_png ? "PNG" : "JPEG") + " header";
    else if (width > max_texture_side || height > max_texture_side)
        *why = "is " + std::to_string(width) + "x" + std::to_string(height) + " pixels, larger than gtlab reads (" +
               std::to_string(max_texture_side) + " per side)";
    else
        return true;
    return false;
}

/* tinygltf's image callback. It runs while the model is parsed, after the
 * buffers and bufferViews: an image stored in a bufferView is checked to lie
 * inside its buffer (tinygltf does not check the extent), then decoded to
 * 8- or 16-bit RGBA by tinygltf's own stb_image decoder. An image that does
 * not decode is not fatal: the reason is kept and the material falls back to
 * its factor (with a warning, if the image is used). */
bool load_image(tinygltf::Image *image, const int index, std::string *err, std::string *warn, int req_width,
                int req_height, const unsigned char *bytes, int size, void *user_data)
{
    Loader *L = static_cast<Loader *>(user_data);
    if (image->bufferView >= 0) {
        const tinygltf::BufferView &view = L->model.bufferViews[(size_t)image->bufferView];
        const tinygltf::Buffer &buffer = L->model.buffers[(size_t)view.buffer];
        if (!range_inside(view.byteOffset, view.byteLength, buffer.data.size())) {
            *err += "image " + std::to_string(index) + ": bufferView " + std::to_string(image->bufferView) +
                    " lies outside its buffer";
            return false;
        }
    }
    std::string why;
    if (!image_decodable(bytes, size, &why))
        L->image_problem[index] = "cannot be decoded (it " + why + ")";
    else if (!tinygltf::LoadImageData(image, index, &why, warn, req_width, req_height, bytes, size, nullptr))
        L->image_problem[index] = "cannot be decoded (" + one_line(why) + ")";
    return true;
}

/* The extensions gtlab reads: a file may require them. */
bool supported_extension(const std::string &name)
{
    return name == "KHR_mesh_quantization" || name == "EXT_meshopt_compression" ||
           name == "KHR_draco_mesh_compression" || name == "KHR_texture_transform";
}

/* Extensions that store data gtlab cannot decode, with what they hold. */
const std::map<std::string, const char *> &data_extensions()
{
    static const std::map<std::string, const char *> contents = {
        {"KHR_texture_basisu", "Basis Universal textures"},
        {"EXT_texture_webp", "WebP textures"},
        {"EXT_mesh_gpu_instancing", "instanced meshes"},
        {"KHR_meshopt_compression", "meshoptimizer-compressed buffers, ratified form"},
    };
    return contents;
}

/* An extension's name for a message, with what it holds when known. */
std::string extension_with_content(const std::string &name)
{
    auto it = data_extensions().find(name);
    return printable(name) + (it != data_extensions().end() ? std::string(" (") + it->second + ")" : "");
}

/* "the glTF extension A (what it holds)" or "the glTF extensions A, B and 2 more". */
std::string extension_list(const std::vector<std::string> &names)
{
    const size_t shown = std::min<size_t>(names.size(), 3);
    std::string out = names.size() > 1 ? "the glTF extensions " : "the glTF extension ";
    for (size_t i = 0; i < shown; ++i)
        out += (i ? ", " : "") + extension_with_content(names[i]);
    if (names.size() > shown)
        out += " and " + std::to_string(names.size() - shown) + " more";
    return out;
}

/* A required extension gtlab does not read refuses the file. */
int refuse_required_extensions(Loader &L, std::vector<std::string> required)
{
    required.erase(std::remove_if(required.begin(), required.end(), supported_extension), required.end());
    if (required.empty())
        return 0;
    return L.fail("requires %s, which gtlab does not support", extension_list(required).c_str());
}

/* The strings of the top-level array `key` of the JSON text, which
 * json_check has accepted (so parsing cannot fail or recurse deeply). */
std::vector<std::string> top_level_strings(const unsigned char *json, size_t length, const char *key)
{
    std::vector<std::string> names;
    const nlohmann::json doc = nlohmann::json::parse(json, json + length, nullptr, false);
    if (!doc.is_object())
        return names;
    auto it = doc.find(key);
    if (it == doc.end() || !it->is_array())
        return names;
    for (const auto &v : *it)
        if (v.is_string())
            names.push_back(v.get<std::string>());
    return names;
}

/* tinygltf refused the file: its own message, naming any extension the file
 * uses whose data gtlab cannot decode (it may be why). */
int fail_tinygltf(Loader &L, bool binary, const unsigned char *json, size_t json_length, const std::string &err)
{
    std::string reason = err.empty() ? "no reason given" : one_line(err);
    std::vector<std::string> used = top_level_strings(json, json_length, "extensionsUsed");
    used.erase(std::remove_if(used.begin(), used.end(),
                              [](const std::string &name) { return data_extensions().count(name) == 0; }),
               used.end());
    if (!used.empty())
        reason += "; the file uses " + extension_list(used) + ", which gtlab does not support";
    return L.fail("%s: %s", binary ? "cannot load binary glTF" : "cannot load glTF", reason.c_str());
}

/* The asset's glTF version, which the glTF 2.0 specification requires
 * (asset.version, "2.0"; section 5.3): a glTF 1.0 file (asset.version
 * "1.0", or without an asset and with its scenes or meshes as objects keyed
 * by id, 1.0's layout) is refused in those words, not by what tinygltf's
 * 2.0 reader trips over first. The JSON has passed the gate. */
int refuse_other_versions(Loader &L, const unsigned char *json, size_t length)
{
    const nlohmann::json doc = nlohmann::json::parse(json, json + length, nullptr, false);
    if (!doc.is_object())
        return 0;
    auto asset = doc.find("asset");
    std::string version;
    if (asset != doc.end() && asset->is_object() && asset->contains("version") && (*asset)["version"].is_string())
        version = (*asset)["version"].get<std::string>();
    bool keyed_by_id = (doc.contains("scenes") && doc["scenes"].is_object()) ||
                       (doc.contains("meshes") && doc["meshes"].is_object());
    if (version.empty() && keyed_by_id)
        version = "1.0";
    if (version.empty() || version.rfind("2.", 0) == 0)
        return 0;
    return L.fail("glTF %s is not supported: gtlab reads glTF 2.0 (convert the file, e.g. by importing it into "
                  "Blender and exporting glTF 2.0)",
                  printable(version).c_str());
}

/* The JSON of the file (all of a .gltf, the JSON chunk of a .glb) must pass
 * the JSON gate (core/files/json_check.h) before tinygltf's recursive parser sees
 * it, and a GLB's chunks must lie inside the file. */
int check_container(Loader &L, const unsigned char *bytes, size_t size, bool binary, const unsigned char **json,
                    size_t *json_length)
{
    if (!binary && has_extension(L.path, ".glb"))
        return L.fail("not a binary glTF file (no \"glTF\" magic; empty or truncated?)");
    if (size > UINT32_MAX)
        return L.fail("file too large for glTF (4 GiB or more)");
    glb_chunks chunks = {bytes, nullptr, size, 0};
    if (binary && glb_split(bytes, size, L.path, &chunks, L.e) != 0)
        return -1;
    *json = chunks.json;
    *json_length = chunks.json_length;
    return json_check(reinterpret_cast<const char *>(*json), *json_length, json_limits_gltf, L.path, L.e);
}

/* The file as tinygltf is given it, in `out`, when the JSON prepass
 * (gltf_json_prepass.h) rewrote it; out stays empty when the file is fine
 * as it is. */
int prepare_for_tinygltf(Loader &L, const unsigned char *bytes, size_t size, bool binary, const unsigned char *json,
                         size_t json_length, std::vector<unsigned char> &out)
{
    char *text = nullptr;
    size_t length = 0;
    const int rc = gltf_json_prepass(json, json_length, &text, &length);
    if (rc <= 0)
        return rc < 0 ? L.fail("out of memory") : 0;
    if (!binary) {
        out.assign(text, text + length);
        std::free(text);
        return 0;
    }
    glb_chunks chunks;
    glb_split(bytes, size, L.path, &chunks, L.e); /* it succeeded in check_container */
    chunks.json = reinterpret_cast<unsigned char *>(text);
    chunks.json_length = length;
    size_t joined_size = 0;
    unsigned char *joined = glb_join(&chunks, &joined_size);
    std::free(text);
    if (!joined)
        return L.fail("out of memory");
    out.assign(joined, joined + joined_size);
    std::free(joined);
    return 0;
}

/* The file's extensionsUsed, for the report; KHR_mesh_quantization among
 * them lets accessors hold its integer types. */
void note_extensions_used(Loader &L)
{
    std::string list;
    for (const std::string &name : L.model.extensionsUsed) {
        list += (list.empty() ? "" : ", ") + printable(name);
        L.quantization = L.quantization || name == "KHR_mesh_quantization";
    }
    std::snprintf(L.report->extensions_used, sizeof L.report->extensions_used, "%s", list.c_str());
}

int parse_bytes(Loader &L, const unsigned char *bytes, size_t size, const std::string &base_dir)
{
    const bool binary = glb_has_magic(bytes, size);
    const unsigned char *json = nullptr;
    size_t json_length = 0;
    if (check_container(L, bytes, size, binary, &json, &json_length) != 0 ||
        refuse_other_versions(L, json, json_length) != 0 ||
        refuse_required_extensions(L, top_level_strings(json, json_length, "extensionsRequired")) != 0)
        return -1;
    std::vector<unsigned char> prepared;
    if (prepare_for_tinygltf(L, bytes, size, binary, json, json_length, prepared) != 0)
        return -1;
    if (!prepared.empty()) {
        bytes = prepared.data();
        size = prepared.size();
    }
    tinygltf::TinyGLTF gltf;
    gltf.SetImageLoader(load_image, &L);
    gltf.SetFsCallbacks({&named_file_exists, &tinygltf::ExpandFilePath, &read_named_file,
                         &tinygltf::WriteWholeFile, nullptr});
    std::string err, warn;
    const unsigned int n = (unsigned int)size;
    bool ok = binary ? gltf.LoadBinaryFromMemory(&L.model, &err, &warn, bytes, n, base_dir)
                     : gltf.LoadASCIIFromString(&L.model, &err, &warn, reinterpret_cast<const char *>(bytes), n,
                                                base_dir);
    if (!ok)
        return fail_tinygltf(L, binary, json, json_length, err);
    /* tinygltf's warnings are about images it could not read; those that
     * matter (images a material uses) are reported by convert_texture. */
    if (refuse_required_extensions(L, L.model.extensionsRequired) != 0)
        return -1;
    note_extensions_used(L);
    return decode_meshopt_views(L);
}

/* The node graph must be a forest (glTF 2.0 "Nodes and Hierarchy": "the node hierarchy
 * MUST be a set of disjoint strict trees"). tinygltf does not check child
 * indices or cycles; a cycle would make the traversal endless. With at most one
 * parent per node, every node that no root reaches lies on or below a cycle. */
int check_node_graph(Loader &L)
{
    const int n = (int)L.model.nodes.size();
    L.parent.assign((size_t)n, -1);
    for (int i = 0; i < n; ++i)
        for (int child : L.model.nodes[(size_t)i].children) {
            if (child < 0 || child >= n)
                return L.fail("node %d: child %d does not exist (%d nodes)", i, child, n);
            int &p = L.parent[(size_t)child];
            if (p == i)
                return L.fail("node %d lists child %d twice", i, child);
            if (p >= 0)
                return L.fail("node %d has two parents (nodes %d and %d); glTF node hierarchies must be trees",
                              child, p, i);
            p = i;
        }
    std::vector<char> reached((size_t)n, 0);
    std::vector<int> stack;
    for (int i = 0; i < n; ++i)
        if (L.parent[(size_t)i] < 0)
            stack.push_back(i);
    while (!stack.empty()) {
        int node = stack.back();
        stack.pop_back();
        reached[(size_t)node] = 1;
        for (int child : L.model.nodes[(size_t)node].children)
            stack.push_back(child);
    }
    for (int i = 0; i < n; ++i)
        if (!reached[(size_t)i]) {
            int on_cycle = i; /* n steps up from any unreached node land on the cycle */
            for (int k = 0; k < n; ++k)
                on_cycle = L.parent[(size_t)on_cycle];
            return L.fail("node graph has a cycle (node %d is its own ancestor)", on_cycle);
        }
    return 0;
}

/* Counts normals that cannot be used at all (zero or degenerate after the
 * transform); those make the whole primitive's normals be recomputed. */
size_t transform_normals(const Mat4 &world, const std::vector<float> &in, scene_mesh *m)
{
    double cof[9];
    mat4_cofactor3(world, cof);
    const double sign = mat4_det3(world) < 0.0 ? -1.0 : 1.0;
    size_t bad = 0;
    for (uint32_t i = 0; i < m->vertex_count; ++i) {
        const float *n = &in[3 * (size_t)i];
        double r[3];
        for (int row = 0; row < 3; ++row)
            r[row] = sign * (cof[row] * n[0] + cof[3 + row] * n[1] + cof[6 + row] * n[2]);
        const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
        if (!(len > 0.0) || !std::isfinite(len)) {
            ++bad;
            continue;
        }
        v3_store(&m->normals[3 * (size_t)i], v3((float)(r[0] / len), (float)(r[1] / len), (float)(r[2] / len)));
    }
    return bad;
}

int add_world_mesh(Loader &L, const std::string &what, const Primitive &p, const Mat4 &world, int material)
{
    const uint32_t vertex_count = (uint32_t)(p.positions.size() / 3);
    const uint32_t triangle_count = (uint32_t)(p.indices.size() / 3);
    scene_mesh *m = scene_add_mesh(L.s, vertex_count, triangle_count, !p.texcoords.empty());
    if (!m)
        return L.fail("out of memory");
    m->material = material;
    for (uint32_t i = 0; i < vertex_count; ++i)
        v3_store(&m->positions[3 * (size_t)i], mat4_point(world, &p.positions[3 * (size_t)i]));
    if (!p.texcoords.empty()) {
        std::copy(p.texcoords.begin(), p.texcoords.end(), m->texcoords);
        if (material >= 0)
            uv_transform_apply(&L.material_uv[(size_t)material], m->texcoords, vertex_count);
    }
    /* A mirroring transform (det < 0) turns counter-clockwise triangles
     * clockwise; swapping two corners keeps the geometric normal on the side
     * of the transformed shading normals. */
    const bool mirrored = mat4_det3(world) < 0.0;
    for (uint32_t t = 0; t < triangle_count; ++t) {
        const uint32_t *src = &p.indices[3 * (size_t)t];
        uint32_t *dst = &m->indices[3 * (size_t)t];
        dst[0] = src[0];
        dst[1] = mirrored ? src[2] : src[1];
        dst[2] = mirrored ? src[1] : src[2];
    }
    if (p.normals.empty()) {
        /* Flat: the world-space triangles' face normals, normalised as a
         * file's normals are, so a file that carries these normals loads to
         * the same bits. */
        scene_mesh_compute_flat_normals(m);
        const std::vector<float> face(m->normals, m->normals + 3 * (size_t)vertex_count);
        transform_normals(mat4_identity(), face, m);
    } else if (mat4_det3(world) == 0.0) {
        gt_warn(L.path, "%s: its node transform is singular (flattens the mesh); normals recomputed", what.c_str());
        scene_mesh_compute_normals(m);
    } else {
        const size_t bad = transform_normals(world, p.normals, m);
        if (bad > 0) {
            gt_warn(L.path, "%s: %zu of %u normals are zero or not finite; normals recomputed from the triangles",
                    what.c_str(), bad, vertex_count);
            scene_mesh_compute_normals(m);
        }
    }
    return 0;
}

/* ------------------------------------------------------- materials/images */

int add_texture_from_image(Loader &L, const tinygltf::Image &image, int *out)
{
    const size_t texels = (size_t)image.width * (size_t)image.height;
    const size_t bytes_per_channel = image.bits == 16 ? 2 : 1;
    if (image.component != 4 || image.image.size() != texels * 4 * bytes_per_channel)
        return L.fail("image decoded to an unexpected layout (%d channels, %d bits)", image.component, image.bits);
    unsigned char *rgba = (unsigned char *)std::malloc(texels * 4 + 1);
    if (!rgba)
        return L.fail("out of memory");
    scene_texture *grown =
        (scene_texture *)std::realloc(L.s->textures, sizeof *grown * (size_t)(L.s->texture_count + 1));
    if (!grown) {
        std::free(rgba);
        return L.fail("out of memory");
    }
    L.s->textures = grown;
    for (size_t i = 0; i < texels * 4; ++i) {
        if (bytes_per_channel == 2) { /* 16-bit PNG: round to the nearest 8-bit level */
            uint16_t u;
            std::memcpy(&u, &image.image[2 * i], 2);
            rgba[i] = (unsigned char)((u + 128u) / 257u);
        } else {
            rgba[i] = image.image[i];
        }
    }
    scene_texture *t = &L.s->textures[L.s->texture_count];
    t->width = image.width;
    t->height = image.height;
    t->rgba = rgba;
    *out = L.s->texture_count++;
    return 0;
}

/* Resolves a material's texture reference to a scene texture, or -1 when the
 * material must render with its factor alone (warned). Broken indices are
 * errors. */
int convert_texture(Loader &L, int material, const char *slot, const tinygltf::TextureInfo &info, int *out)
{
    *out = -1;
    if (info.index < 0)
        return 0;
    const tinygltf::Model &m = L.model;
    if ((size_t)info.index >= m.textures.size())
        return L.fail("material %d: %s: texture %d does not exist", material, slot, info.index);
    const int source = m.textures[(size_t)info.index].source;
    if (source < 0) {
        gt_warn(L.path, "material %d: %s: texture %d has no image gtlab can read; using the factor alone", material,
                slot, info.index);
        return 0;
    }
    if ((size_t)source >= m.images.size())
        return L.fail("material %d: %s: texture %d: image %d does not exist", material, slot, info.index, source);
    if (info.texCoord != 0) {
        gt_warn(L.path, "material %d: %s uses TEXCOORD_%d (only TEXCOORD_0 is supported); using the factor alone",
                material, slot, info.texCoord);
        return 0;
    }
    const tinygltf::Image &image = m.images[(size_t)source];
    if (image.image.empty()) {
        auto why = L.image_problem.find(source);
        const std::string name =
            printable(!image.uri.empty() ? image.uri : !image.name.empty() ? image.name : "embedded");
        gt_warn(L.path, "material %d: %s: image %d (%s) %s; using the factor alone", material, slot, source,
                name.c_str(), why != L.image_problem.end() ? why->second.c_str() : "could not be read");
        return 0;
    }
    int &cached = L.image_texture[(size_t)source];
    if (cached < 0 && add_texture_from_image(L, image, &cached) != 0)
        return -1;
    *out = cached;
    return 0;
}

/* The slot's KHR_texture_transform (identity without one). */
int texture_transform(Loader &L, int material, const char *slot, const tinygltf::TextureInfo &info, uv_transform *out)
{
    *out = uv_transform_identity();
    const tinygltf::Value *ext = extension(info.extensions, "KHR_texture_transform");
    if (!ext)
        return 0;
    static const double zero[2] = {0, 0}, one[2] = {1, 1};
    double offset[2], rotation, scale[2];
    if (!member_numbers(*ext, "offset", 2, zero, offset) || !member_numbers(*ext, "rotation", 1, zero, &rotation) ||
        !member_numbers(*ext, "scale", 2, one, scale))
        return L.fail("material %d: %s: KHR_texture_transform has an offset, rotation or scale that is not numbers",
                      material, slot);
    if (member_count(*ext, "texCoord", 0) != 0)
        gt_warn(L.path, "material %d: %s: KHR_texture_transform selects another TEXCOORD set (only TEXCOORD_0 is "
                        "read); its transform is applied to TEXCOORD_0", material, slot);
    *out = uv_transform_from_khr(offset, rotation, scale);
    return 0;
}

/* A mesh has one set of texture coordinates, so a material's textures must
 * share their transform: the base colour texture's wins, with a warning. */
int material_uv_transform(Loader &L, int material, const tinygltf::PbrMetallicRoughness &pbr, uv_transform *out)
{
    uv_transform color, mr;
    if (texture_transform(L, material, "baseColorTexture", pbr.baseColorTexture, &color) != 0 ||
        texture_transform(L, material, "metallicRoughnessTexture", pbr.metallicRoughnessTexture, &mr) != 0)
        return -1;
    const bool both = pbr.baseColorTexture.index >= 0 && pbr.metallicRoughnessTexture.index >= 0;
    if (both && !uv_transform_equal(&color, &mr))
        gt_warn(L.path, "material %d: its textures have different KHR_texture_transform; using baseColorTexture's",
                material);
    *out = pbr.baseColorTexture.index >= 0 ? color : mr;
    return 0;
}

/* alphaMode MASK: the material's alphaCutoff (glTF 2.0, "Alpha Coverage";
 * default 0.5). BLEND is drawn opaque (no sorted transparency here). */
static int alpha_mask(Loader &L, int i)
{
    const tinygltf::Material &m = L.model.materials[(size_t)i];
    if (m.alphaMode != "MASK")
        return 0;
    if (!std::isfinite(m.alphaCutoff) || m.alphaCutoff < 0.0)
        return L.fail("material %d has a bad alphaCutoff", i);
    return scene_set_alpha_cutoff(L.s, i, (float)m.alphaCutoff) == 0 ? 0 : L.fail("out of memory");
}

/* glTF materials become scene materials with the same indices. */
int convert_materials(Loader &L)
{
    L.image_texture.assign(L.model.images.size(), -1);
    L.material_uv.assign(L.model.materials.size(), uv_transform_identity());
    for (size_t i = 0; i < L.model.materials.size(); ++i) {
        const tinygltf::PbrMetallicRoughness &pbr = L.model.materials[i].pbrMetallicRoughness;
        scene_material sm = scene_default_material();
        bool finite = std::isfinite(pbr.metallicFactor) && std::isfinite(pbr.roughnessFactor);
        for (int k = 0; k < 4; ++k) {
            sm.base_color[k] = (float)pbr.baseColorFactor[(size_t)k];
            finite = finite && std::isfinite(pbr.baseColorFactor[(size_t)k]);
        }
        if (!finite)
            return L.fail("material %zu has non-finite factors", i);
        sm.metallic = (float)pbr.metallicFactor;
        sm.roughness = (float)pbr.roughnessFactor;
        if (convert_texture(L, (int)i, "baseColorTexture", pbr.baseColorTexture, &sm.base_color_texture) != 0 ||
            convert_texture(L, (int)i, "metallicRoughnessTexture", pbr.metallicRoughnessTexture,
                            &sm.metallic_roughness_texture) != 0 ||
            material_uv_transform(L, (int)i, pbr, &L.material_uv[i]) != 0)
            return -1;
        if (scene_add_material(L.s, sm) < 0)
            return L.fail("out of memory");
        if (alpha_mask(L, (int)i) != 0)
            return -1;
    }
    return 0;
}

/* ------------------------------------------------------------- traversal */

/* Triangle primitives (modes 4-6) become meshes; points and lines are
 * skipped with a warning (once per mesh). */
int add_node_meshes(Loader &L, int node_index, const Mat4 &world)
{
    const tinygltf::Node &node = L.model.nodes[(size_t)node_index];
    if (node.mesh < 0)
        return 0;
    if ((size_t)node.mesh >= L.model.meshes.size())
        return L.fail("node %d: mesh %d does not exist", node_index, node.mesh);
    const tinygltf::Mesh &mesh = L.model.meshes[(size_t)node.mesh];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive &prim = mesh.primitives[p];
        const std::string what = "mesh " + std::to_string(node.mesh) +
                                 (mesh.name.empty() ? "" : " (" + printable(mesh.name) + ")") + " primitive " +
                                 std::to_string(p);
        if (prim.mode >= 0 && prim.mode < 7)
            ++L.report->primitives_by_mode[prim.mode];
        if (!gltf_mode_has_triangles(prim.mode)) {
            if (!L.warned_mode[(size_t)node.mesh])
                gt_warn(L.path, "%s: mode %d (%s) is not triangles; skipped", what.c_str(), prim.mode,
                        mode_name(prim.mode));
            L.warned_mode[(size_t)node.mesh] = true;
            continue;
        }
        if (prim.material < -1 || prim.material >= (int)L.model.materials.size())
            return L.fail("%s: material %d does not exist", what.c_str(), prim.material);
        Primitive data;
        if (read_primitive(L, what, node, mesh, prim, data) != 0)
            return -1;
        const Mat4 placed = data.skinned ? mat4_identity() : world;
        if (add_world_mesh(L, what, data, placed, prim.material) != 0)
            return -1;
        L.report->position_step = std::max(L.report->position_step, L.position_step * mat4_largest_scale(placed));
    }
    return 0;
}

/* The camera at a node looks down the node's local -Z with local +Y up
 * (glTF 2.0 "Cameras"). */
int set_camera(Loader &L, int node_index, const Mat4 &world)
{
    const int index = L.model.nodes[(size_t)node_index].camera;
    if ((size_t)index >= L.model.cameras.size())
        return L.fail("node %d: camera %d does not exist", node_index, index);
    const tinygltf::Camera &c = L.model.cameras[(size_t)index];
    if (c.type != "perspective") {
        if (!L.warned_orthographic)
            gt_warn(L.path, "camera %d is %s; only perspective cameras are used", index, printable(c.type).c_str());
        L.warned_orthographic = true;
        return 0;
    }
    const double yfov = c.perspective.yfov, aspect = c.perspective.aspectRatio;
    if (!((float)yfov > 0.0f && yfov < M_PI))
        return L.fail("camera %d: yfov %g is not in (0, pi)", index, yfov);
    if (aspect != 0.0 && !(aspect > 0.0 && std::isfinite(aspect)))
        return L.fail("camera %d: aspectRatio %g is not positive", index, aspect);
    const float origin[3] = {0, 0, 0};
    vec3 position = mat4_point(world, origin);
    vec3 forward = mat4_direction(world, 0, 0, -1), up = mat4_direction(world, 0, 1, 0);
    if (!(v3_length(forward) > 0.0f) || !(v3_length(up) > 0.0f) || !v3_is_finite(position))
        return L.fail("node %d: camera transform is degenerate", node_index);
    camera *cam = &L.s->camera;
    cam->position = position;
    cam->target = v3_add(position, v3_normalize(forward));
    cam->up = v3_normalize(up);
    cam->yfov = (float)yfov;
    cam->width = 512;
    cam->height = aspect > 0.0 ? (int)std::min(65536.0, std::max(1.0, std::round(512.0 / aspect))) : 512;
    L.s->has_camera = 1;
    return 0;
}

int scene_roots(Loader &L, std::vector<int> &roots)
{
    const tinygltf::Model &m = L.model;
    if (m.scenes.empty()) { /* no scenes: every root node */
        for (size_t i = 0; i < m.nodes.size(); ++i)
            if (L.parent[i] < 0)
                roots.push_back((int)i);
        return 0;
    }
    const int chosen = m.defaultScene >= 0 ? m.defaultScene : 0;
    if (m.defaultScene < -1 || (size_t)chosen >= m.scenes.size())
        return L.fail("default scene %d does not exist (%zu scenes)", m.defaultScene, m.scenes.size());
    std::vector<char> listed(m.nodes.size(), 0);
    for (int node : m.scenes[(size_t)chosen].nodes) {
        if (node < 0 || (size_t)node >= m.nodes.size())
            return L.fail("scene %d: node %d does not exist", chosen, node);
        if (L.parent[(size_t)node] >= 0)
            return L.fail("scene %d lists node %d as a root, but it is a child of node %d", chosen, node,
                          L.parent[(size_t)node]);
        if (listed[(size_t)node])
            return L.fail("scene %d lists node %d twice", chosen, node);
        listed[(size_t)node] = 1;
        roots.push_back(node);
    }
    return 0;
}

/* Depth-first, parents before children, in file order: the first perspective
 * camera met is the scene camera. Iterative, so that a deep hierarchy cannot
 * overflow the stack; check_node_graph guarantees termination. */
int flatten(Loader &L)
{
    std::vector<int> roots;
    if (scene_roots(L, roots) != 0)
        return -1;
    L.warned_mode.assign(L.model.meshes.size(), false);
    L.world.assign(L.model.nodes.size(), mat4_identity());
    L.world_known.assign(L.model.nodes.size(), 0);
    std::vector<int> stack(roots.rbegin(), roots.rend());
    while (!stack.empty()) {
        const int index = stack.back();
        stack.pop_back();
        Mat4 world;
        if (world_of(L, index, &world) != 0)
            return -1;
        const tinygltf::Node &node = L.model.nodes[(size_t)index];
        if (add_node_meshes(L, index, world) != 0)
            return -1;
        const bool wanted = L.camera_wanted < 0 || node.camera == L.camera_wanted;
        if (node.camera >= 0 && wanted && !L.s->has_camera && set_camera(L, index, world) != 0)
            return -1;
        stack.insert(stack.end(), node.children.rbegin(), node.children.rend());
    }
    if (L.camera_wanted >= 0 && !L.s->has_camera)
        return L.fail("camera %d is not a perspective camera on a node of the scene", L.camera_wanted);
    return 0;
}

/* The camera asked for by name or index, checked to exist in the file. */
int resolve_camera(Loader &L)
{
    const size_t count = L.model.cameras.size();
    for (size_t i = 0; L.camera_name && i < count; ++i)
        if (L.model.cameras[i].name == L.camera_name)
            L.camera_wanted = (int)i;
    if (L.camera_name && L.camera_wanted < 0)
        return L.fail("no camera named '%s' (%zu cameras)", printable(L.camera_name).c_str(), count);
    if (L.camera_wanted >= 0 && (size_t)L.camera_wanted >= count)
        return L.fail("camera %d does not exist (%zu cameras)", L.camera_wanted, count);
    return 0;
}

int load(Loader &L, const unsigned char *bytes, size_t size, const std::string &base_dir)
{
    if (parse_bytes(L, bytes, size, base_dir) != 0 || resolve_camera(L) != 0 || check_node_graph(L) != 0 ||
        convert_materials(L) != 0 || flatten(L) != 0)
        return -1;
    return scene_validate(L.s, L.path, L.e);
}

int load_guarded(const unsigned char *bytes, size_t size, const char *name, const std::string &base_dir, scene *s,
                 gltf_report *report, const gltf_camera_choice *choice, gt_error *e)
{
    int rc;
    try {
        Loader L;
        L.path = name;
        L.e = e;
        L.s = s;
        L.report = report;
        L.camera_wanted = choice ? choice->index : -1;
        L.camera_name = choice ? choice->name : nullptr;
        const char *slash = std::strrchr(name, '/');
        std::snprintf(s->name, sizeof s->name, "%s", slash ? slash + 1 : name);
        rc = load(L, bytes, size, base_dir);
        report->sparse_accessors = (int)L.sparse_seen.size();
    } catch (const std::bad_alloc &) {
        rc = gt_error_set(e, name, "out of memory");
    } catch (const std::exception &x) { /* tinygltf throws on some malformed input */
        rc = gt_error_set(e, name, "cannot load glTF: malformed data (%s)", printable(x.what()).c_str());
    }
    return rc;
}

int load_memory(const void *bytes, size_t size, const char *name, const char *base_dir, scene *s,
                gltf_report *report, const gltf_camera_choice *choice, gt_error *e)
{
    gltf_report unused;
    report = report ? report : &unused;
    std::memset(report, 0, sizeof *report);
    std::memset(s, 0, sizeof *s);
    int rc = load_guarded(static_cast<const unsigned char *>(bytes), size, name, base_dir ? base_dir : "", s, report,
                          choice, e);
    if (rc != 0)
        scene_free(s);
    return rc;
}

} // namespace gltf_detail

using gltf_detail::directory_of;
using gltf_detail::load_memory;
using gltf_detail::max_gltf_bytes;

extern "C" int gltf_load_memory(const void *bytes, size_t size, const char *name, const char *base_dir, scene *s,
                                gt_error *e)
{
    return load_memory(bytes, size, name, base_dir, s, nullptr, nullptr, e);
}

/* Reads the file and loads it; choice may be NULL (the first camera met). */
static int load_file(const char *path, scene *s, gltf_report *report, const gltf_camera_choice *choice, gt_error *e)
{
    std::memset(s, 0, sizeof *s);
    int rc;
    try {
        char *bytes;
        size_t size;
        rc = input_file_read(path, max_gltf_bytes, "larger than 4 GiB: not a glTF file gtlab reads", &bytes, &size, e);
        if (rc == 0) {
            std::unique_ptr<char, void (*)(void *)> owned(bytes, std::free); /* freed on bad_alloc too */
            rc = load_memory(bytes, size, path, directory_of(path).c_str(), s, report, choice, e);
        }
    } catch (const std::bad_alloc &) {
        rc = gt_error_set(e, path, "out of memory");
    }
    return rc;
}

extern "C" int gltf_load_report(const char *path, scene *s, gltf_report *report, gt_error *e)
{
    return load_file(path, s, report, nullptr, e);
}

extern "C" int gltf_load(const char *path, scene *s, gt_error *e)
{
    return gltf_load_report(path, s, nullptr, e);
}

extern "C" int gltf_load_with_camera(const char *path, const gltf_camera_choice *choice, scene *s, gt_error *e)
{
    return load_file(path, s, nullptr, choice, e);
}
