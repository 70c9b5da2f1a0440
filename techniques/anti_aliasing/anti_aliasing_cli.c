/* The command-line face of anti-aliasing (Decima, SIGGRAPH 2017; issue 19):
 * `gtlab approx anti-aliasing` (a technique over frames of a pan), `gtlab render
 * frames` (the frames and their truth), `gtlab bench anti-aliasing` and the stage anti-aliasing of
 * `gtlab all` (the study, anti_aliasing_study.h, and its section); the
 * command bodies are in aa_commands.h. */
#include <stdio.h>

#include "anti_aliasing/aa_commands.h"
#include "anti_aliasing/anti_aliasing_section.h"
#include "anti_aliasing/anti_aliasing_study.h"
#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/sampling/pixel_filter.h"
#include "core/threads.h"

GTLAB_STUDY_STAGE(all_stage_aa, aa, aa_section)

static int approx_aa(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_CHOICE("technique", "T", aa_technique_short_name, AA_T_TECHNIQUES, "none, fxaa, taa, edge-taa, checkerboard"),
        CLI_STRING("scene", "S", "builtin:NAME or a glTF file"), CLI_INT32("frames", "N", 1, 100000, "frames"),
        CLI_INT32("threads", "T", 1, 1024, "worker threads; the result does not depend on it"), CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {"approx anti-aliasing", "An AA technique over 384x288 frames of a pan (4 cm, 0.25 deg a "
        "frame): DIR/<technique>_NNN.exr, .png\n(display values; anti_aliasing/aa_commands.h).", options, NULL, NULL};
    aa_frames_request rq = {"builtin:aa-thin", 384, 288, 8, {0.04f, 0.0f, 0.0f}, 0.25f, 3, NULL, (int)threads_default(),
                            0, 0};
    int status;
    gt_error e;
    if (cli_options_parse(&command, (void *[]){&rq.technique, &rq.scene, &rq.frames, &rq.threads, &rq.dir}, argc, argv,
                          &status) != 0 || (status = cli_make_output_dir(rq.dir)) != 0)
        return status;
    return aa_approx(&rq, &e) == 0 ? EXIT_OK : cli_fail(&e);
}

static const char *truth_filter_name(int i) { return pixel_filter_name(i); }

static int render_frames(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_STRING("scene", "S", "builtin:NAME or a glTF file (default builtin:aa-thin)"),
        CLI_INT32("width", "W", 8, 8192, "frame width"), CLI_INT32("height", "H", 8, 8192, "frame height"),
        CLI_INT32("frames", "N", 1, 100000, "frames"),
        CLI_CHOICE("jitter", "T", aa_technique_short_name, AA_T_TECHNIQUES, "whose sub-pixel jitter: none (centres), "
                   "taa (Halton 2,3),\nedge-taa (edge midpoints), checkerboard (corners); fxaa = none"),
        CLI_INT32("truth", "S", 0, 16, "also each frame's truth, S x S stratified samples a pixel\n(4: 16x, 8: 64x; "
                  "0: none)"),
        CLI_CHOICE("filter", "F", truth_filter_name, PIXEL_FILTER_COUNT, "the truth's pixel filter: box or "
                   "blackman-harris"),
        CLI_INT32("threads", "T", 1, 1024, "worker threads; the result does not depend on it"), CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {"render frames", "Shaded frames (sun + sky, shadow rays) of a pan, 4 cm and 0.25 "
        "deg a frame: DIR/frame_NNN.exr with\nframe.R/G/B (linear), depth.Z, motion.X/Y, disoccluded.V and, with "
        "--truth, truth.R/G/B\n(anti_aliasing/aa_commands.h).", options, NULL, NULL};
    aa_frames_request rq = {"builtin:aa-thin", 384, 288, 8, {0.04f, 0.0f, 0.0f}, 0.25f, 0, NULL, (int)threads_default(),
                            0, PIXEL_FILTER_BLACKMAN_HARRIS};
    int status;
    gt_error e;
    if (cli_options_parse(&command, (void *[]){&rq.scene, &rq.width, &rq.height, &rq.frames, &rq.technique,
                                              &rq.truth_strata, &rq.truth_filter, &rq.threads, &rq.dir},
                          argc, argv, &status) != 0 || (status = cli_make_output_dir(rq.dir)) != 0)
        return status;
    return aa_frames_write(&rq, &e) == 0 ? EXIT_OK : cli_fail(&e);
}

static int bench_aa(int argc, char **argv)
{
    static const cli_option options[] = {CLI_THREADS, CLI_END};
    static const cli_command command = {"bench anti-aliasing", "ms per 1920x1080 frame per AA technique, in C.", options, NULL, NULL};
    long threads = threads_default();
    int status;
    gt_error e;
    if (cli_options_parse(&command, (void *[]){&threads}, argc, argv, &status) != 0)
        return status;
    return aa_bench_print(stdout, (int)threads, &e) == 0 ? EXIT_OK : cli_fail(&e);
}

const technique technique_anti_aliasing = {
    .name = "anti-aliasing",
    .subcommands = {[VERB_APPROX] = CLI_SUBCOMMANDS({"anti-aliasing", approx_aa, "anti-aliasing over frames of a pan"}),
                    [VERB_RENDER] = CLI_SUBCOMMANDS({"frames", render_frames, "shaded frames of a pan with motion, and their truth"}),
                    [VERB_BENCH] = CLI_SUBCOMMANDS({"anti-aliasing", bench_aa, "anti-aliasing: ms per 1080p frame"})},
    .stages = ALL_STAGES({"anti-aliasing", "anti-aliasing against supersampled truth", all_stage_aa, AA_DIR, NULL}),
    .renamed = TECHNIQUE_RENAMES({"aa", "anti-aliasing"}),
};
