/* Fuzz target "gltf": glTF and GLB files (the input is the file's bytes)
 * through the loader gtlab renders from: the GLB container, the JSON gate,
 * the JSON prepass, tinygltf, gtlab's checks of every index and byte range,
 * images, sparse and quantized accessors, strips and fans, morph targets and
 * skins, the EXT_meshopt_compression and KHR_draco_mesh_compression decoders
 * (seeds: plane-meshopt.glb, draco.glb, strip-sparse.gltf, morph-skin.gltf),
 * the flattening of the node tree and scene_validate (scene/gltf/gltf_reader.h).
 * External buffers and images are looked up in a folder that does not
 * exist. What loads is then used as a render would use it: its bounds, the
 * automatic camera framing them, and each mesh's material at its
 * vertices' texture coordinates. */
#include <math.h>

#include "fuzz_target.h"
#include "scene/camera.h"
#include "scene/gltf/gltf_reader.h"
#include "scene/material_lookup.h"

static void use_scene(const scene *s)
{
    vec3 lo, hi;
    scene_bounds(s, &lo, &hi);
    camera framed = camera_auto_framing(lo, hi, 64, 48);
    gt_error e;
    (void)camera_validate(&framed, "framing", &e);
    if (s->has_camera)
        (void)camera_validate(&s->camera, "glTF camera", &e);
    for (int m = 0; m < s->mesh_count; ++m) {
        const scene_mesh *mesh = &s->meshes[m];
        for (uint32_t v = 0; v < mesh->vertex_count && v < 64; ++v) {
            const float zero[2] = {0.0f, 0.0f};
            const material_sample ms = material_lookup(s, m, mesh->texcoords ? &mesh->texcoords[2 * v] : zero);
            FUZZ_REQUIRE(isfinite(ms.base_color[0]) && isfinite(ms.roughness) && isfinite(ms.metallic));
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    scene s;
    gt_error e;
    if (gltf_load_memory(data, size, "fuzz.gltf", "/nonexistent-gtlab-fuzz", &s, &e) == 0) {
        use_scene(&s);
        scene_free(&s);
    }
    return 0;
}
