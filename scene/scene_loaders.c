/* The loader table behind scene_load (scene_loaders.h): the first entry
 * whose prefix starts the spec (and, if it names one, whose extension ends
 * it, in any case) loads it, given the spec without the prefix. The glTF
 * reader comes last and takes any path: a file in no known format gets its
 * error from it ("not a binary glTF file", "cannot load glTF: ..."). */
#include "scene/scene_loaders.h"

#include <ctype.h>
#include <string.h>

#include "scene/builtin_scenes.h"
#include "scene/gltf/gltf_reader.h"

typedef struct {
    const char *prefix;    /* the spec starts with it ("" for any); removed before loading */
    const char *extension; /* lower case, e.g. ".obj": the spec ends with it; NULL for any */
    int (*load)(const char *name, scene *s, gt_error *e);
} scene_loader;

static const scene_loader loaders[] = {
    {"builtin:", NULL, builtin_scene_build},
    {"", NULL, gltf_load}, /* last: any other spec is a .gltf/.glb path */
};

static int ends_with_lower(const char *text, const char *suffix)
{
    size_t n = strlen(text), k = strlen(suffix);
    if (n < k)
        return 0;
    for (size_t i = 0; i < k; ++i)
        if (tolower((unsigned char)text[n - k + i]) != suffix[i])
            return 0;
    return 1;
}

static int loader_matches(const scene_loader *l, const char *spec)
{
    return strncmp(spec, l->prefix, strlen(l->prefix)) == 0 && (!l->extension || ends_with_lower(spec, l->extension));
}

static int load_with_table(const char *spec, scene *s, gt_error *e)
{
    for (size_t i = 0; i < sizeof loaders / sizeof loaders[0]; ++i)
        if (loader_matches(&loaders[i], spec))
            return loaders[i].load(spec + strlen(loaders[i].prefix), s, e);
    return gt_error_set(e, spec, "no loader for this scene (builtin:NAME, .gltf or .glb)");
}

int scene_load(const char *spec, scene *s, gt_error *e)
{
    memset(s, 0, sizeof *s);
    int rc = load_with_table(spec, s, e);
    if (rc == 0)
        rc = scene_validate(s, spec, e);
    if (rc != 0)
        scene_free(s);
    return rc;
}
