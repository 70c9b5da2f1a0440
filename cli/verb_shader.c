/* gtlab shader run: a user's screen-space GLSL/HLSL on Vulkan over a G-buffer
 * (docs/shaders.md; the work is techniques/shader/shader_run.c), optionally scored. */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/subcommands.h"
#include "shader/shader_run.h"
#include "shader/shader_scores.h"

enum { MAX_PARAMS = 64 };

static const cli_option options[] = {
    CLI_REQUIRED_STRING("shader", "F.glsl|F.hlsl", "the compute shader (the language by the extension)"),
    CLI_STRING("entry", "NAME", "entry point (default main; GLSL's is always main)"),
    CLI_REQUIRED_STRING("gbuffer", "G.exr", "G-buffer: depth.Z, N.X/Y/Z, mask.A (and P, albedo, roughness, bent)"),
    CLI_STRING("camera", "C.json", "camera (default: the G-buffer's gtlab.camera or its sidecar)"),
    CLI_CUSTOM("param", "NAME=VALUE", cli_list_add, "a gtlab.param of the shader (the option may repeat)"),
    CLI_INT32("frames", "N", 1, 4096, "frames dispatched (Gtlab.frame 0..N-1) and averaged"),
    CLI_DOUBLE("timeout", "S", 0.001, 86400, "seconds a frame may take before 'device timeout'"),
    CLI_STRING("device", "NAME", "a Vulkan device whose name contains NAME (default: a GPU, else lavapipe)"),
    CLI_OUTPUT("out.exr", 1, "the shader's outputs (its gtlab.output channels) and mask.A"),
    CLI_STRING("reference", "R.exr", "score the output against this reference (DSSIM, RMSE, noise floor)"),
    CLI_STRING("channel", "CH", "the channel scored (default: the shader's first output)"),
    CLI_END};
static const cli_command command = {"shader run", "Runs a screen-space compute shader on Vulkan over a G-buffer "
                                    "(the binding contract:\ndocs/shaders.md) and writes its outputs.",
                                    options, NULL, NULL};

static int shader_run_command(int argc, char **argv)
{
    const char *params[MAX_PARAMS];
    cli_list list = {params, 0, MAX_PARAMS, "--param"};
    shader_run_request r = {.frames = 1, .timeout = 10.0};
    void *dest[] = {&r.shader, &r.entry, &r.gbuffer, &r.camera, &list, &r.frames, &r.timeout, &r.device, &r.output,
                    &r.reference, &r.channel};
    int status;
    if (cli_options_parse(&command, dest, argc, argv, &status) != 0)
        return status;
    r.params = list.values, r.param_count = list.count;
    shader_run_result result;
    gt_error e;
    if (shader_run(&r, &result, &e) != 0)
        return cli_fail(&e);
    shader_run_print(stdout, &result);
    return EXIT_OK;
}

static const cli_option score_options[] = {
    CLI_CUSTOM("function", "F.glsl|F.hlsl", cli_list_add, "a function file (docs/shaders.md; the option may repeat)"),
    CLI_CUSTOM("plugin", "LIB.so", cli_list_add, "a C plug-in (core/plugin_abi.h; the option may repeat)"),
    CLI_STRING("quantity", "Q", "the quantity approximated: multibounce (the default) or specular-occlusion"),
    CLI_CUSTOM("ao", "AO.exr", cli_list_add, "specular-occlusion: each reference's 'gtlab render ao' (in order)"),
    CLI_DOUBLE("timeout", "S", 0.001, 86400, "seconds a dispatch may take before 'device timeout'"),
    CLI_STRING("device", "NAME", "a Vulkan device whose name contains NAME (default: a GPU, else lavapipe)"), CLI_END};
static const cli_command score_command = {"shader score", "Scores per-sample functions (GLSL/HLSL) and C plug-ins "
    "beside gtlab's own on\nmulti-bounce references ('gtlab render multibounce --albedo ...'), as the multibounce\n"
    "stage validates its fit, or on specular-occlusion references (docs/shaders.md).", score_options, "REF.exr ...",
    NULL};

static int shader_score_command(int argc, char **argv)
{
    enum { MAX = FUNCTION_SCORE_MAX_FILES };
    const char *functions[MAX], *plugins[MAX], *aos[MAX];
    cli_list f = {functions, 0, MAX, "--function"}, p = {plugins, 0, MAX, "--plugin"}, a = {aos, 0, MAX, "--ao"};
    shader_score_request r = {.aos = aos, .files = {.functions = functions, .plugins = plugins, .timeout = 10.0}};
    cli_arguments refs;
    int status;
    if (cli_options_parse(&score_command,
                          (void *[]){&f, &p, &r.quantity, &a, &r.files.timeout, &r.files.device, &refs}, argc, argv,
                          &status) != 0)
        return status;
    r.files.function_count = f.count, r.files.plugin_count = p.count, r.reference_count = refs.count;
    r.ao_count = a.count;
    r.references = (const char *const *)refs.values;
    static function_score_result result;
    gt_error e;
    return shader_score(&r, &result, &e) != 0 ? cli_fail(&e) : (function_score_print(stdout, &result), EXIT_OK);
}

static const cli_subcommand subcommands[] = {{"run", shader_run_command, "a screen-space shader over a G-buffer"},
                                             {"score", shader_score_command, "per-sample functions and plug-ins"}};

int verb_shader(int argc, char **argv)
{
    static const cli_subcommand_verb verb = {"shader", "run|score [options]", "subcommands",
                                             "shader subcommand", subcommands, 2, NULL};
    return cli_run_subcommand(&verb, argc, argv);
}
