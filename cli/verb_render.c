/* gtlab render QUANTITY: a reference image rendered with Embree. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/render_quantities.h"
#include "cli/technique.h"
#include "core/files/atomic_file.h"
#include "core/files/exr_io.h"
#include "core/files/run_inputs.h"
#include "raytracer/distributed_render.h"
#include "raytracer/reference_render.h"
#include "raytracer/render_checkpoint_files.h"
#include "scene/scene_loaders.h"
#include "core/threads.h"

enum { MAX_QUANTITY_OPTIONS = 64, HELP_SIZE = 16384 };

static const char *normal_name(int i) { return i == NORMAL_GEOMETRIC ? "geometric" : "shading"; }

static const cli_option common_options[] = {
    CLI_STRING("scene", "S", "a .gltf/.glb file or builtin:NAME ('gtlab scene list')"),
    CLI_STRING("camera", "cam.json", "camera JSON (default: the scene's camera, else a 3/4 view)"),
    CLI_INT("width", "W", 1, 65536, "image width (default: the camera's; --width or --height\nalone keeps the camera's aspect ratio)"),
    CLI_INT("height", "H", 1, 65536, "image height (default: the camera's)"),
    CLI_INT32("spp", "N", 1, 1 << 24, "samples per pixel, at most"),
    CLI_SEED("seed", "sequence seed"),
    CLI_INT("sample-offset", "K", 0, 4294967295.0, "first sample index: renders the block [K, K+N) so blocks\n"
             "of one seed can be rendered apart and merged"),
    CLI_DOUBLE("target-stderr", "E", 0.0, 1.0, "stop a pixel once the standard error of its first channel\n"
               "(ao.V; multibounce: the first multibounce channel;\nspecular-occlusion: specocc_occluded.V) is <= E\n"
               "(checked at 64, 128, 256, ... samples; default 0: never)"),
    CLI_CHOICE("normal", "shading|geometric", normal_name, 2, "normal the hemisphere is built on"),
    CLI_INT32("threads", "T", 1, 1024, "worker threads (default: all cores); the output does not\ndepend on it"),
    CLI_FLAG("resume", "continue from F.checkpoint.exr, left by an interrupted render\n(the bits of an uninterrupted one; "
             "under mpirun -n N each\nrank its F.checkpoint.rank<r>-of-<N>.exr, N as before)"),
    CLI_OUTPUT("F.exr", 0, "output EXR; the camera used goes to F.camera.json")};
enum { COMMON_OPTIONS = sizeof common_options / sizeof common_options[0] };

typedef struct {
    const char *scene, *camera, *output;
    long width, height, seed, sample_offset;
    reference_request request;
    /* The quantity options as given (reference_option_at(render_quantities(), i); "" for a flag), or NULL. */
    const char *values[MAX_QUANTITY_OPTIONS];
    int flags[MAX_QUANTITY_OPTIONS];
} render_options;

/* Appends text to help[*k], its continuation lines indented. */
static void append_indented(char *help, int *k, const char *text, int indent)
{
    for (const char *p = text; *p && *k < HELP_SIZE - indent - 2; ++p)
        *k += *p == '\n' ? snprintf(help + *k, HELP_SIZE - (size_t)*k, "\n%*s", indent, "")
                         : (help[*k] = *p, help[*k + 1] = '\0', 1);
}

/* The help's paragraph with every quantity, and each quantity option's
 * help ("q1, q2 (required): help") into texts, from one buffer. */
static void describe(char *help, const char *texts[MAX_QUANTITY_OPTIONS])
{
    const reference_registry *quantities = render_quantities();
    int k = snprintf(help, HELP_SIZE, "Renders a reference quantity at the surface seen through each pixel centre.\n"
                                      "QUANTITY:");
    for (int i = 0; i < reference_quantity_count(quantities); ++i) {
        k += snprintf(help + k, HELP_SIZE - (size_t)k, "\n  %-8s  ", reference_quantity_at(quantities, i)->name);
        append_indented(help, &k, reference_quantity_at(quantities, i)->help, 12);
    }
    cli_subcommand more[8]; /* not reference quantities: a technique's own (their options: --help) */
    for (size_t i = 0, n = technique_subcommands(VERB_RENDER, more, 8); i < n; ++i)
        k += snprintf(help + k, HELP_SIZE - (size_t)k, "\n  %-8s  %s (own options: 'gtlab render %s --help')",
                      more[i].name, more[i].summary, more[i].name);
    for (int i = 0; i < reference_option_count(quantities) && k < HELP_SIZE - 512; ++i) {
        const reference_option *option = reference_option_at(quantities, i);
        char text[1024];
        texts[i] = help + ++k;
        reference_option_owners(quantities, option, ", ", help + k, 256);
        k += (int)strlen(help + k);
        reference_option_help(quantities, option, text, sizeof text);
        k += snprintf(help + k, HELP_SIZE - (size_t)k, "%s: %s", option->required ? " (required)" : "", text);
    }
}

/* The QUANTITY argument, then its defaults and its options (refusing those
 * of other quantities). */
static int parse_quantity(const cli_arguments *args, render_options *o)
{
    const reference_registry *quantities = render_quantities();
    char names[512];
    reference_quantity_names(quantities, names, sizeof names);
    if (args->count == 0)
        return cli_failf("render", "no QUANTITY given (%s; see 'gtlab render --help')", names), -1;
    reference_request *rq = &o->request;
    if (reference_quantity_parse(quantities, args->values[0], &rq->quantity) != 0)
        return cli_failf("render", "unknown quantity '%s' (%s)", args->values[0], names), -1;
    if (args->count > 1)
        return cli_failf("render", "unexpected argument '%s'", args->values[1]), -1;
    if (rq->quantity->settings_size && !(rq->settings = reference_settings_new(rq->quantity)))
        return cli_failf("render", "out of memory"), -1;
    if (rq->quantity->set_defaults)
        rq->quantity->set_defaults(rq);
    for (int i = 0; i < reference_option_count(quantities); ++i)
        if (o->flags[i])
            o->values[i] = "";
    gt_error e;
    return reference_options_apply(quantities, rq, o->values, "render", &e) != 0 ? (cli_fail(&e), -1) : 0;
}

/* The common options, then every quantity's; 0 to go on, else 1 and the exit status. */
static int parse_options(int argc, char **argv, render_options *o, int *status)
{
    static cli_option options[COMMON_OPTIONS + MAX_QUANTITY_OPTIONS + 1];
    static char help[HELP_SIZE];
    const char *texts[MAX_QUANTITY_OPTIONS] = {0};
    sampling_settings *ss = &o->request.sampling;
    void *dest[COMMON_OPTIONS + MAX_QUANTITY_OPTIONS + 1] = {&o->scene, &o->camera, &o->width, &o->height, &ss->spp,
        &o->seed, &o->sample_offset, &ss->target_stderr, &o->request.normals, &ss->threads, &o->request.resume, &o->output};
    const reference_registry *quantities = render_quantities();
    int n = reference_option_count(quantities);
    if (n > MAX_QUANTITY_OPTIONS)
        return *status = cli_failf("render", "more than %d quantity options", MAX_QUANTITY_OPTIONS), 1;
    describe(help, texts);
    memcpy(options, common_options, sizeof common_options);
    for (int i = 0; i < n; ++i) {
        const reference_option *q = reference_option_at(quantities, i);
        options[COMMON_OPTIONS + i] = q->value ? (cli_option)CLI_STRING(q->name, q->value, texts[i])
                                               : (cli_option)CLI_FLAG(q->name, texts[i]);
        dest[COMMON_OPTIONS + i] = q->value ? (void *)&o->values[i] : (void *)&o->flags[i];
    }
    options[COMMON_OPTIONS + n] = (cli_option)CLI_END;
    cli_arguments quantity;
    dest[COMMON_OPTIONS + n] = &quantity;
    const cli_command command = {"render", help, options, "QUANTITY", NULL};
    if (cli_options_parse(&command, dest, argc, argv, status) != 0)
        return 1;
    *status = EXIT_USER_ERROR;
    if (parse_quantity(&quantity, o) != 0)
        return 1;
    if (!o->scene)
        return cli_failf("render", "--scene is required"), 1;
    if (!o->output)
        return cli_failf("render", "-o/--output is required"), 1;
    if ((uint64_t)o->sample_offset + (uint64_t)ss->spp > 4294967296ull)
        return cli_failf("--sample-offset", "the block runs past sample index 2^32"), 1;
    ss->seed = (uint32_t)o->seed, ss->sample_offset = (uint32_t)o->sample_offset;
    return *status = EXIT_OK, 0;
}

/* Renders the parsed request and writes the EXR and its camera. */
static int render(const render_options *o)
{
    gt_error e;
    char camera_path[ATOMIC_PATH_MAX], checkpoint[ATOMIC_PATH_MAX];
    camera_sidecar_path(o->output, camera_path, sizeof camera_path);
    reference_request request = o->request;
    request.checkpoint = checkpoint;
    if (atomic_file_check_writable(o->output, &e) != 0 || atomic_file_check_writable(camera_path, &e) != 0 ||
        distributed_begin(&e) != 0)
        return cli_fail(&e);
    if (render_checkpoint_prepare(o->output, request.resume, checkpoint, sizeof checkpoint, &e) != 0 ||
        run_inputs_check_output(checkpoint, &e) != 0) /* the render writes it, then removes it */
        return distributed_is_writer() ? cli_fail(&e) : EXIT_USER_ERROR; /* every rank finds it: rank 0 says it */
    scene s;
    if (scene_load(o->scene, &s, &e) != 0)
        return cli_fail(&e);
    camera cam;
    image out;
    render_stats stats;
    int status = EXIT_OK;
    if (scene_choose_camera(&s, o->camera, (int)o->width, (int)o->height, &cam, &e) != 0 ||
        reference_render(&s, o->scene, &cam, &request, &out, &stats, &e) != 0) {
        status = cli_fail(&e);
    } else {
        const int writer = distributed_is_writer(); /* under mpirun, rank 0 alone */
        if (writer && (exr_write(o->output, &out, &e) != 0 || camera_write_json(camera_path, &cam, &e) != 0))
            status = cli_fail(&e);
        else if (writer && o->request.quantity->prepare /* sampled */)
            printf("%s: %dx%d, %.3g samples, %.3g rays in %.2f s (%.3g rays/s)\n", o->output,
                    cam.width, cam.height, (double)stats.samples, (double)stats.rays, stats.seconds,
                    stats.seconds > 0 ? (double)stats.rays / stats.seconds : 0.0);
        image_free(&out);
    }
    render_checkpoint_finish(checkpoint, status == EXIT_OK); /* every rank: removed once rank 0 wrote */
    scene_free(&s);
    return status;
}

int verb_render(int argc, char **argv)
{
    cli_subcommand more[8];
    for (size_t i = 0, n = technique_subcommands(VERB_RENDER, more, 8); argc >= 2 && i < n; ++i)
        if (strcmp(argv[1], more[i].name) == 0)
            return cli_reset_getopt(), more[i].run(argc - 1, argv + 1);
    render_options o = {.seed = 1};
    o.request.sampling.spp = 64;
    o.request.sampling.threads = threads_default();
    int status;
    if (parse_options(argc, argv, &o, &status) != 0) {
        free(o.request.settings);
        return status;
    }
    status = render(&o);
    free(o.request.settings);
    return status;
}
