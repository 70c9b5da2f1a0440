/* CryENGINE 3 (Kaplanyan 2010) on the command line: best-fit normals
 * (`gtlab lut best-fit-normals`, stage normals; studies/best_fit_normals.h),
 * colour precision and the HDR range (stage hdr-precision;
 * studies/hdr_precision.h), colour-grading LUTs (stage color-grading;
 * studies/color_grading.h) and the NDF fit with spherical Gaussians
 * (`gtlab fit sg-ndf`, stage sg-ndf; studies/sg_ndf.h): four techniques of
 * one talk. */
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
#include "report/sg_ndf_section.h"
#include "studies/best_fit_normals.h"
#include "studies/color_grading.h"
#include "studies/hdr_precision.h"
#include "studies/sg_ndf.h"

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

static const char *ndf_choice(int i) { return i >= 0 && i < 2 ? ndf_kind_name((ndf_kind)i) : NULL; }

static void print_series(const sg_ndf_material *m, int max_lobes)
{
    for (int k = 0; k < max_lobes; ++k)
        printf("k=%d %s E=%.5f max=%.5f %s\n", k + 1, sg_fit_status_name(m->fits[k].status), m->fits[k].l2_error,
               m->fits[k].max_error, m->fits[k].note);
}

static int fit_sg_ndf(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_CHOICE("ndf", "NAME", ndf_choice, 2, "ward or ggx"),
        CLI_DOUBLE("alpha-x", "A", 0.01, 2.0, "roughness along the tangent"),
        CLI_DOUBLE("alpha-y", "A", 0.01, 2.0, "roughness along the bitangent"),
        CLI_INT("lobes", "K", 1, SG_NDF_STUDY_LOBES, "fits k = 1..K lobes"), CLI_THREADS, CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {
        "fit sg-ndf",
        "Fits k = 1..K spherical Gaussians to an anisotropic Ward or GGX NDF by Ceres (least squares in D,\n"
        "solid-angle weights; fitters/sg_ndf_fit.h). Writes DIR/sg_ndf/sg_ndf_lobes.{json,h} and sg_ndf_error.dat.",
        options, NULL, NULL};
    int kind = NDF_WARD;
    double ax = 0.4, ay = 0.2;
    long lobes = 7, threads = threads_default();
    const char *dir = NULL;
    int status;
    if (cli_options_parse(&command, (void *[]){&kind, &ax, &ay, &lobes, &threads, &dir}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(dir)) != 0)
        return status;
    sg_ndf_request rq = sg_ndf_default_request(QUALITY_PRODUCTION);
    rq.material_count = 1;
    rq.materials[0] = (anisotropic_ndf){(ndf_kind)kind, ax, ay};
    rq.imaged[0] = 0;
    rq.max_lobes = (int)lobes;
    study_context ctx = {dir, QUALITY_PRODUCTION, (int)threads, NULL, NULL};
    static sg_ndf_result r;
    gt_error e;
    if (sg_ndf_study(&ctx, &rq, &r, &e) != 0)
        return cli_fail(&e);
    print_series(&r.materials[0], rq.max_lobes);
    return EXIT_OK;
}

GTLAB_STUDY_STAGE(all_stage_sg_ndf, sg_ndf, sg_ndf_section)

const technique technique_sg_ndf = {
    .name = "sg-ndf",
    .subcommands = {[VERB_FIT] = CLI_SUBCOMMANDS(
        {"sg-ndf", fit_sg_ndf, "spherical Gaussians fitted to anisotropic Ward/GGX NDFs (Kaplanyan 2010): JSON, C header"})},
    .stages = ALL_STAGES({"sg-ndf", "NDF fit with spherical Gaussians", all_stage_sg_ndf, NULL, NULL}),
};
