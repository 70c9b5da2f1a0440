/* gtlab render QUANTITY: a reference image rendered with Embree. */
#define _GNU_SOURCE
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "core/atomic_file.h"
#include "core/exr_io.h"
#include "raytracer/reference_render.h"
#include "scene/scene_loaders.h"
#include "core/threads.h"

enum { MAX_QUANTITY_OPTIONS = 64, FIRST_QUANTITY_OPTION = 256 };

/* Prints text's lines, the first where the cursor is, the others indented. */
static void print_indented(const char *text, int indent)
{
    for (const char *line = text; line;) {
        const char *end = strchr(line, '\n');
        printf("%.*s\n", end ? (int)(end - line) : (int)strlen(line), line);
        if ((line = end ? end + 1 : NULL))
            printf("%*s", indent, "");
    }
}

/* "  --name VALUE          q1, q2 (required): help": a quantity option. */
static void print_option_help(const reference_option *option)
{
    char synopsis[128], owners[256];
    snprintf(synopsis, sizeof synopsis, "--%s%s%s", option->name, option->value ? " " : "",
             option->value ? option->value : "");
    reference_option_owners(option, ", ", owners, sizeof owners);
    printf("  %-20s  %s%s: ", synopsis, owners, option->required ? " (required)" : "");
    print_indented(option->help, 24);
}

static void print_help(void)
{
    printf("usage: gtlab render QUANTITY --scene F.glb|builtin:NAME -o out.exr [options]\n"
           "\n"
           "Renders a reference quantity at the surface seen through each pixel centre.\n"
           "QUANTITY:\n");
    for (int i = 0; i < reference_quantity_count(); ++i) {
        printf("  %-8s  ", reference_quantity_at(i)->name);
        print_indented(reference_quantity_at(i)->help, 12);
    }
    printf("\n"
           "options:\n"
           "  --scene S             a .gltf/.glb file or builtin:NAME ('gtlab scene list')\n"
           "  --camera cam.json     camera JSON (default: the scene's camera, else a 3/4 view)\n"
           "  --width W --height H  image size (one alone keeps the camera's aspect ratio)\n"
           "  --spp N               samples per pixel, at most (default 64)\n"
           "  --seed S              sequence seed (default 1)\n"
           "  --sample-offset K     first sample index: renders the block [K, K+N) so blocks\n"
           "                        of one seed can be rendered apart and merged\n"
           "  --target-stderr E     stop a pixel once the standard error of its first channel\n"
           "                        (ao.V; multibounce: the first multibounce channel;\n"
           "                        specular-occlusion: specocc_occluded.V) is <= E\n"
           "                        (checked at 64, 128, 256, ... samples)\n");
    for (int i = 0; i < reference_option_count(); ++i)
        print_option_help(reference_option_at(i));
    printf("  --normal shading|geometric   normal the hemisphere is built on (default shading)\n"
           "  --threads T           worker threads (default: all cores); the output does not\n"
           "                        depend on it\n"
           "  -o, --output F.exr    output EXR; the camera used goes to F.camera.json\n"
           "  -h, --help\n");
}

typedef struct {
    const char *scene, *camera, *output;
    long width, height;
    reference_request request;
    /* The quantity options as given (reference_option_at(i); "" for a flag), or NULL. */
    const char *values[MAX_QUANTITY_OPTIONS];
} render_options;

static const struct option common_options[] = {
    {"scene", required_argument, 0, 's'},         {"camera", required_argument, 0, 'c'},
    {"width", required_argument, 0, 'W'},         {"height", required_argument, 0, 'H'},
    {"spp", required_argument, 0, 'n'},           {"seed", required_argument, 0, 'S'},
    {"sample-offset", required_argument, 0, 'k'}, {"target-stderr", required_argument, 0, 'e'},
    {"normal", required_argument, 0, 'N'},        {"threads", required_argument, 0, 't'},
    {"output", required_argument, 0, 'o'},        {"help", no_argument, 0, 'h'}};
enum { COMMON_OPTIONS = sizeof common_options / sizeof common_options[0] };

/* The common options, then every quantity's (FIRST_QUANTITY_OPTION + i for
 * reference_option_at(i)), then the terminator. -1 if they do not fit. */
static int build_long_options(struct option *longs)
{
    memcpy(longs, common_options, sizeof common_options);
    int n = reference_option_count();
    if (n > MAX_QUANTITY_OPTIONS)
        return cli_failf("render", "more than %d quantity options: raise MAX_QUANTITY_OPTIONS", MAX_QUANTITY_OPTIONS), -1;
    for (int i = 0; i < n; ++i) {
        const reference_option *option = reference_option_at(i);
        longs[COMMON_OPTIONS + i] = (struct option){option->name, option->value ? required_argument : no_argument, 0,
                                                    FIRST_QUANTITY_OPTION + i};
    }
    longs[COMMON_OPTIONS + n] = (struct option){0, 0, 0, 0};
    return 0;
}

/* One common option; 1 after --help, -1 on error. */
static int parse_common_option(int c, render_options *o)
{
    long value;
    sampling_settings *ss = &o->request.sampling;
    switch (c) {
    case 's': o->scene = optarg; return 0;
    case 'c': o->camera = optarg; return 0;
    case 'o': o->output = optarg; return 0;
    case 'W': return cli_parse_int("--width", optarg, 1, 65536, &o->width);
    case 'H': return cli_parse_int("--height", optarg, 1, 65536, &o->height);
    case 'n': return cli_parse_int("--spp", optarg, 1, 1 << 24, &value) ? -1 : (ss->spp = (int)value, 0);
    case 'S': return cli_parse_u32("--seed", optarg, &ss->seed);
    case 'k': return cli_parse_u32("--sample-offset", optarg, &ss->sample_offset);
    case 'e': return cli_parse_double("--target-stderr", optarg, 0.0, 1.0, &ss->target_stderr);
    case 't': return cli_parse_int("--threads", optarg, 1, 1024, &value) ? -1 : (ss->threads = (int)value, 0);
    case 'N':
        if (strcmp(optarg, "shading") == 0)
            o->request.normals = NORMAL_SHADING;
        else if (strcmp(optarg, "geometric") == 0)
            o->request.normals = NORMAL_GEOMETRIC;
        else
            return cli_failf("--normal", "'%s' is neither shading nor geometric", optarg), -1;
        return 0;
    case 'h': print_help(); return 1;
    default: return cli_usage_error("render"), -1;
    }
}

/* The QUANTITY argument, then its defaults and its options (refusing those
 * of other quantities). */
static int parse_quantity(int argc, char **argv, render_options *o)
{
    char names[512];
    reference_quantity_names(names, sizeof names);
    if (optind >= argc)
        return cli_failf("render", "no QUANTITY given (%s; see 'gtlab render --help')", names), -1;
    reference_request *rq = &o->request;
    if (reference_quantity_parse(argv[optind], &rq->quantity) != 0)
        return cli_failf("render", "unknown quantity '%s' (%s)", argv[optind], names), -1;
    if (optind + 1 < argc)
        return cli_failf("render", "unexpected argument '%s'", argv[optind + 1]), -1;
    if (rq->quantity->settings_size && !(rq->settings = calloc(1, rq->quantity->settings_size)))
        return cli_failf("render", "out of memory"), -1;
    if (rq->quantity->set_defaults)
        rq->quantity->set_defaults(rq);
    gt_error e;
    return reference_options_apply(rq, o->values, "render", &e) != 0 ? (cli_fail(&e), -1) : 0;
}

static int parse_options(int argc, char **argv, render_options *o)
{
    struct option longs[COMMON_OPTIONS + MAX_QUANTITY_OPTIONS + 1];
    if (build_long_options(longs) != 0)
        return -1;
    int c, quantity_options = reference_option_count();
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        int parsed = 0;
        if (c >= FIRST_QUANTITY_OPTION && c < FIRST_QUANTITY_OPTION + quantity_options)
            o->values[c - FIRST_QUANTITY_OPTION] = optarg ? optarg : "";
        else if ((parsed = parse_common_option(c, o)) != 0)
            return parsed;
    }
    if (parse_quantity(argc, argv, o) != 0)
        return -1;
    if (!o->scene)
        return cli_failf("render", "--scene is required"), -1;
    if (!o->output)
        return cli_failf("render", "-o/--output is required"), -1;
    if ((uint64_t)o->request.sampling.sample_offset + (uint64_t)o->request.sampling.spp > 4294967296ull)
        return cli_failf("--sample-offset", "the block runs past sample index 2^32"), -1;
    return 0;
}

/* Renders the parsed request and writes the EXR and its camera. */
static int render(const render_options *o)
{
    gt_error e;
    char camera_path[ATOMIC_PATH_MAX];
    camera_sidecar_path(o->output, camera_path, sizeof camera_path);
    if (atomic_file_check_writable(o->output, &e) != 0 || atomic_file_check_writable(camera_path, &e) != 0)
        return cli_fail(&e);
    scene s;
    if (scene_load(o->scene, &s, &e) != 0)
        return cli_fail(&e);
    camera cam;
    image out;
    render_stats stats;
    int status = EXIT_OK;
    if (scene_choose_camera(&s, o->camera, (int)o->width, (int)o->height, &cam, &e) != 0 ||
        reference_render(&s, o->scene, &cam, &o->request, &out, &stats, &e) != 0) {
        status = cli_fail(&e);
    } else {
        if (exr_write(o->output, &out, &e) != 0 || camera_write_json(camera_path, &cam, &e) != 0)
            status = cli_fail(&e);
        else if (o->request.quantity->prepare /* sampled */)
            printf("%s: %dx%d, %.3g samples, %.3g rays in %.2f s (%.3g rays/s)\n", o->output,
                    cam.width, cam.height, (double)stats.samples, (double)stats.rays, stats.seconds,
                    stats.seconds > 0 ? (double)stats.rays / stats.seconds : 0.0);
        image_free(&out);
    }
    scene_free(&s);
    return status;
}

int verb_render(int argc, char **argv)
{
    render_options o = {0};
    o.request.sampling.spp = 64;
    o.request.sampling.seed = 1;
    o.request.sampling.threads = threads_default();
    int parsed = parse_options(argc, argv, &o);
    if (parsed != 0) {
        free(o.request.settings);
        return parsed > 0 ? EXIT_OK : EXIT_USER_ERROR;
    }
    int status = render(&o);
    free(o.request.settings);
    return status;
}
