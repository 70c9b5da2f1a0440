/* gtlab approx alchemy and gtlab approx crytek: the screen-space AO
 * baselines the GTAO talk names, Alchemy ambient obscurance
 * (realtime/alchemy_ao.c) and CryENGINE 2's SSAO (realtime/crytek_ssao.c),
 * on a G-buffer. */
#include "cli/approx_io.h"
#include "cli/cli.h"
#include "core/reference_schema.h"
#include "realtime/alchemy_ao.h"
#include "realtime/crytek_ssao.h"

#define STRINGIFY(x) #x
#define TEXT(x) STRINGIFY(x)

static int alchemy_compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? alchemy_render(g, params, ao) : -1;
}

static void alchemy_text(const void *params, char *text, size_t size) { alchemy_params_text(params, text, size); }

int approx_alchemy(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_INT32("samples", "N", 1, 1024, "s"), CLI_FLOAT("radius", "R", 1e-9, 1e30, "world-space radius"),
        CLI_FLOAT("max-radius-px", "P", 1, 4096, "clamp of its screen-space radius"),
        CLI_FLOAT("sigma", "S", 0, 1e6, "intensity"), CLI_FLOAT("contrast", "K", 1e-3, 1e3, "k"),
        CLI_FLOAT("beta", "B", 0, 1, "bias distance per unit depth"), APPROX_FRAME_OPTIONS, CLI_END};
    static const approx_technique t = {
        "alchemy",
        "Alchemy ambient obscurance (McGuire et al. 2011): from s points on a spiral\n"
        "over the screen disc of the radius, A = max(0, 1 - 2 sigma / s sum_i\n"
        "max(0, v_i.n + z_C beta) / (v_i.v_i + epsilon))^k. Writes ao.V (= A).",
        options, alchemy_text, alchemy_compute};
    alchemy_params p = alchemy_default_params(1.0f);
    return approx_main(&t, &p, (void *[]){&p.samples, &p.radius, &p.max_radius_px, &p.sigma, &p.contrast, &p.beta,
                       &p.pattern, &p.denoise, &p.frames}, argc, argv);
}

static int crytek_compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? crytek_render(g, params, ao) : -1;
}

/* An even count: the points come in opposite pairs. */
static int parse_samples(void *dest, const char *text)
{
    long n;
    if (cli_parse_int("--samples", text, 2, CRYTEK_MAX_SAMPLES, &n) != 0)
        return -1;
    if (n % 2 != 0)
        return cli_failf("--samples", "'%s' is odd: the points come in opposite pairs", text), -1;
    return *(int *)dest = (int)n, 0;
}

static void crytek_text(const void *params, char *text, size_t size) { crytek_params_text(params, text, size); }

int approx_crytek(int argc, char **argv)
{
    static const cli_option options[] = {
        CLI_CUSTOM("samples", "N", parse_samples, "points, even, 2.." TEXT(CRYTEK_MAX_SAMPLES) " (default 16)"),
        CLI_FLOAT("radius", "R", 1e-9, 1e30, "world-space sphere radius"), APPROX_FRAME_OPTIONS, CLI_END};
    static const approx_technique t = {
        "crytek",
        "Screen-space AO as in CryENGINE 2 (Mittring 2007): N points in a sphere about\n"
        "the surface point, each occluded when the depth buffer lies in front of it by\n"
        "less than the radius; ao.V = min(1, 2 (1 - occluded fraction)), 1 on a plane.\n"
        "Depth only.",
        options, crytek_text, crytek_compute};
    crytek_params p = {16, 1.0f, 1, 0, 1};
    return approx_main(&t, &p, (void *[]){&p.samples, &p.radius, &p.pattern, &p.denoise, &p.frames}, argc, argv);
}
