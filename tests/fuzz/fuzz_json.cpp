/* Fuzz target "json": the JSON gate (core/files/json_check.h) against the two
 * parsers it guards. Whatever text the gate accepts, nlohmann json (which
 * tinygltf parses glTF with) and cJSON (camera JSON; with the gate's cJSON
 * limits) must parse too, and nothing the gate accepts nests deeper than its
 * limit; so every JSON error a user sees is the gate's, in gtlab's words,
 * and no text reaches a recursive parser unchecked. */
#include <cjson/cJSON.h>

#include <cstring>
#include <nlohmann/json.hpp>
#include <string>

extern "C" {
#include "core/files/json_check.h"
}
#include "fuzz_target.h"

/* The deepest nesting of a parsed document, without recursion. */
static int depth_of(const nlohmann::json &root)
{
    std::vector<std::pair<const nlohmann::json *, int>> stack{{&root, 0}};
    int deepest = 0;
    while (!stack.empty()) {
        auto [node, depth] = stack.back();
        stack.pop_back();
        if (!node->is_structured())
            continue;
        deepest = std::max(deepest, depth + 1);
        for (const auto &child : *node)
            stack.emplace_back(&child, depth + 1);
    }
    return deepest;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *text = reinterpret_cast<const char *>(data);
    gt_error e;
    if (json_check(text, size, json_limits_gltf, "fuzz.json", &e) == 0) {
        const nlohmann::json doc = nlohmann::json::parse(data, data + size, nullptr, false);
        FUZZ_REQUIRE(!doc.is_discarded());
        FUZZ_REQUIRE(depth_of(doc) <= JSON_MAX_DEPTH);
    } else {
        FUZZ_REQUIRE(std::strncmp(e.message, "fuzz.json: ", 11) == 0 && std::strchr(e.message, '\n') == nullptr);
    }
    if (json_check(text, size, json_limits_cjson, "fuzz.json", &e) == 0) {
        const size_t bom = json_bom_length(text, size);
        const std::string copy(text + bom, size - bom); /* cJSON wants the NUL inside the length */
        cJSON *root = cJSON_ParseWithLengthOpts(copy.c_str(), copy.size() + 1, nullptr, 1);
        FUZZ_REQUIRE(root != nullptr);
        cJSON_Delete(root);
    }
    return 0;
}
