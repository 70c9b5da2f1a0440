/* The JSON rewrite before tinygltf: see gltf_json_prepass.h. */
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

extern "C" {
#include "scene/gltf/gltf_json_prepass.h"
}

namespace {

using nlohmann::json;

const json *find_path(const json &o, const char *a, const char *b)
{
    if (!o.is_object())
        return nullptr;
    auto i = o.find(a);
    if (i == o.end() || !i->is_object())
        return nullptr;
    auto j = i->find(b);
    return j == i->end() ? nullptr : &*j;
}

bool is_fallback_buffer(const json &buffer)
{
    const json *ext = find_path(buffer, "extensions", "EXT_meshopt_compression");
    if (!ext || !ext->is_object())
        return false;
    auto f = ext->find("fallback");
    return f != ext->end() && f->is_boolean() && f->get<bool>();
}

bool rewrite_fallback_buffers(json &doc)
{
    auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array())
        return false;
    bool changed = false;
    for (json &buffer : *buffers)
        if (is_fallback_buffer(buffer)) {
            buffer["uri"] = "data:application/octet-stream;base64,AAAAAA==";
            buffer["byteLength"] = 4;
            changed = true;
        }
    return changed;
}

bool rewrite_draco_primitives(json &doc)
{
    auto meshes = doc.find("meshes");
    if (meshes == doc.end() || !meshes->is_array())
        return false;
    bool changed = false;
    for (json &mesh : *meshes) {
        auto primitives = mesh.is_object() ? mesh.find("primitives") : mesh.end();
        if (!mesh.is_object() || primitives == mesh.end() || !primitives->is_array())
            continue;
        for (json &p : *primitives)
            if (find_path(p, "extensions", "KHR_draco_mesh_compression") && p.erase("indices") > 0)
                changed = true;
    }
    return changed;
}

} // namespace

extern "C" int gltf_json_prepass(const unsigned char *text, size_t length, char **out, size_t *out_length)
{
    *out = nullptr;
    *out_length = 0;
    try {
        json doc = json::parse(text, text + length, nullptr, false);
        if (!doc.is_object())
            return 0;
        const bool fallback = rewrite_fallback_buffers(doc);
        const bool draco = rewrite_draco_primitives(doc);
        if (!fallback && !draco)
            return 0;
        const std::string dumped = doc.dump(-1, ' ', false, json::error_handler_t::replace);
        *out = static_cast<char *>(std::malloc(dumped.size() + 1));
        if (!*out)
            return -1;
        std::memcpy(*out, dumped.data(), dumped.size());
        *out_length = dumped.size();
        return 1;
    } catch (const std::bad_alloc &) {
        return -1;
    } catch (const std::exception &) { /* left as it is: tinygltf reports the problem */
        return 0;
    }
}
