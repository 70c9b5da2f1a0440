/* glTF 2.0 in through tinygltf: the thin C++ adapter behind
 * scene/gltf_reader.h (the writer is gltf_writer.cpp; the two share no code).
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
#include <new>
#include <sstream>
#include <string>
#include <vector>

extern "C" {
#include "core/json_check.h"
#include "scene/accessor_decode.h"
#include "scene/draco_decode.h"
#include "scene/glb_container.h"
#include "scene/gltf_json_prepass.h"
#include "scene/gltf_reader.h"
#include "scene/meshopt_decode.h"
#include "scene/primitive_topology.h"
#include "scene/uv_transform.h"
#include "scene/vertex_pose.h"
}
#include <set>

namespace {

/* ---------------------------------------------------------------- matrices */

/* 4x4 affine transform, column-major as glTF stores it: m[4 * column + row]. */
struct Mat4 {
    double m[16];
};

Mat4 mat4_identity()
{
    Mat4 r = {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}};
    return r;
}

Mat4 mat4_mul(const Mat4 &a, const Mat4 &b)
{
    Mat4 r;
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row) {
            double sum = 0.0;
            for (int k = 0; k < 4; ++k)
                sum += a.m[4 * k + row] * b.m[4 * c + k];
            r.m[4 * c + row] = sum;
        }
    return r;
}

/* T * R * S (glTF 2.0 "Transformations"), R from the unit quaternion (x, y, z, w). */
Mat4 mat4_trs(const double t[3], const double q[4], const double s[3])
{
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double rot[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                              {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                              {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    Mat4 r = mat4_identity();
    for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row)
            r.m[4 * c + row] = rot[row][c] * s[c];
    for (int row = 0; row < 3; ++row)
        r.m[12 + row] = t[row];
    return r;
}

vec3 mat4_point(const Mat4 &a, const float p[3])
{
    double r[3];
    for (int row = 0; row < 3; ++row)
        r[row] = a.m[row] * p[0] + a.m[4 + row] * p[1] + a.m[8 + row] * p[2] + a.m[12 + row];
    return v3((float)r[0], (float)r[1], (float)r[2]);
}

vec3 mat4_direction(const Mat4 &a, double x, double y, double z)
{
    double r[3];
    for (int row = 0; row < 3; ++row)
        r[row] = a.m[row] * x + a.m[4 + row] * y + a.m[8 + row] * z;
    return v3((float)r[0], (float)r[1], (float)r[2]);
}

double mat4_det3(const Mat4 &a)
{
    const double *m = a.m;
    return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
           m[8] * (m[1] * m[6] - m[5] * m[2]);
}

/* The cofactor matrix of the upper 3x3 part, cof(A) = det(A) A^-T: normals
 * transform by the inverse transpose, and the cofactor form needs no division
 * (the length is renormalised anyway; the sign of det is applied by the caller).
 * Returned as a 3x3 column-major array. */
void mat4_cofactor3(const Mat4 &a, double cof[9])
{
    auto e = [&a](int row, int col) { return a.m[4 * col + row]; };
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) {
            const int r0 = (row + 1) % 3, r1 = (row + 2) % 3, c0 = (col + 1) % 3, c1 = (col + 2) % 3;
            cof[3 * col + row] = e(r0, c0) * e(r1, c1) - e(r0, c1) * e(r1, c0);
        }
}

/* The largest length of the images of the unit axes: how much the
 * transform stretches a short distance at most, for a transform without
 * shear (rotation times scale, as TRS nodes are). */
double mat4_largest_scale(const Mat4 &a)
{
    double largest = 0.0;
    for (int c = 0; c < 3; ++c)
        largest = std::max(largest, std::sqrt(a.m[4 * c] * a.m[4 * c] + a.m[4 * c + 1] * a.m[4 * c + 1] +
                                              a.m[4 * c + 2] * a.m[4 * c + 2]));
    return largest;
}

bool mat4_is_finite(const Mat4 &a)
{
    for (double v : a.m)
        if (!std::isfinite(v))
            return false;
    return true;
}

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

/* A name from the file, fit for a one-line message: control characters
 * replaced, long names cut (gt_quote). */
std::string printable(const std::string &name)
{
    gt_quoted q;
    return gt_quote(name.c_str(), &q);
}

/* [offset, offset + length) lies inside [0, size), without overflow. */
bool range_inside(uint64_t offset, uint64_t length, uint64_t size)
{
    return offset <= size && length <= size - offset;
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

const char *mode_name(int mode)
{
    switch (mode) {
    case TINYGLTF_MODE_POINTS: return "points";
    case TINYGLTF_MODE_LINE: return "lines";
    case TINYGLTF_MODE_LINE_LOOP: return "line loop";
    case TINYGLTF_MODE_LINE_STRIP: return "line strip";
    case TINYGLTF_MODE_TRIANGLE_STRIP: return "triangle strip";
    case TINYGLTF_MODE_TRIANGLE_FAN: return "triangle fan";
    default: return "unknown";
    }
}

const char *component_type_name(int type)
{
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "byte";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "unsigned byte";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "short";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "unsigned short";
    case TINYGLTF_COMPONENT_TYPE_INT: return "int";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "unsigned int";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "float";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "double";
    default: return "unknown";
    }
}

const char *type_name(int type)
{
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "unknown";
    }
}

struct Loader {
    const char *path;
    gt_error *e;
    scene *s;
    tinygltf::Model model;
    std::vector<int> parent;          /* per node, -1 for a root */
    std::map<int, std::string> image_problem; /* why an image has no pixels */
    std::vector<int> image_texture;   /* glTF image -> scene texture, -1 = not yet */
    std::vector<bool> warned_mode;    /* per mesh: non-triangle primitive reported */
    bool warned_orthographic = false;
    std::vector<Mat4> world;          /* per node: global transform, once world_known */
    std::vector<char> world_known;
    bool quantization = false;        /* KHR_mesh_quantization is in extensionsUsed */
    bool quantized_primitive = false, morphed_primitive = false; /* of the primitive being read */
    double position_step = 0.0;       /* of the primitive being read, in its local units */
    std::set<int> sparse_seen;        /* sparse accessors read */
    std::vector<uv_transform> material_uv; /* per material: KHR_texture_transform, baked into texcoords */
    gltf_report *report;

    int fail(const char *fmt, ...) __attribute__((format(printf, 2, 3)))
    {
        char problem[768];
        va_list ap;
        va_start(ap, fmt);
        std::vsnprintf(problem, sizeof problem, fmt, ap);
        va_end(ap);
        return gt_error_set(e, path, "%s", problem);
    }
};

int read_whole_file(const char *path, std::vector<unsigned char> &bytes, gt_error *e)
{
    FILE *f = std::fopen(path, "rb");
    if (!f)
        return gt_error_set(e, path, "cannot open: %s", std::strerror(errno));
    unsigned char chunk[1 << 16];
    size_t n;
    while ((n = std::fread(chunk, 1, sizeof chunk, f)) > 0)
        bytes.insert(bytes.end(), chunk, chunk + n);
    int failed = std::ferror(f);
    int err = errno;
    std::fclose(f);
    if (failed)
        return gt_error_set(e, path, "cannot read: %s", std::strerror(err));
    return 0;
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

/* The JSON of the file (all of a .gltf, the JSON chunk of a .glb) must pass
 * the JSON gate (core/json_check.h) before tinygltf's recursive parser sees
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

/* Defined with the accessors, below. */
int decode_meshopt_views(Loader &L);

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

/* ------------------------------------------------------------- accessors */

/* A checked window onto count elements of element_size bytes: element i
 * starts at base + i * stride and all of them lie inside the buffer. */
struct AccessorView {
    const unsigned char *base;
    size_t stride, count;
};

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

/* What a role accepts: core glTF 2.0 ("Meshes", attribute table), and with
 * KHR_mesh_quantization (declared in extensionsUsed) its additions. */
struct RoleTypes {
    const char *name;
    int type;
    unsigned core, quantized;
};

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

/* One triangle primitive in its mesh's local space (or, skinned, in world
 * space), as a triangle list. */
struct Primitive {
    std::vector<float> positions, normals, texcoords;
    std::vector<uint32_t> indices;
    std::vector<uint32_t> joints; /* influences per vertex, each set of JOINTS_n/WEIGHTS_n adds 4 */
    std::vector<float> weights;
    int influences = 0;
    bool skinned = false;
};

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
        if (node.camera >= 0 && !L.s->has_camera && set_camera(L, index, world) != 0)
            return -1;
        stack.insert(stack.end(), node.children.rbegin(), node.children.rend());
    }
    return 0;
}

int load(Loader &L, const unsigned char *bytes, size_t size, const std::string &base_dir)
{
    if (parse_bytes(L, bytes, size, base_dir) != 0 || check_node_graph(L) != 0 || convert_materials(L) != 0 ||
        flatten(L) != 0)
        return -1;
    return scene_validate(L.s, L.path, L.e);
}

int load_guarded(const unsigned char *bytes, size_t size, const char *name, const std::string &base_dir, scene *s,
                 gltf_report *report, gt_error *e)
{
    int rc;
    try {
        Loader L;
        L.path = name;
        L.e = e;
        L.s = s;
        L.report = report;
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
                gltf_report *report, gt_error *e)
{
    gltf_report unused;
    report = report ? report : &unused;
    std::memset(report, 0, sizeof *report);
    std::memset(s, 0, sizeof *s);
    int rc = load_guarded(static_cast<const unsigned char *>(bytes), size, name, base_dir ? base_dir : "", s, report,
                          e);
    if (rc != 0)
        scene_free(s);
    return rc;
}

} // namespace

extern "C" int gltf_load_memory(const void *bytes, size_t size, const char *name, const char *base_dir, scene *s,
                                gt_error *e)
{
    return load_memory(bytes, size, name, base_dir, s, nullptr, e);
}

extern "C" int gltf_load_report(const char *path, scene *s, gltf_report *report, gt_error *e)
{
    std::memset(s, 0, sizeof *s);
    int rc;
    try {
        std::vector<unsigned char> bytes;
        rc = read_whole_file(path, bytes, e);
        if (rc == 0)
            rc = load_memory(bytes.data(), bytes.size(), path, directory_of(path).c_str(), s, report, e);
    } catch (const std::bad_alloc &) {
        rc = gt_error_set(e, path, "out of memory");
    }
    return rc;
}

extern "C" int gltf_load(const char *path, scene *s, gt_error *e)
{
    return gltf_load_report(path, s, nullptr, e);
}
