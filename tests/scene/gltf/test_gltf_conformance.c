/* The conformance sweep (issue 30): every glTF file of Debian's
 * assimp-testmodels (46), each with its expected outcome written here —
 * it loads (with its triangle count, and what the reader must report of it),
 * or it is refused with one line that starts with its path and names the
 * reason. A file missing from the table, or a table entry missing from the
 * disk, fails the test: the table is the list, not a discovery. The library
 * may print nothing but warnings. Load only (no render): a few seconds. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "gltf_test_files.h"
#include "scene/gltf/gltf_reader.h"
#include "tests/check.h"

#define MODELS "/usr/share/assimp/models/glTF2/"
#define MODES "glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_"

typedef struct {
    const char *file;     /* under MODELS */
    unsigned triangles;   /* > 0: loads with this many triangles */
    const char *refused;  /* else: the reason the one-line error names */
    const char *report;   /* for loaded files: what the report must say (see check_report_text) */
} expectation;

static const char no_triangles[] = "the scene has no triangles";

static const expectation table[] = {
    {"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 121496, NULL, "lists 115"},
    {"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", 12, NULL, NULL}, /* warned: normals recomputed */
    {"BoxTexcoords-glTF/boxTexcoords.gltf", 12, NULL, NULL},         /* warned: TEXCOORD_1 unused */
    {"BoxTextured-glTF-Binary/BoxTextured.glb", 12, NULL, NULL},
    {"BoxTextured-glTF-Embedded/BoxTextured.gltf", 12, NULL, NULL},
    {"BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", 12, NULL, NULL}, /* used, not required */
    {"BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", 0, "requires the glTF extension KHR_technique_webgl", NULL},
    {"BoxTextured-glTF/BoxTextured.gltf", 12, NULL, NULL},
    {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", 0, "POSITION 0 is not finite", NULL},
    {"ClearCoat-glTF/ClearCoatTest.gltf", 37116, NULL, NULL},
    {"IncorrectVertexArrays/Cube.gltf", 0, "35 vertices without indices is not a whole number of triangles", NULL},
    {"IndexOutOfRange/AllIndicesOutOfRange.gltf", 0, "index 65535 (entry 0) is out of range", NULL},
    {"IndexOutOfRange/IndexOutOfRange.gltf", 0, "index 255 (entry 0) is out of range", NULL},
    {"MissingBin/BoxTextured.gltf", 0, "BoxTextured0.bin", NULL},
    {"RecursiveNodes/RecursiveNodes.gltf", 0, "node graph has a cycle", NULL},
    {"SchemaFailures/sceneWrongType.gltf", 0, "BoxTextured0.bin", NULL}, /* its buffer is not shipped */
    {"TestNoRootNode/NoScene.gltf", 0, no_triangles, NULL},
    {"TestNoRootNode/SceneWithoutNodes.gltf", 0, no_triangles, NULL},
    {"cameras/Cameras.gltf", 2, NULL, NULL},
    {"draco/2CylinderEngine.gltf", 110336, NULL, "draco 115"}, /* Draco drops degenerate triangles */
    {MODES "00.gltf", 0, no_triangles, NULL}, /* points: skipped with a warning */
    {MODES "01.gltf", 0, no_triangles, NULL}, /* lines */
    {MODES "02.gltf", 0, no_triangles, NULL}, /* line loop */
    {MODES "03.gltf", 0, no_triangles, NULL}, /* line strip */
    {MODES "04.gltf", 2, NULL, "strips 1"},
    {MODES "05.gltf", 2, NULL, "fans 1"},
    {MODES "06.gltf", 2, NULL, "lists 1"},
    {MODES "07.gltf", 0, no_triangles, NULL},
    {MODES "08.gltf", 0, no_triangles, NULL},
    {MODES "09.gltf", 0, no_triangles, NULL},
    {MODES "10.gltf", 0, no_triangles, NULL},
    {MODES "11.gltf", 2, NULL, "strips 1"},
    {MODES "12.gltf", 2, NULL, "fans 1"},
    {MODES "13.gltf", 2, NULL, "lists 1"},
    {MODES "14.gltf", 2, NULL, "lists 1"},
    {MODES "15.gltf", 2, NULL, "lists 1"},
    {"glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", 12, NULL, "morphed 0"}, /* weights 0 */
    {"issue_3269/texcoord_crash.gltf", 10, NULL, NULL},
    {"simple_skin/simple_skin.gltf", 8, NULL, "skinned 1"},
    {"textureTransform/TextureTransformTest.gltf", 24, NULL, NULL}, /* KHR_texture_transform applied */
    {"wrongTypes/badArray.gltf", 0, no_triangles, NULL},
    {"wrongTypes/badExtension.gltf", 12, NULL, NULL},
    {"wrongTypes/badNumber.gltf", 12, NULL, NULL},
    {"wrongTypes/badObject.gltf", 12, NULL, NULL},
    {"wrongTypes/badString.gltf", 12, NULL, NULL},
    {"wrongTypes/badUint.gltf", 12, NULL, NULL},
};
enum { TABLE_SIZE = sizeof table / sizeof table[0] };

static char printed[65536];

/* "lists N", "strips N", "fans N", "draco N", "morphed N", "skinned N". */
static int report_says(const gltf_report *r, const char *text)
{
    char what[16];
    int n;
    if (sscanf(text, "%15s %d", what, &n) != 2)
        return 0;
    const int *mode = r->primitives_by_mode;
    return (!strcmp(what, "lists") && mode[4] == n) || (!strcmp(what, "strips") && mode[5] == n) ||
           (!strcmp(what, "fans") && mode[6] == n) || (!strcmp(what, "draco") && r->draco_primitives == n) ||
           (!strcmp(what, "morphed") && r->morphed_primitives == n) ||
           (!strcmp(what, "skinned") && r->skinned_primitives == n);
}

static void check_entry(const expectation *x)
{
    char path[1024];
    snprintf(path, sizeof path, MODELS "%s", x->file);
    scene s;
    gt_error e = {{0}};
    const int rc = load_capturing(path, &s, &e, printed, sizeof printed);
    CHECK_MSG(only_warnings(printed), "%s printed more than warnings: %s", x->file, printed);
    if (x->triangles == 0) {
        CHECK_MSG(rc != 0, "%s loaded; expected refused: %s", x->file, x->refused);
        CHECK_MSG(rc == 0 || (strncmp(e.message, path, strlen(path)) == 0 && strstr(e.message, x->refused) &&
                              !strchr(e.message, '\n')),
                  "%s: \"%s\" does not say \"%s\"", x->file, e.message, x->refused);
        if (rc == 0)
            scene_free(&s);
        return;
    }
    CHECK_MSG(rc == 0, "%s refused: %s", x->file, e.message);
    if (rc != 0)
        return;
    CHECK_MSG(scene_triangle_count(&s) == x->triangles, "%s: %llu triangles, expected %u", x->file,
              (unsigned long long)scene_triangle_count(&s), x->triangles);
    scene_free(&s);
    gltf_report r;
    if (x->report && gltf_load_report(path, &s, &r, &e) == 0) {
        CHECK_MSG(report_says(&r, x->report), "%s: the report does not say %s", x->file, x->report);
        scene_free(&s);
    }
}

static int listed(const char *relative)
{
    for (int i = 0; i < TABLE_SIZE; ++i)
        if (strcmp(table[i].file, relative) == 0)
            return 1;
    return 0;
}

/* Every .gltf/.glb under MODELS (two levels of folders deep) is in the table. */
static int count_unlisted(const char *folder, int depth)
{
    char dir_path[1024];
    snprintf(dir_path, sizeof dir_path, MODELS "%s", folder);
    DIR *d = opendir(dir_path);
    int unlisted = 0;
    for (struct dirent *entry; d && (entry = readdir(d));) {
        char relative[1024];
        snprintf(relative, sizeof relative, "%s%s%s", folder, *folder ? "/" : "", entry->d_name);
        const size_t n = strlen(entry->d_name);
        const int gltf = n > 5 && (!strcmp(entry->d_name + n - 5, ".gltf") || !strcmp(entry->d_name + n - 4, ".glb"));
        if (gltf && !listed(relative))
            printf("test_gltf_conformance: %s is not in the table\n", relative), ++unlisted;
        else if (entry->d_name[0] != '.' && !gltf && depth < 2 && !strchr(entry->d_name, '.'))
            unlisted += count_unlisted(relative, depth + 1);
    }
    if (d)
        closedir(d);
    return unlisted;
}

int main(void)
{
    struct stat st;
    if (stat(MODELS, &st) != 0) {
        printf("test_gltf_conformance: %s not installed (assimp-testmodels); skipped\n", MODELS);
        return check_report("test_gltf_conformance");
    }
    CHECK(TABLE_SIZE == 46);
    CHECK(count_unlisted("", 0) == 0);
    for (int i = 0; i < TABLE_SIZE; ++i)
        check_entry(&table[i]);
    return check_report("test_gltf_conformance");
}
