/* INSIDE (Gjoel, GDC 2016): dithering and blue noise (studies/dither.h), the
 * bloom downsample's 13 -> 9 tap refit (studies/bloom.h). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "report/bloom_section.h"
#include "report/dither_section.h"
#include "studies/dither_check.h"

static int lut_blue_noise(int argc, char **argv)
{
    static const cli_option options[] = {CLI_INT("size", "N", 8, 1024, "texels per axis"),
                                         CLI_INT("channels", "C", 1, 4, "channels, one seed each"),
                                         CLI_INT("seed", "S", 0, 4294967295.0, "seed"), CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {
        "lut blue-noise",
        "Void-and-cluster blue noise (Ulichney 1993, sigma 1.5, luts/blue_noise.h), as INSIDE bakes into\n"
        "256^2 RGBA8 (four seeds). Writes DIR/blue_noise_N.exr (float) and .png (8-bit for one channel,\n"
        "else 16-bit). Same size, channels and seed: the same bits.",
        options};
    long size = 256, channels = 4, seed = 1;
    const char *dir = NULL;
    int status;
    if (cli_options_parse(&command, (void *[]){&size, &channels, &seed, &dir}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(dir)) != 0)
        return status;
    blue_noise_texture t;
    gt_error e;
    char stem[4096];
    snprintf(stem, sizeof stem, "%s/blue_noise_%ld", dir, size);
    if (blue_noise_build((int)size, (int)channels, (uint64_t)seed, &t, &e) != 0 || blue_noise_write(&t, stem, &e) != 0)
        return cli_fail(&e);
    blue_noise_free(&t);
    printf("%s.{exr,png}: %ld^2, %ld channel(s)\n", stem, size, channels);
    return EXIT_OK;
}

static int check_dither(int argc, char **argv)
{
    static const cli_option options[] = {CLI_INT("signals", "K", 2, 1000, "signals across one LSB"),
                                         CLI_INT("samples", "N", 100, 100000000, "dither draws per signal"), CLI_END};
    static const cli_command command = {
        "check dither",
        "Moments of the floor-quantisation error of each dither (realtime/dither.h) against the laws of\n"
        "nonsubtractive dither: mean 0; variance 1/4 LSB^2 (TPDF of 2 LSB) or f(1-f) (RPDF). Fails when\n"
        "a kind with a law is off by more than 5 standard errors.",
        options};
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

static int all_stage_dither(report_context *ctx, gt_error *e)
{
    static dither_result r;
    dither_request rq = dither_default_request(ctx->study.quality);
    return dither_study(&ctx->study, &rq, &r, e) != 0 ? -1 : dither_section(ctx, &r, e);
}

static int all_stage_bloom(report_context *ctx, gt_error *e)
{
    static bloom_result r;
    bloom_request rq = bloom_default_request(ctx->study.quality);
    return bloom_study(&ctx->study, &rq, &r, e) != 0 ? -1 : bloom_section(ctx, &r, e);
}

static const cli_subcommand luts[] = {{"blue-noise", lut_blue_noise, "void-and-cluster blue noise: EXR, PNG"},
                                      {NULL, NULL, NULL}};
static const cli_subcommand checks[] = {{"dither", check_dither, "RPDF/TPDF error moments against their laws"},
                                        {NULL, NULL, NULL}};
static const all_stage stages[] = {{"dither", "dithering and blue noise (INSIDE)", all_stage_dither, DITHER_DIR, NULL},
                                   {"bloom", "bloom 13 -> 9 tap refit (INSIDE)", all_stage_bloom, BLOOM_DIR, NULL},
                                   {NULL, NULL, NULL, NULL, NULL}};

const technique technique_inside = {
    .name = "inside", .subcommands = {[VERB_LUT] = luts, [VERB_CHECK] = checks}, .stages = stages};
