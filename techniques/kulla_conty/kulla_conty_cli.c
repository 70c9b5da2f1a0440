/* The Kulla-Conty energy compensation on the command line: `gtlab lut
 * kulla-conty` (the average-albedo table) and its stage of `gtlab all`
 * (kulla_conty_study.h, kulla_conty_section.h). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"
#include "kulla_conty/kulla_conty_section.h"
#include "kulla_conty/kulla_conty_study.h"

static int lut_kulla_conty(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_INT("size", "N", KULLA_CONTY_MIN_SIZE, KULLA_CONTY_MAX_SIZE, "entries (roughness at texel centres)"),
        CLI_THREADS, CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {
        "lut kulla-conty",
        "Tabulates the average albedo E_avg(r) = 2 int E(mu, r) mu dmu of single-scattering GGX that\n"
        "the multiple-scattering energy compensation of Kulla & Conty 2017 divides by (E: the DFG\n"
        "table's albedo), at N roughnesses r = (j + 0.5) / N. Writes DIR/kulla_conty_eavg_N.exr\n"
        "(float, N x 1), .png (8-bit) and .h (C array).",
        options, NULL, NULL};
    long size = 32, threads = threads_default();
    const char *dir = NULL;
    int status;
    if (cli_options_parse(&command, (void *[]){&size, &threads, &dir}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(dir)) != 0)
        return status;
    double bound = 0.0;
    gt_error e;
    if (kulla_conty_write_table(dir, (int)size, (int)threads, &bound, &e) != 0)
        return cli_fail(&e);
    printf("%s/kulla_conty_eavg_%ld.{exr,png,h}: %ld entries; quadrature error <= %.1e\n", dir, size, size, bound);
    return EXIT_OK;
}

GTLAB_STUDY_STAGE(all_stage_kulla_conty, kulla_conty, kulla_conty_section)

const technique technique_kulla_conty = {
    .name = "kulla-conty",
    .subcommands = {[VERB_LUT] = CLI_SUBCOMMANDS(
        {"kulla-conty", lut_kulla_conty, "Kulla-Conty 2017 average albedo E_avg(r) for energy compensation: EXR, PNG, C"})},
    .stages = ALL_STAGES({"kulla-conty", "Kulla-Conty energy compensation", all_stage_kulla_conty, NULL, NULL}),
};
