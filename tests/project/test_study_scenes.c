/* project/scene_list: the scene list the studies run over. With no
 * project it is the built-in study list, in its order, each labelled by its
 * name and loaded at its own camera exactly as scene_load and
 * scene_choose_camera give it (so the studies' numbers cannot change), then
 * as many of the procedural family's members as the context asks for;
 * labels that are not safe file names, and a label used twice, are refused;
 * a glTF camera chosen by index or by name is the one its node places (two
 * cameras at known translations), and an unknown, unplaced or orthographic
 * camera is an error naming the file. */
#include <stdio.h>
#include <string.h>

#include "scene/builtin_scene_family.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_loaders.h"
#include "project/scene_list.h"
#include "tests/check.h"

static int same_camera(const camera *a, const camera *b)
{
    return memcmp(&a->position, &b->position, sizeof a->position) == 0 &&
           memcmp(&a->target, &b->target, sizeof a->target) == 0 && a->yfov == b->yfov && a->width == b->width &&
           a->height == b->height;
}

/* The entry loads as scene_load(spec) and scene_choose_camera give it at width. */
static void check_loads_as(const study_scene_entry *x, const char *spec, int width)
{
    scene a, b;
    camera ca, cb;
    gt_error e;
    CHECK_MSG(study_scene_view(x, width, 0, &a, &ca, &e) == 0, "%s", e.message);
    CHECK(scene_load(spec, &b, &e) == 0 && scene_choose_camera(&b, NULL, width, 0, &cb, &e) == 0);
    CHECK(same_camera(&ca, &cb) && scene_triangle_count(&a) == scene_triangle_count(&b));
    scene_free(&a);
    scene_free(&b);
}

static void test_builtin_list(void)
{
    CHECK(study_scene_count(NULL) == builtin_study_scene_count());
    for (int i = 0; i < study_scene_count(NULL); ++i) {
        const study_scene_entry *x = study_scene_at(NULL, i);
        char spec[128];
        snprintf(spec, sizeof spec, "builtin:%s", builtin_study_scene_at(i)->name);
        CHECK(strcmp(x->label, builtin_study_scene_at(i)->name) == 0 && strcmp(x->spec, spec) == 0);
        CHECK(x->camera_json[0] == '\0' && x->gltf_camera == -1 && x->gltf_camera_name[0] == '\0');
        CHECK(study_scene_find(NULL, x->label) == x && strcmp(study_scene_spec(NULL, x->label), spec) == 0);
        check_loads_as(x, spec, 96);
    }
    CHECK(study_scene_at(NULL, study_scene_count(NULL)) == NULL && study_scene_find(NULL, "no-such") == NULL);
}

/* Without a project, study_scenes extends the built-in study scenes with the
 * procedural family in family_member_name's order, each entry the member as
 * scene_load builds it; the count is at least the built-ins and at most
 * STUDY_SCENES_MAX, and a project's scenes are never extended. */
static void test_builtin_set(void)
{
    const int builtins = builtin_study_scene_count();
    study_context ctx = {check_tmp_dir(), QUALITY_PREVIEW, 1, NULL, NULL, builtins + 3};
    CHECK(study_scene_count(&ctx) == builtins + 3 && !study_scenes_from_project(&ctx));
    for (int i = 0; i < builtins; ++i)
        CHECK(study_scene_at(&ctx, i) == study_scene_at(NULL, i));
    for (int k = 0; k < 3; ++k) {
        char name[64], spec[80];
        family_member_name(k, name, sizeof name);
        snprintf(spec, sizeof spec, "builtin:%s", name);
        const study_scene_entry *x = study_scene_at(&ctx, builtins + k);
        CHECK_MSG(x && strcmp(x->label, name) == 0 && strcmp(x->spec, spec) == 0, "entry %d", builtins + k);
        CHECK(study_scene_find(&ctx, name) == x && study_scene_find(NULL, name) == NULL);
        check_loads_as(x, spec, 64);
    }
    CHECK(strcmp(study_scene_at(&ctx, builtins)->label, "room-0") == 0 &&
          strcmp(study_scene_at(&ctx, builtins + 1)->label, "railing-0") == 0);
    CHECK(study_scene_at(&ctx, builtins + 3) == NULL);
    ctx.study_scenes = 1;
    CHECK(study_scene_count(&ctx) == builtins);
    ctx.study_scenes = 1000;
    CHECK(study_scene_count(&ctx) == STUDY_SCENES_MAX && study_scene_at(&ctx, STUDY_SCENES_MAX - 1));
    static study_scene_list project;
    study_scene_entry one = {.spec = "builtin:plane", .label = "mine", .gltf_camera = -1};
    gt_error e;
    CHECK(study_scene_list_add(&project, &one, "t", &e) == 0);
    ctx.scenes = &project;
    CHECK(study_scene_count(&ctx) == 1 && study_scenes_from_project(&ctx) && study_scene_find(&ctx, "room-0") == NULL);
}

static void test_labels(void)
{
    gt_error e;
    const char *good[] = {"a", "shop_2.view-A", "x1234567890123456789012345678901234567890123456"}; /* 47 */
    const char *bad[] = {"", ".hidden", "-option", "a b", "a/b", "caf\xc3\xa9",
                         "x12345678901234567890123456789012345678901234567"}; /* 48 */
    for (size_t i = 0; i < sizeof good / sizeof good[0]; ++i)
        CHECK_MSG(study_scene_label_check(good[i], "t", &e) == 0, "%s", e.message);
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i)
        CHECK_MSG(study_scene_label_check(bad[i], "t", &e) != 0, "'%s' accepted", bad[i]);
    static study_scene_list list;
    study_scene_entry x = {.spec = "builtin:plane", .label = "p", .gltf_camera = -1};
    CHECK(study_scene_list_add(&list, &x, "t", &e) == 0);
    CHECK(study_scene_list_add(&list, &x, "t", &e) != 0 && strstr(e.message, "used twice"));
    for (int i = 1; i < STUDY_SCENES_MAX; ++i) {
        snprintf(x.label, sizeof x.label, "p%d", i);
        CHECK(study_scene_list_add(&list, &x, "t", &e) == 0);
    }
    snprintf(x.label, sizeof x.label, "one-more");
    CHECK(study_scene_list_add(&list, &x, "t", &e) != 0 && list.count == STUDY_SCENES_MAX);
    study_context ctx = {check_tmp_dir(), QUALITY_PREVIEW, 1, &list, NULL, 0};
    CHECK(study_scene_count(&ctx) == STUDY_SCENES_MAX && study_scene_find(&ctx, "p3") == &list.scenes[3]);
}

/* One triangle and two perspective cameras, "A" at z = 3 and "B" at z = 7,
 * and a third camera no node places. */
static const char two_cameras[] =
    "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0,1,2]}],"
    "\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,0,3]},{\"camera\":1,\"translation\":[0,0,7]}],"
    "\"cameras\":[{\"name\":\"A\",\"type\":\"perspective\",\"perspective\":{\"yfov\":0.7,\"znear\":0.1}},"
    "{\"name\":\"B\",\"type\":\"perspective\",\"perspective\":{\"yfov\":0.5,\"znear\":0.1}},"
    "{\"name\":\"C\",\"type\":\"perspective\",\"perspective\":{\"yfov\":0.5,\"znear\":0.1}}],"
    "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
    "\"min\":[0,0,0],\"max\":[1,1,0]}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
    "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64,"
    "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}]}";

static int view_z(const study_scene_entry *x, float *z, gt_error *e)
{
    scene s;
    camera cam;
    if (study_scene_view(x, 32, 32, &s, &cam, e) != 0)
        return -1;
    *z = cam.position.z;
    scene_free(&s);
    return 0;
}

static void test_gltf_cameras(void)
{
    study_scene_entry x = {.gltf_camera = -1};
    snprintf(x.spec, sizeof x.spec, "%s/two_cameras.gltf", check_tmp_dir());
    FILE *f = fopen(x.spec, "w");
    CHECK(f && fputs(two_cameras, f) >= 0 && fclose(f) == 0);
    gt_error e;
    float z = 0.0f;
    CHECK_MSG(view_z(&x, &z, &e) == 0 && z == 3.0f, "default: %s, z %g", e.message, z); /* the first met */
    x.gltf_camera = 1;
    CHECK_MSG(view_z(&x, &z, &e) == 0 && z == 7.0f, "index 1: %s, z %g", e.message, z);
    x.gltf_camera = 0;
    CHECK_MSG(view_z(&x, &z, &e) == 0 && z == 3.0f, "index 0: %s, z %g", e.message, z);
    x.gltf_camera = -1;
    snprintf(x.gltf_camera_name, sizeof x.gltf_camera_name, "B");
    CHECK_MSG(view_z(&x, &z, &e) == 0 && z == 7.0f, "name B: %s, z %g", e.message, z);
    snprintf(x.gltf_camera_name, sizeof x.gltf_camera_name, "Top");
    CHECK(view_z(&x, &z, &e) != 0 && strstr(e.message, "no camera named 'Top'") && strstr(e.message, x.spec));
    snprintf(x.gltf_camera_name, sizeof x.gltf_camera_name, "C");
    CHECK(view_z(&x, &z, &e) != 0 && strstr(e.message, "camera 2 is not a perspective camera on a node"));
    x.gltf_camera_name[0] = '\0';
    x.gltf_camera = 3;
    CHECK(view_z(&x, &z, &e) != 0 && strstr(e.message, "camera 3 does not exist (3 cameras)"));
    x.gltf_camera = 0;
    snprintf(x.spec, sizeof x.spec, "builtin:boxes");
    CHECK(view_z(&x, &z, &e) != 0 && strstr(e.message, "builtin:boxes"));
}

/* Assimp's sample: camera 1 is orthographic, which gtlab does not render. */
static void test_orthographic(void)
{
    const char *path = "/usr/share/assimp/models/glTF2/cameras/Cameras.gltf";
    FILE *f = fopen(path, "r");
    if (!f)
        return;
    fclose(f);
    study_scene_entry x = {.gltf_camera = 1};
    snprintf(x.spec, sizeof x.spec, "%s", path);
    gt_error e;
    float z;
    CHECK(view_z(&x, &z, &e) != 0 && strstr(e.message, "camera 1 is not a perspective camera"));
}

int main(void)
{
    test_builtin_list();
    test_builtin_set();
    test_labels();
    test_gltf_cameras();
    test_orthographic();
    return check_report("studies_study_scenes");
}
