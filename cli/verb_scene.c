/* `gtlab scene list` prints every built-in scene with its exact geometry;
 * `gtlab scene write NAME -o F.glb` writes one as a real binary glTF, so any
 * other renderer can be run on exactly the geometry gtlab's references saw;
 * `gtlab scene info SCENE` says what gtlab made of a scene file. */
#define _GNU_SOURCE
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "scene/builtin_scene_family.h"
#include "scene/builtin_scenes.h"
#include "scene/gltf/gltf_reader.h"
#include "scene/gltf/gltf_writer.h"
#include "scene/scene_describe.h"
#include "scene/scene_loaders.h"

static const cli_option no_options[] = {CLI_END};
static const cli_option write_options[] = {CLI_OUTPUT("F.glb", 0, "the file to write (required)"), CLI_END};
static const cli_command list_command = {
    "scene list",
    "Prints the name of every built-in scene with its exact geometry (units, positions, sizes,\n"
    "normals), materials and default camera. Any verb taking a scene accepts builtin:NAME.",
    no_options, NULL, NULL};
static const cli_command write_command = {
    "scene write",
    "Writes the built-in scene NAME (see 'gtlab scene list') as binary glTF 2.0 with its\n"
    "materials and camera; the file appears whole or not at all.",
    write_options, "NAME", NULL};
static int scene_list(int argc, char **argv)
{
    int status;
    if (cli_options_parse(&list_command, NULL, argc, argv, &status) != 0)
        return status;
    printf("Built-in scenes: use them as builtin:NAME, write them with 'gtlab scene write NAME -o F.glb'.\n"
           "Units are arbitrary (think metres); +Y is up; all normals are unit length.\n");
    for (int i = 0; i < builtin_scene_count(); ++i) {
        putchar('\n');
        builtin_scene_describe(stdout, builtin_scene_at(i));
    }
    putchar('\n');
    family_describe(stdout);
    return EXIT_OK;
}

static const cli_command info_command = {
    "scene info",
    "What gtlab reads from a .gltf/.glb file or builtin:NAME: its meshes (one per glTF\n"
    "primitive, in world space) with their triangles, vertices and material, and whether\n"
    "each had normals; a primitive without NORMAL is flat-shaded (glTF 2.0, \"Meshes\"):\n"
    "each triangle gets its own vertices and its face normal. For a glTF file, also how it\n"
    "was read: the extensions it uses, its primitives by mode (strips and fans become\n"
    "triangles; points and lines are skipped), quantized and compressed data (with the\n"
    "largest position quantization step in world units), sparse accessors, morph targets\n"
    "and skins applied in their default pose, and primitives without normals.",
    no_options, "SCENE", NULL};

/* builtin:NAME through the loader table, any other spec as a glTF file
 * with the reader's report. */
static int load_for_info(const char *spec, scene *s, gltf_report *r, int *is_gltf, gt_error *e)
{
    *is_gltf = strncmp(spec, "builtin:", 8) != 0;
    if (!*is_gltf)
        return scene_load(spec, s, e);
    return gltf_load_report(spec, s, r, e);
}

static int scene_info(int argc, char **argv)
{
    cli_arguments spec;
    int status;
    if (cli_options_parse(&info_command, (void *[]){&spec}, argc, argv, &status) != 0)
        return status;
    if (spec.count != 1)
        return cli_failf("scene info", "expected one scene: a .gltf/.glb file or builtin:NAME");
    scene s;
    gt_error e;
    gltf_report report;
    int is_gltf;
    if (load_for_info(spec.values[0], &s, &report, &is_gltf, &e) != 0)
        return cli_fail(&e);
    scene_describe(stdout, &s);
    if (is_gltf)
        gltf_report_describe(stdout, &report);
    scene_free(&s);
    return EXIT_OK;
}

static int has_glb_suffix(const char *path)
{
    size_t n = strlen(path);
    return n > 4 && strcasecmp(path + n - 4, ".glb") == 0;
}

static int scene_write(int argc, char **argv)
{
    const char *output = NULL;
    cli_arguments names;
    int status;
    if (cli_options_parse(&write_command, (void *[]){&output, &names}, argc, argv, &status) != 0)
        return status;
    if (names.count != 1)
        return cli_failf("scene write", "expected one scene name (see 'gtlab scene list')");
    if (!output)
        return cli_failf("scene write", "missing -o F.glb (see 'gtlab scene --help')");
    if (!has_glb_suffix(output))
        return cli_failf(output, "'gtlab scene write' writes binary glTF: name the output *.glb");
    const char *name = names.values[0];
    if (strncmp(name, "builtin:", 8) == 0)
        name += 8;
    scene s;
    gt_error e;
    if (builtin_scene_build(name, &s, &e) != 0) {
        cli_fail(&e);
        return builtin_scene_find(name) ? EXIT_INTERNAL_ERROR : EXIT_USER_ERROR; /* known name: out of memory */
    }
    int rc = gltf_write_glb(output, &s, &e);
    if (rc == 0)
        printf("%s: %s, %llu triangles, %d mesh%s\n", output, s.name,
               (unsigned long long)scene_triangle_count(&s), s.mesh_count, s.mesh_count == 1 ? "" : "es");
    scene_free(&s);
    return rc == 0 ? EXIT_OK : cli_fail(&e);
}

int verb_scene(int argc, char **argv)
{
    if (argc >= 2 && strcmp(argv[1], "list") == 0)
        return scene_list(argc - 1, argv + 1);
    if (argc >= 2 && strcmp(argv[1], "write") == 0)
        return scene_write(argc - 1, argv + 1);
    if (argc >= 2 && strcmp(argv[1], "info") == 0)
        return scene_info(argc - 1, argv + 1);
    if (argc == 2 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        const char *none = NULL;
        cli_options_print_help(&list_command, NULL);
        cli_options_print_help(&write_command, (void *[]){&none});
        cli_options_print_help(&info_command, NULL);
        return EXIT_OK;
    }
    if (argc < 2)
        return cli_failf("scene", "expected 'list', 'write' or 'info' (see 'gtlab scene --help')");
    return cli_failf("scene", "unknown subcommand '%s' (see 'gtlab scene --help')", argv[1]);
}
