/* The command-line face of the GGX LTC table: `gtlab lut ltc` (fitted with
 * Ceres and written, ltc_study.h). The LTC sphere light is scored in the
 * sphere-light stage (techniques/sphere_light/). */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"
#include "ltc/ltc_study.h"

static int lut_ltc(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_INT("size", "N", LTC_MIN_SIZE, LTC_MAX_SIZE, "texels per axis (default 64, as Heitz ships it)"),
        CLI_THREADS, CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {
        "lut ltc",
        "Fits the GGX LTC table (Heitz et al. 2016) to gtlab's GGX with Ceres: M^-1's a, b, c, d,\n"
        "magnitude E and Fresnel term B per (sqrt(1 - n.v), roughness) texel centre\n"
        "(techniques/ltc/ltc_ggx.h). Writes DIR/ltc_ggx.exr (with the fit's error per texel), .h, .hlsl and .glsl.",
        options, NULL, NULL};
    long size = 64, threads = threads_default();
    const char *dir = NULL;
    int status;
    if (cli_options_parse(&command, (void *[]){&size, &threads, &dir}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(dir)) != 0)
        return status;
    ltc_table t;
    double seconds;
    gt_error e;
    if (ltc_table_fit_and_write(dir, (int)size, (int)threads, &t, &seconds, &e) != 0)
        return cli_fail(&e);
    printf("%s/ltc_ggx.{exr,h,hlsl,glsl}: %ld^2 in %.2f s; fit error (total variation) mean %.4f, worst %.4f\n", dir,
           size, seconds, t.mean_error, t.max_error);
    ltc_table_free(&t);
    return EXIT_OK;
}

const technique technique_ltc = {
    .name = "ltc",
    .subcommands = {
        [VERB_LUT] = CLI_SUBCOMMANDS({"ltc", lut_ltc, "GGX LTC table (Heitz 2016) fitted with Ceres: EXR, C, HLSL, GLSL"}),
    },
};
