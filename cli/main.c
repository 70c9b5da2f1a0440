/* gtlab: Monte Carlo ground truth and fitting for real-time rendering. */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "core/files/output_set.h"

typedef struct {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} verb;

static const verb verbs[] = {
    {"scene", verb_scene, "list the built-in scenes, or write one as .glb"},
    {"render", verb_render, "render a reference (gbuffer, ao, multibounce, heightfield-ao, ...) with Embree"},
    {"merge", verb_merge, "combine partial renders of disjoint sample blocks exactly"},
    {"plan", verb_plan, "split a render into jobs for Slurm or any batch scheduler"},
    {"approx", verb_approx, "a real-time approximation on a G-buffer (gtao, hbao, vo, specular-occlusion)"},
    {"compare", verb_compare, "SSIM/DSSIM, RMSE and absolute errors between two EXRs"},
    {"fit", verb_fit, "fit a real-time model's constants to references (Ceres)"},
    {"bench", verb_bench, "throughput figures (rays/s) and their ratios, from one run"},
    {"check", verb_check, "accuracy checks against brute force (sphere-noh, ...)"},
    {"shader", verb_shader, "run a GLSL/HLSL screen-space shader on Vulkan over a G-buffer, and score it"},
    {"lut", verb_lut, "lookup tables in every format (EXR, 8-bit PNG, C header)"},
    {"all", verb_all, "the main job: every reference and the accuracy report"},
    {"init", verb_init, "write an example project file (gtlab.json) for 'gtlab all --project'"},
};

static void print_help(FILE *out)
{
    fprintf(out, "gtlab %s — Monte Carlo ground truth and fitting for real-time rendering\n\n", GTLAB_VERSION);
    fprintf(out, "usage: gtlab <verb> [options]     (gtlab <verb> --help for each)\n\nverbs:\n");
    for (size_t i = 0; i < sizeof verbs / sizeof verbs[0]; ++i)
        fprintf(out, "  %-9s %s\n", verbs[i].name, verbs[i].summary);
    fprintf(out, "\nErrors are one line on stderr; exit status 0 success, 1 bad input, 2 internal error.\n");
}

/* A verb's files are kept together or not at all (core/files/output_set.h):
 * on failure or interruption none of them stays, and what they replaced
 * is back. */
static int run_verb(const verb *v, int argc, char **argv)
{
    output_set_install_signal_handlers();
    output_set_begin();
    int status = v->run(argc, argv);
    gt_error e;
    if (status != EXIT_OK)
        output_set_abort();
    else if (output_set_commit(&e) != 0)
        gt_warn("gtlab", "%s", e.message);
    return status;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        print_help(stderr);
        return EXIT_USER_ERROR;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        print_help(stdout);
        return EXIT_OK;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("gtlab %s\n", GTLAB_VERSION);
        return EXIT_OK;
    }
    for (size_t i = 0; i < sizeof verbs / sizeof verbs[0]; ++i) {
        if (strcmp(argv[1], verbs[i].name) == 0) {
            cli_reset_getopt();
            return run_verb(&verbs[i], argc - 1, argv + 1);
        }
    }
    fprintf(stderr, "gtlab: %s: unknown verb (see 'gtlab --help')\n", argv[1]);
    return EXIT_USER_ERROR;
}
