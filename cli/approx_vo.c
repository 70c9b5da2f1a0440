/* gtlab approx vo: volumetric obscurance with 4 samples
 * (realtime/volumetric_obscurance.c) on a G-buffer. */
#include "cli/approx_io.h"
#include "core/reference_schema.h"
#include "realtime/volumetric_obscurance.h"

static int compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? vo_render(g, params, ao) : -1;
}

static void settings_text(const void *params, char *text, size_t size) { vo_params_text(params, text, size); }

int approx_vo(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_FLOAT("radius", "R", 1e-9, 1e30, "world-space sphere radius"),
        CLI_FLOAT("max-radius-px", "P", 1, 4096, "clamp of its screen-space radius"),
        CLI_SWITCH("pattern", "rotate the samples by the GTAO talk's 4x4 pattern"),
        CLI_SWITCH("denoise", "the 4x4 bilateral spatial denoiser"),
        CLI_INT32("frames", "N", 1, 100000, "frames accumulated (static camera)"), CLI_END};
    static const approx_technique technique = {
        "vo",
        "Volumetric obscurance (Loos and Sloan 2010) with CryENGINE 3's 4 samples\n"
        "(Kaplanyan, SIGGRAPH 2010): the fraction of a sphere about the surface point\n"
        "behind the depth buffer, from 4 line integrals; ao.V = min(1, 2 (1 - fraction)),\n"
        "1 on a plane. Depth only.",
        options, settings_text, compute};
    vo_params p = {1.0f, 256.0f, 1, 1, 1};
    return approx_main(&technique, &p, (void *[]){&p.radius, &p.max_radius_px, &p.pattern, &p.denoise, &p.frames},
                       argc, argv);
}
