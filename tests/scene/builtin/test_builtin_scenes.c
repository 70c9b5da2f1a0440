/* Properties every built-in scene must have: it builds and validates, its
 * bounding box is the documented one, it has a camera that sees the
 * documented subject from a 3/4 view, every material index is valid, every
 * normal is unit length and agrees with the triangle winding, and flat faces
 * carry exactly their face's normal. Unknown names give the documented error. */
#include <string.h>

#include "scene/builtin_scenes.h"
#include "scene/scene_loaders.h"
#include "tests/check.h"
#include "tests/scene/builtin/mesh_math.h"

typedef struct {
    const char *name;
    d3 lo, hi;                 /* documented bounds ("Bounds:" in the description) */
    d3 subject_lo, subject_hi; /* a box the default camera must see whole */
    int smooth_mesh;           /* index of the mesh with smooth (sphere) normals, or -1 */
} expected_scene;

static const expected_scene expected[] = {
    {"plane", {-50, 0, -50}, {50, 0, 50}, {-5, 0, -5}, {5, 0, 5}, -1},
    {"sphere-on-plane", {-50, 0, -50}, {50, 2.5, 50}, {-2, 0, -2}, {2, 2.5, 2}, 1},
    {"corner", {0, 0, 0}, {10, 10, 10}, {0, 0, 0}, {6, 6, 6}, -1},
    {"menger", {-50, 0, -50}, {50, 2, 50}, {-1, 0, -1}, {1, 2, 1}, -1},
    /* 3.894838: the tallest box, recomputed from the documented formula in test_builtin_geometry */
    {"boxes", {-50, 0, -50}, {50, 3.894838, 50}, {-12.5, 0, -12.5}, {12.5, 3.9, 12.5}, -1},
    {"cornell", {-2.75, 0, -2.75}, {2.75, 5.5, 2.75}, {-2.75, 0, -2.75}, {2.75, 5.5, 2.75}, -1},
    /* 513.28863525: the highest vertex (float) of the documented height field */
    {"terrain", {-4000, 0, -4000}, {4000, 513.28863525, 4000}, {-1500, 0, -1500}, {1500, 500, 1500}, 0},
    {"pill-on-plane", {-50, 0, -50}, {50, 1.3, 50}, {-1.6, 0, -0.5}, {1.6, 1.3, 0.5}, 1},
    {"box-on-plane", {-50, 0, -50}, {50, 1.2, 50}, {-0.75, 0, -0.5}, {0.75, 1.2, 0.5}, -1},
    {"box-in-corner", {0, 0, 0}, {10, 10, 10}, {0, 0, 0}, {2.5, 1.5, 2.5}, -1},
    {"overlap-on-plane", {-50, -0.5, -50}, {50, 1.7, 50}, {-4.0, 0, -3.2}, {1.8, 1.7, 1.0}, 1},
};
enum { EXPECTED_COUNT = sizeof expected / sizeof expected[0] };

static void check_bounds(const scene *s, const expected_scene *x)
{
    vec3 lo, hi;
    scene_bounds(s, &lo, &hi);
    CHECK_NEAR(lo.x, x->lo.x, 1e-6);
    CHECK_NEAR(lo.y, x->lo.y, 1e-6);
    CHECK_NEAR(lo.z, x->lo.z, 1e-6);
    CHECK_NEAR(hi.x, x->hi.x, 1e-6);
    CHECK_NEAR(hi.y, x->hi.y, 1e-6);
    CHECK_NEAR(hi.z, x->hi.z, 1e-6);
}

/* The subject box's eight corners lie in front of the camera and inside its
 * image; the view is from above, at an angle to both horizontal axes (3/4),
 * except for the Cornell box, seen straight in through its open front. */
static void check_camera(const scene *s, const expected_scene *x)
{
    CHECK_MSG(s->has_camera, "%s", x->name);
    gt_error e;
    CHECK_MSG(camera_validate(&s->camera, x->name, &e) == 0, "%s", e.message);
    CHECK(s->camera.width == 512 && s->camera.height == 512);
    camera_view view = camera_view_from(&s->camera);
    for (int c = 0; c < 8; ++c) {
        vec3 p = v3((float)(c & 1 ? x->subject_hi.x : x->subject_lo.x), (float)(c & 2 ? x->subject_hi.y : x->subject_lo.y),
                    (float)(c & 4 ? x->subject_hi.z : x->subject_lo.z));
        vec3 d = v3_sub(p, view.origin);
        float depth = v3_dot(d, view.forward);
        float sx = v3_dot(d, view.right) / (depth * view.tan_half_yfov * view.aspect);
        float sy = v3_dot(d, view.up) / (depth * view.tan_half_yfov);
        CHECK_MSG(depth > 0.0f && fabsf(sx) <= 1.0f && fabsf(sy) <= 1.0f,
                  "%s: corner (%g, %g, %g) at image (%g, %g), depth %g", x->name, p.x, p.y, p.z, sx, sy, depth);
    }
    if (strcmp(x->name, "cornell") == 0) {
        CHECK(view.forward.z < -0.999f);
        CHECK(view.origin.z > 2.75f);
    } else {
        CHECK_MSG(view.forward.y < -0.2f && fabsf(view.forward.x) > 0.2f && fabsf(view.forward.z) > 0.2f,
                  "%s: forward (%g, %g, %g) is not a 3/4 view from above", x->name, view.forward.x, view.forward.y,
                  view.forward.z);
    }
}

/* The description states the camera and bounds the scene really has. */
static void check_description(const scene *s, const char *description, const char *name)
{
    const char *cam = strstr(description, "position (");
    float p[3], t[3], yfov_deg;
    int parsed = cam && sscanf(cam, "position (%f, %f, %f), target (%f, %f, %f), up +Y, yfov %f deg", &p[0], &p[1],
                               &p[2], &t[0], &t[1], &t[2], &yfov_deg) == 7;
    CHECK_MSG(parsed, "%s: no camera line in the description", name);
    if (parsed) {
        CHECK(p[0] == s->camera.position.x && p[1] == s->camera.position.y && p[2] == s->camera.position.z);
        CHECK(t[0] == s->camera.target.x && t[1] == s->camera.target.y && t[2] == s->camera.target.z);
        CHECK(s->camera.up.x == 0.0f && s->camera.up.y == 1.0f && s->camera.up.z == 0.0f);
        CHECK_NEAR(yfov_deg, s->camera.yfov * 180.0 / 3.14159265358979323846, 1e-4);
    }
    const char *bounds = strstr(description, "Bounds: ");
    float b[6];
    parsed = bounds && sscanf(bounds, "Bounds: [%f, %f] x [%f, %f] x [%f, %f]", &b[0], &b[1], &b[2], &b[3], &b[4],
                              &b[5]) == 6;
    CHECK_MSG(parsed, "%s: no bounds line in the description", name);
    if (parsed) {
        vec3 lo, hi;
        scene_bounds(s, &lo, &hi);
        CHECK_NEAR(b[0], lo.x, 1e-4);
        CHECK_NEAR(b[1], hi.x, 1e-4);
        CHECK_NEAR(b[2], lo.y, 1e-4);
        CHECK_NEAR(b[3], hi.y, 1e-4);
        CHECK_NEAR(b[4], lo.z, 1e-4);
        CHECK_NEAR(b[5], hi.z, 1e-4);
    }
}

static void check_materials(const scene *s, const char *name)
{
    CHECK_MSG(s->material_count >= 1, "%s", name);
    for (int i = 0; i < s->mesh_count; ++i)
        CHECK_MSG(s->meshes[i].material >= 0 && s->meshes[i].material < s->material_count, "%s mesh %d", name, i);
    for (int i = 0; i < s->material_count; ++i) {
        const scene_material *m = &s->materials[i];
        CHECK(m->metallic == 0.0f && m->roughness == 0.5f && m->base_color[3] == 1.0f);
        CHECK(m->base_color_texture == -1 && m->metallic_roughness_texture == -1);
    }
}

/* Unit normals; no degenerate triangle; each vertex normal on the side the
 * winding says is the front; on flat meshes each vertex normal is exactly its
 * triangle's (no averaging across hard edges). */
static void check_normals(const scene *s, const expected_scene *x)
{
    for (int i = 0; i < s->mesh_count; ++i) {
        const scene_mesh *m = &s->meshes[i];
        long bad_length = 0, degenerate = 0, back_facing = 0, not_flat = 0;
        for (uint32_t v = 0; v < m->vertex_count; ++v)
            bad_length += fabs(d3_length(d3_of(&m->normals[3 * v])) - 1.0) > 1e-6;
        for (uint32_t t = 0; t < m->triangle_count; ++t) {
            d3 g = tri_area_vector(m, t);
            double len = d3_length(g);
            if (!(len > 1e-9)) {
                ++degenerate;
                continue;
            }
            for (int k = 0; k < 3; ++k) {
                double c = d3_dot(g, tri_normal(m, t, k)) / len;
                back_facing += !(c > 0.0);
                not_flat += i != x->smooth_mesh && !(c > 1.0 - 1e-6);
            }
        }
        CHECK_MSG(bad_length == 0, "%s mesh %d: %ld normals not unit length", x->name, i, bad_length);
        CHECK_MSG(degenerate == 0, "%s mesh %d: %ld degenerate triangles", x->name, i, degenerate);
        CHECK_MSG(back_facing == 0, "%s mesh %d: %ld vertex normals against the winding", x->name, i, back_facing);
        CHECK_MSG(not_flat == 0, "%s mesh %d: %ld vertex normals differ from their flat face's", x->name, i, not_flat);
    }
}

static void test_every_scene(void)
{
    CHECK(builtin_scene_count() == EXPECTED_COUNT + 1); /* + aa-thin: tests/raytracer/test_aa_alpha_mask.c */
    for (int i = 0; i < EXPECTED_COUNT; ++i) {
        const expected_scene *x = &expected[i];
        const builtin_scene *b = builtin_scene_find(x->name);
        CHECK_MSG(b != NULL, "%s is not in the table", x->name);
        if (!b)
            continue;
        CHECK(strchr(b->description, '\n') != NULL); /* several lines */
        scene s;
        gt_error e;
        CHECK_MSG(builtin_scene_build(x->name, &s, &e) == 0, "%s", e.message);
        char expected_name[64];
        snprintf(expected_name, sizeof expected_name, "builtin:%s", x->name);
        CHECK(strcmp(s.name, expected_name) == 0);
        CHECK_MSG(scene_validate(&s, x->name, &e) == 0, "%s", e.message);
        check_bounds(&s, x);
        check_camera(&s, x);
        check_description(&s, b->description, x->name);
        check_materials(&s, x->name);
        check_normals(&s, x);
        scene_free(&s);
    }
}

static void test_table(void)
{
    /* The studies' list: every scene but those outside it, in table order. */
    int outside = 0;
    for (int i = 0; i < builtin_scene_count(); ++i)
        outside += builtin_scene_at(i)->outside_studies;
    CHECK(builtin_study_scene_count() == builtin_scene_count() - outside);
    CHECK(builtin_study_scene_count() == 6); /* plane .. cornell: what every study's numbers were made on */
    CHECK(builtin_scene_find("aa-thin")->outside_studies == 1);
    for (int i = 0; i < builtin_study_scene_count(); ++i)
        CHECK(builtin_study_scene_at(i) == builtin_scene_at(i) && !builtin_scene_at(i)->outside_studies);
    /* (the outside scenes come last, so the study indices are table indices) */
    CHECK(builtin_study_scene_at(builtin_study_scene_count()) == NULL);
    CHECK(builtin_scene_find("terrain")->outside_studies == 1);
    const char *decal_scenes[] = {"pill-on-plane", "box-on-plane", "box-in-corner", "overlap-on-plane"};
    for (int i = 0; i < 4; ++i)
        CHECK(builtin_scene_find(decal_scenes[i])->outside_studies == 1);
    for (int i = 0; i < builtin_scene_count(); ++i) {
        const builtin_scene *b = builtin_scene_at(i);
        CHECK(builtin_scene_find(b->name) == b); /* names are unique */
    }
    CHECK(builtin_scene_at(-1) == NULL);
    CHECK(builtin_scene_at(builtin_scene_count()) == NULL);
}

static void test_unknown_name(void)
{
    scene s;
    gt_error e;
    CHECK(builtin_scene_build("teapot", &s, &e) == -1);
    CHECK_MSG(strcmp(e.message, "builtin:teapot: unknown built-in scene (try 'gtlab scene list')") == 0, "%s",
              e.message);
    CHECK(s.mesh_count == 0 && s.meshes == NULL);
    CHECK(scene_load("builtin:teapot", &s, &e) == -1);
    CHECK(strncmp(e.message, "builtin:teapot: ", 16) == 0);
    CHECK(scene_load("builtin:plane", &s, &e) == 0 && scene_triangle_count(&s) == 2);
    scene_free(&s);
}

int main(void)
{
    test_every_scene();
    test_table();
    test_unknown_name();
    return check_report("test_builtin_scenes");
}
