/* The command-line face of dithering and blue noise (INSIDE, Gjoel, GDC
 * 2016): `gtlab lut blue-noise` (the shared void-and-cluster table the talk
 * bakes, luts/blue_noise.h), `gtlab check dither` (dither_check.h) and the
 * stage dither of `gtlab all` (dither_study.h and its section). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "dither/dither_check.h"
#include "dither/dither_section.h"
#include "luts/blue_noise.h"

static int lut_blue_noise(int argc, char **argv)
{
    static const cli_option options[] = {CLI_INT("size", "N", 8, 1024, "texels per axis"),
                                         CLI_INT("channels", "C", 1, 4, "channels, one seed each"),
                                         CLI_INT("seed", "S", 0, 4294967295.0, "seed"), CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {
        "lut blue-noise",
        "Void-and-cluster blue noise (Ulichney 1993, luts/blue_noise.h), as INSIDE bakes into 256^2 RGBA8\n"
        "(4 seeds): DIR/blue_noise_N.exr and .png (8-bit if 1 channel, else 16). Same inputs, same bits.",
        options, NULL, NULL};
    long size = 256, channels = 4, seed = 1;
    const char *dir = NULL;
    int status;
    if (cli_options_parse(&command, (void *[]){&size, &channels, &seed, &dir}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(dir)) != 0)
        return status;
    gt_error e;
    char stem[4096];
    if (blue_noise_make(dir, (int)size, (int)channels, (uint64_t)seed, stem, sizeof stem, &e) != 0)
        return cli_fail(&e);
    printf("%s.{exr,png}: %ld^2, %ld channel(s)\n", stem, size, channels);
    return EXIT_OK;
}

static int check_dither(int argc, char **argv)
{
    static const cli_option options[] = {CLI_INT("signals", "K", 2, 1000, "signals across one LSB"),
                                         CLI_INT("samples", "N", 100, 100000000, "dither draws per signal"), CLI_END};
    static const cli_command command = {
        "check dither",
        "Floor-quantisation error moments of each dither (dither/dither.h) against mean 0 and variance\n"
        "1/4 LSB^2 (TPDF of 2 LSB) or f(1-f) (RPDF); fails beyond 5 standard errors.",
        options, NULL, NULL};
    long signals = 33, samples = 100000;
    int status;
    dither_check_result r;
    gt_error e;
    if (cli_options_parse(&command, (void *[]){&signals, &samples}, argc, argv, &status) != 0)
        return status;
    if (dither_check_run((int)signals, (int)samples, 1, &r, &e) != 0)
        return cli_fail(&e);
    return dither_check_print(&r, stdout) ? EXIT_INTERNAL_ERROR : EXIT_OK;
}

GTLAB_STUDY_STAGE(all_stage_dither, dither, dither_section)

const technique technique_dither = {
    .name = "dither",
    .subcommands = {
        [VERB_LUT] = CLI_SUBCOMMANDS({"blue-noise", lut_blue_noise, "void-and-cluster blue noise: EXR, PNG"}),
        [VERB_CHECK] = CLI_SUBCOMMANDS({"dither", check_dither, "RPDF/TPDF error moments against their laws"}),
    },
    .stages = ALL_STAGES({"dither", "dithering and blue noise (INSIDE)", all_stage_dither, DITHER_DIR, NULL}),
};
