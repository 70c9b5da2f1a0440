/* gtlab approx hbao: horizon-based AO (realtime/hbao.c) on a G-buffer. */
#include "cli/approx_io.h"
#include "core/reference_schema.h"
#include "realtime/hbao.h"

static int compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? hbao_render(g, params, ao) : -1;
}

static void settings_text(const void *params, char *text, size_t size) { hbao_params_text(params, text, size); }

int approx_hbao(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_INT32("directions", "N", 1, 4096, "screen directions per pixel and frame"),
        CLI_INT32("steps", "N", 0, 256, "samples per direction, 1..256; 0: exact"),
        CLI_FLOAT("radius", "R", 1e-9, 1e30, "world-space radius"),
        CLI_FLOAT("max-radius-px", "P", 1, 4096, "clamp of the screen-space radius"),
        CLI_SWITCH("attenuation", "Bavoil's per-sample W(r) = 1 - r^2/R^2"),
        APPROX_FRAME_OPTIONS, CLI_END};
    static const approx_technique technique = {
        "hbao",
        "Horizon-based AO (Bavoil et al. 2008): uniform weighting, per screen direction\n"
        "the occluded elevation from the surface tangent up to the horizon. Without\n"
        "attenuation it equals 'gtlab approx gtao --weighting uniform --falloff 0'.\n"
        "Writes ao.V (uniform AO).",
        options, settings_text, compute};
    hbao_params p = {8, 8, 1.0f, 256.0f, 1, 1, 0, 1};
    return approx_main(&technique, &p, (void *[]){&p.directions, &p.steps, &p.radius, &p.max_radius_px, &p.attenuation,
                       &p.pattern, &p.denoise, &p.frames}, argc, argv);
}
