/* The command-line face of the NDF fit with spherical Gaussians: `gtlab fit
 * sg-ndf` (one material's series of fits, printed) and the stage sg-ndf of
 * `gtlab all` (the study, sg_ndf_study.h, and its section). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"
#include "sg_ndf/sg_ndf_section.h"
#include "sg_ndf/sg_ndf_study.h"

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
        "solid-angle weights; sg_ndf/sg_ndf_fit.h). Writes DIR/sg_ndf/sg_ndf_lobes.{json,h} and sg_ndf_error.dat.",
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
    study_context ctx = {dir, QUALITY_PRODUCTION, (int)threads, NULL, NULL, 0};
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
