/* A scene with one albedo for its floor and another for everything else:
 * the per-object-albedo scenes of the multi-bounce studies (issue 25,
 * items 1 and 2). */
#include <string.h>

#include "multibounce/multibounce_parts.h"
#include "scene/scene_loaders.h"

int multibounce_load_two_albedo_scene(const char *spec, const float floor_rgb[3], const float objects_rgb[3],
                                      scene *s, gt_error *e)
{
    if (scene_load(spec, s, e) != 0)
        return -1;
    scene_material floor = *scene_mesh_material(s, &s->meshes[0]), objects = floor;
    memcpy(floor.base_color, floor_rgb, sizeof floor.base_color[0] * 3);
    memcpy(objects.base_color, objects_rgb, sizeof objects.base_color[0] * 3);
    int f = scene_add_material(s, floor), o = scene_add_material(s, objects);
    if (f < 0 || o < 0) {
        scene_free(s);
        return gt_error_set(e, spec, "out of memory");
    }
    for (int m = 0; m < s->mesh_count; ++m)
        s->meshes[m].material = m == 0 ? f : o;
    return 0;
}
