/* A scene described for people: see the header. */
#include "scene/scene_describe.h"

#include <string.h>

/* Each line of the description indented under the scene's name. */
void builtin_scene_describe(FILE *f, const builtin_scene *b)
{
    fprintf(f, "%s\n", b->name);
    for (const char *line = b->description; *line;) {
        size_t n = strcspn(line, "\n");
        fprintf(f, "    %.*s\n", (int)n, line);
        line += n + (line[n] == '\n');
    }
}

void scene_describe(FILE *f, const scene *s)
{
    vec3 lo, hi;
    scene_bounds(s, &lo, &hi);
    fprintf(f, "%s: %llu triangles in %d mesh%s, %d material%s, %d texture%s, %s\n", s->name,
           (unsigned long long)scene_triangle_count(s), s->mesh_count, s->mesh_count == 1 ? "" : "es",
           s->material_count, s->material_count == 1 ? "" : "s", s->texture_count, s->texture_count == 1 ? "" : "s",
           s->has_camera ? "a camera" : "no camera (an automatic view is used)");
    fprintf(f, "bounds: (%g, %g, %g) to (%g, %g, %g)\n", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    int flat = 0;
    for (int i = 0; i < s->mesh_count; ++i) {
        const scene_mesh *m = &s->meshes[i];
        flat += m->flat;
        fprintf(f, "  mesh %d: %u triangles, %u vertices, material %d, %s\n", i, m->triangle_count, m->vertex_count,
               m->material, m->flat ? "no normals: flat-shaded (face normals)" : "normals");
    }
    if (flat)
        fprintf(f, "%d of %d meshes had no normals and are flat-shaded, as glTF 2.0 requires\n", flat, s->mesh_count);
}

void gltf_report_describe(FILE *f, const gltf_report *r)
{
    const int *mode = r->primitives_by_mode;
    fprintf(f, "glTF extensions used: %s\n", r->extensions_used[0] ? r->extensions_used : "none");
    fprintf(f, "primitives: %d triangle lists, %d triangle strips, %d triangle fans; %d points/lines primitives skipped\n",
           mode[4], mode[5], mode[6], mode[0] + mode[1] + mode[2] + mode[3]);
    fprintf(f, "quantized (KHR_mesh_quantization): %d primitives; Draco-compressed: %d primitives; "
           "meshopt-compressed: %d bufferViews\n",
           r->quantized_primitives, r->draco_primitives, r->meshopt_views);
    if (r->position_step > 0.0)
        fprintf(f, "positions quantized to a grid of at most %.6g world units\n", r->position_step);
    fprintf(f, "sparse accessors: %d; morph targets applied: %d primitives; skinned (default pose): %d primitives; "
           "without normals (flat-shaded): %d primitives\n",
           r->sparse_accessors, r->morphed_primitives, r->skinned_primitives, r->primitives_without_normals);
}

