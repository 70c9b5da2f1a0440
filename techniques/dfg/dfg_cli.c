/* The split-sum DFG (environment BRDF) LUT of Karis 2013: `gtlab lut dfg`
 * and its section of `gtlab all` (dfg/dfg_study.h), beside Filament's 128^2. */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/threads.h"
#include "dfg/dfg_section.h"
#include "dfg/dfg_study.h"

static int lut_dfg(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_INT("size", "N", DFG_MIN_SIZE, DFG_MAX_SIZE, "texels per axis; Filament uses 128"),
        CLI_THREADS, CLI_OUTPUT_DIR, CLI_END};
    static const cli_command command = {
        "lut dfg",
        "Tabulates the split-sum environment BRDF of Karis 2013 for GGX with height-correlated\n"
        "Smith masking: scale A and bias B (directional albedo = F0 A + B under Schlick's\n"
        "Fresnel) and E = A + B, the single-scattering albedo that multiple-scattering energy\n"
        "compensation (Kulla-Conty 2017, Fdez-Aguera 2019) divides by. x = n.v, y = perceptual\n"
        "roughness, sampled at texel centres as a GPU reads them (luts/dfg_lut.h).\n"
        "Writes DIR/dfg_N.exr (float A, B, E), .png (16-bit, R = A, G = B), .h (C array)\n"
        "and .hlsl, .glsl (the array and DFG(nv, roughness), the same bilinear lookup).",
        options, NULL, NULL};
    long size = DFG_FILAMENT_SIZE, threads = threads_default();
    const char *dir = NULL;
    int status;
    if (cli_options_parse(&command, (void *[]){&size, &threads, &dir}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(dir)) != 0)
        return status;
    dfg_result r;
    gt_error e;
    if (dfg_write_table(dir, (int)size, (int)threads, &r, &e) != 0)
        return cli_fail(&e);
    printf("%s/dfg_%ld.{exr,png,h,hlsl,glsl}: %ld^2 in %.2f s; quadrature error <= %.1e; smallest albedo E %.4f\n", dir,
           size, size, r.build_seconds, r.max_error_estimate, r.e_min);
    return EXIT_OK;
}

GTLAB_STUDY_STAGE(all_stage_dfg, dfg, dfg_section)

const technique technique_dfg = {
    .name = "dfg",
    .subcommands = {[VERB_LUT] = CLI_SUBCOMMANDS(
        {"dfg", lut_dfg, "split-sum DFG (Karis 2013): scale, bias, albedo vs n.v and roughness: EXR, PNG, C, HLSL, GLSL"})},
    .stages = ALL_STAGES({"dfg", "split-sum DFG LUT", all_stage_dfg, DFG_LUTS_DIR, NULL}),
};
