/* The user's shaders and plug-ins (README.md): `gtlab bench shader`, a screen-space shader's ms per 1080p frame on
 * Vulkan, dispatch only and end to end (shader_bench.h); the stage shader-scores (a project's function files and
 * plug-ins on the multibounce and specular-occlusion references: shader_scores.h), after multibounce, whose
 * references it reads; and the stage screen-shaders (a project's screen_shaders on the AO references:
 * screen_shader_score.h). `gtlab shader run|score` is a verb of its own (cli/verb_shader.c). */
#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"
#include "shader/screen_shader_section.h"
#include "shader/shader_bench.h"
#include "shader/shader_scores_section.h"

static int bench_shader(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_REQUIRED_STRING("shader", "F.glsl|F.hlsl", "a shader of docs/shaders.md's contract, e.g. techniques/gtao/gtao.glsl"),
        CLI_STRING("scene", "S", "builtin:NAME or a glTF file (default builtin:boxes)"),
        CLI_INT32("frames", "N", 1, 4096, "frames (default 4)"), CLI_STRING("device", "NAME", "a Vulkan device"),
        CLI_INT32("width", "W", 8, 8192, "default 1920"), CLI_INT32("height", "H", 8, 8192, "default 1080"), CLI_END};
    static const cli_command command = {"bench shader", "ms per frame of a screen-space shader on Vulkan, dispatch only "
                                        "and end to end, and gtlab's overhead.", options, NULL, NULL};
    shader_bench_request r = {NULL, "builtin:boxes", NULL, SHADER_BENCH_WIDTH, SHADER_BENCH_HEIGHT, 4, threads_default()};
    shader_bench_result b;
    int status;
    gt_error e;
    if (cli_options_parse(&command, (void *[]){&r.shader, &r.scene, &r.frames, &r.device, &r.width, &r.height}, argc,
                          argv, &status) != 0)
        return status;
    return shader_bench_run(&r, &b, &e) != 0 ? cli_fail(&e) : (shader_bench_print(stdout, &r, &b), EXIT_OK);
}

GTLAB_STUDY_STAGE_NO_REQUEST(stage_scores, shader_scores_result, shader_scores_project, shader_scores_section)
GTLAB_STUDY_STAGE_NO_REQUEST(stage_screen, screen_shader_score_result, screen_shader_score_project, screen_shader_section)
const technique technique_shader = {.name = "shader", .subcommands = {[VERB_BENCH] = CLI_SUBCOMMANDS(
                                        {"shader", bench_shader, "a shader's ms per 1080p frame on Vulkan"})},
    .stages = ALL_STAGES({"shader-scores", "the project's shaders, plug-ins", stage_scores, NULL, "multibounce"},
                         {"screen-shaders", "the project's screen-space shaders", stage_screen, NULL, "ao"})};
