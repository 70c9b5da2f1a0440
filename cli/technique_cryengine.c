/* CryENGINE 3 (Kaplanyan 2010) on the command line: best-fit normals
 * (`gtlab lut best-fit-normals`, stage normals; studies/best_fit_normals.h),
 * colour precision and the HDR range (stage hdr-precision;
 * studies/hdr_precision.h), colour-grading LUTs (stage color-grading;
 * studies/color_grading.h): three techniques of one talk (the fourth, the
 * NDF fit with spherical Gaussians, is in techniques/sg_ndf/). */
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"
#include "luts/best_fit_normals.h"
#include "report/best_fit_normals_section.h"
#include "report/color_grading_section.h"
#include "report/hdr_precision_section.h"
#include "studies/best_fit_normals.h"
#include "studies/color_grading.h"
#include "studies/hdr_precision.h"

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
        "(luts/best_fit_normals.h). Writes DIR/best_fit_normals_N.exr (float t), .png (8-bit t,\n"
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

const technique technique_normals = {
    .name = "normals",
    .subcommands = {[VERB_LUT] = CLI_SUBCOMMANDS(
        {"best-fit-normals", lut_best_fit_normals, "best-fit RGB8 G-buffer normals (Kaplanyan 2010): the scale table"})},
    .stages = ALL_STAGES({"normals", "best-fit normals", all_stage_normals, NORMALS_DIR, NULL}),
};

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_hdr_precision, hdr_precision_result, hdr_precision_study, hdr_precision_section)

GTLAB_STAGE_TECHNIQUE(hdr_precision, "hdr-precision", "gamma vs linear and HDR lower bounds", all_stage_hdr_precision,
                      HDR_PRECISION_DIR);

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_color_grading, grading_result, color_grading_study, color_grading_section)

GTLAB_STAGE_TECHNIQUE(color_grading, "color-grading", "colour-grading LUTs", all_stage_color_grading, GRADING_DIR);
