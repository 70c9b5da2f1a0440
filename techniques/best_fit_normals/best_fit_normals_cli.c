/* The command-line face of best-fit normals: `gtlab lut best-fit-normals`
 * (the scale table at one size, best_fit_normals/best_fit_normals_writers.h)
 * and the stage best-fit-normals of `gtlab all` (the study,
 * best_fit_normals/best_fit_normals_study.h, and its section). */
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"
#include "best_fit_normals/best_fit_normals.h"
#include "best_fit_normals/best_fit_normals_section.h"
#include "best_fit_normals/best_fit_normals_study.h"

static int lut_best_fit_normals(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_INT("size", "N", 16, BFN_MAX_SIZE, "texels per axis; the talk ships 512"), CLI_THREADS, CLI_OUTPUT_DIR,
        CLI_END};
    static const cli_command command = {
        "lut best-fit-normals",
        "Tabulates the best-fit scale of RGB8 G-buffer normals (Kaplanyan 2010, Appendix A): per\n"
        "direction, the scale t = k/255 whose quantised vector deviates least from it by the talk's\n"
        "error, indexed by u = the larger of the two smaller |n_i|, v = the smaller / the larger\n"
        "(best_fit_normals/best_fit_normals.h). Writes DIR/best_fit_normals_N.exr (float t), .png (8-bit t,\n"
        "exact), .h (C array of codes) and .hlsl (the encode with a point sampler, and the decode).",
        options, NULL, NULL};
    long size = BFN_TALK_SIZE, threads = threads_default();
    const char *dir = NULL;
    int status;
    if (cli_options_parse(&command, (void *[]){&size, &threads, &dir}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(dir)) != 0)
        return status;
    double seconds;
    gt_error e;
    float *table = normals_write_table(dir, (int)size, (int)threads, &seconds, &e);
    if (!table)
        return cli_fail(&e);
    free(table);
    printf("%s/best_fit_normals_%ld.{exr,png,h,hlsl}: %ld^2 in %.2f s\n", dir, size, size, seconds);
    return EXIT_OK;
}

GTLAB_STUDY_STAGE(all_stage_normals, normals, normals_section)

const technique technique_best_fit_normals = {
    .name = "best-fit-normals",
    .subcommands = {[VERB_LUT] = CLI_SUBCOMMANDS(
        {"best-fit-normals", lut_best_fit_normals, "best-fit RGB8 G-buffer normals (Kaplanyan 2010): the scale table"})},
    .stages = ALL_STAGES({"best-fit-normals", "best-fit normals", all_stage_normals, NORMALS_DIR, NULL}),
    .renamed = TECHNIQUE_RENAMES({"normals", "best-fit-normals"}),
};
