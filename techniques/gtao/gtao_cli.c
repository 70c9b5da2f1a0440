/* GTAO's command-line face (Jimenez et al. 2016; README.md): `gtlab approx
 * gtao` (gtao.c on a G-buffer) and the screen-space baselines it is ranked
 * against, `gtlab approx hbao|vo|alchemy|crytek`; `gtlab fit gtao-params`
 * (world radius, falloff and thickness fitted to 3-D references and scored
 * on held-out scenes: gtao_params.h); `gtlab bench gtao` (the talk's
 * configuration at 1920x1080 and every preset's cost per pixel:
 * gtao_bench.h); and the stages gtao and gtao-shortcuts (the talk's
 * shortcuts measured, issue 25, items 6-13). */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ao/ao_references.h"
#include "cli/approx_io.h"
#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/files/atomic_file.h"
#include "core/reference_schema.h"
#include "core/files/run_inputs.h"
#include "core/threads.h"
#include "gtao/alchemy_ao.h"
#include "gtao/crytek_ssao.h"
#include "gtao/gtao.h"
#include "gtao/gtao_bench.h"
#include "gtao/gtao_checks_section.h"
#include "gtao/gtao_params_json.h"
#include "gtao/gtao_section.h"
#include "gtao/hbao.h"
#include "gtao/volumetric_obscurance.h"

/* The parameters and the preset they started from (for the header). */
typedef struct {
    gtao_params p;
    const char *preset;
} gtao_settings;

static int compute(const ss_gbuffer *g, const void *settings, image *out)
{
    const gtao_params *p = &((const gtao_settings *)settings)->p;
    float *ao = image_add_channel(out, CH_AO);
    float *bent[3] = {image_add_channel(out, CH_BENT_X), image_add_channel(out, CH_BENT_Y),
                      image_add_channel(out, CH_BENT_Z)};
    if (!ao || !bent[0] || !bent[1] || !bent[2])
        return -1;
    return gtao_render(g, p, ao, bent);
}

static void settings_text(const void *settings, char *text, size_t size)
{
    const gtao_settings *s = settings;
    char params[512];
    gtao_params_text(&s->p, params, sizeof params);
    snprintf(text, size, "preset=%s %s", s->preset, params);
}

/* The preset comes first, whatever its place among the approx_options (the other
 * approx_options override it). */
static const char *find_preset(int argc, char **argv)
{
    const char *preset = "medium";
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--preset") == 0 && i + 1 < argc)
            preset = argv[i + 1];
        else if (strncmp(argv[i], "--preset=", 9) == 0)
            preset = argv[i] + 9;
    }
    return preset;
}

static const char *weighting_name(int i) { return i == GTAO_UNIFORM ? "uniform" : "cosine"; }
static const char *bent_name(int i) { return i ? "halfway" : "exact"; }

static const cli_option approx_options[] = {
    CLI_STRING("preset", "P", "low | medium (the talk's: 1 direction per pixel, 8 samples,\n"
               "4x4 spatial noise and denoiser) | high | ultra | reference\n(brute force: 64 regular slices, exact "
               "horizons through\nevery pixel cell, no noise, no denoiser)"),
    CLI_FLOAT("radius", "R", 1e-9, 1e30, "world-space search radius"),
    CLI_FLOAT("falloff", "F", 0, 1, "fraction of the radius over which samples fade out, in\n[0, 1]; the talk's "
              "150 to 200 inches"),
    CLI_FLOAT("max-radius-px", "P", 1, 4096, "clamp of the screen-space radius in pixels"),
    CLI_FLOAT("thickness", "T", 0, 0.999, "thickness heuristic in [0, 1): how fast a horizon relaxes\n"
              "behind a thin occluder (0: off)"),
    CLI_INT32("slices", "N", 1, 4096, "slice directions per pixel and frame"),
    CLI_INT32("steps", "N", 0, GTAO_MAX_STEPS, "samples per side of a slice (1..256); 0: exact horizons,\n"
              "both ends of every pixel cell within the radius"),
    CLI_INT32("frames", "N", 1, 100000, "frames of the spatio-temporal pattern accumulated by the\n"
              "temporal filter (static camera; 24 is a full cycle)"),
    CLI_SWITCH("pattern", "the talk's 4x4 spatial and 6x4 temporal pattern (off:\nregular slices, step offset 0.5)"),
    CLI_SWITCH("denoise", "the 4x4 bilateral spatial denoiser"),
    CLI_SWITCH("fast-math", "the talk's fast acos and sqrt"),
    CLI_CHOICE("weighting", "W", weighting_name, 2, "cosine | uniform (HBAO's measure)"),
    CLI_CHOICE("bent", "B", bent_name, 2, "bent normal: the cosine-weighted mean direction of each\n"
               "slice's visible arc (exact) or the talk's direction\nhalfway between the horizons (16 degrees off on a plane)"),
    CLI_END};

static int approx_gtao(int argc, char **argv)
{
    static const approx_technique technique = {
        "gtao",
        "Ground-truth ambient occlusion (Jimenez et al., SIGGRAPH 2016) on a G-buffer:\n"
        "per slice the two horizons found on the depth buffer, the cosine-weighted arc\n"
        "integrated analytically with the normal projected onto the slice. Writes ao.V\n"
        "(cosine AO, or uniform with --weighting uniform) and bent.X/Y/Z (world space).\n"
        "The preset's values are the defaults; the other approx_options override them.\n"
        "example: gtlab approx gtao --gbuffer ao.exr --preset high --radius 2 -o gtao.exr",
        approx_options, settings_text, compute};
    gtao_settings s = {.preset = find_preset(argc, argv)};
    if (gtao_preset(s.preset, &s.p) != 0)
        return cli_failf("--preset", "unknown preset '%s' (low, medium, high, ultra, reference)", s.preset);
    gtao_params *p = &s.p;
    return approx_main(&technique, &s, (void *[]){&s.preset, &p->radius, &p->falloff, &p->max_radius_px,
                       &p->thickness, &p->slices, &p->steps, &p->frames, &p->pattern, &p->denoise, &p->fast_math,
                       &p->weighting, &p->bent_halfway}, argc, argv);
}

/* The screen-space baselines GTAO is ranked against, on a G-buffer: HBAO
 * (hbao.c), volumetric obscurance with 4 samples (volumetric_obscurance.c),
 * Alchemy ambient obscurance (alchemy_ao.c) and CryENGINE 2's SSAO
 * (crytek_ssao.c). */
static int hbao_compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? hbao_render(g, params, ao) : -1;
}

static void hbao_text(const void *params, char *text, size_t size) { hbao_params_text(params, text, size); }

static int approx_hbao(int argc, char **argv)
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
        options, hbao_text, hbao_compute};
    hbao_params p = {8, 8, 1.0f, 256.0f, 1, 1, 0, 1};
    return approx_main(&technique, &p, (void *[]){&p.directions, &p.steps, &p.radius, &p.max_radius_px, &p.attenuation,
                       &p.pattern, &p.denoise, &p.frames}, argc, argv);
}

static int vo_compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? vo_render(g, params, ao) : -1;
}

static void vo_text(const void *params, char *text, size_t size) { vo_params_text(params, text, size); }

static int approx_vo(int argc, char **argv)
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
        options, vo_text, vo_compute};
    vo_params p = {1.0f, 256.0f, 1, 1, 1};
    return approx_main(&technique, &p, (void *[]){&p.radius, &p.max_radius_px, &p.pattern, &p.denoise, &p.frames},
                       argc, argv);
}

#define STRINGIFY(x) #x
#define TEXT(x) STRINGIFY(x)

static int alchemy_compute(const ss_gbuffer *g, const void *params, image *out)
{
    float *ao = image_add_channel(out, CH_AO);
    return ao ? alchemy_render(g, params, ao) : -1;
}

static void alchemy_text(const void *params, char *text, size_t size) { alchemy_params_text(params, text, size); }

static int approx_alchemy(int argc, char **argv)
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

static int approx_crytek(int argc, char **argv)
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

static const char *objective_name(int i) { return gtao_fit_objective_names[i]; }

static const cli_option fit_options[] = {
    CLI_REQUIRED_STRING("refs", "DIR", "folder of AO references <scene>.exr with their G-buffer and\n"
                        "camera (e.g. the ao/ folder 'gtlab all' writes)"),
    CLI_STRING("train", "LIST", "scenes to fit on, comma-separated"),
    CLI_STRING("test", "LIST", "held-out scenes"),
    CLI_STRING("preset", "P", "GTAO preset"),
    CLI_CHOICE("objective", "O", objective_name, 2, "dssim (the sum over scenes of each scene's mean\n"
               "DSSIM) or rmse (per-pixel least squares)"),
    CLI_OUTPUT("F", 1, "fit JSON: values, standard errors, scores before and after"), CLI_END};
static const cli_command fit_command = {
    "fit gtao-params",
    "Fits GTAO's radius (a fraction of each camera's distance to its target), falloff\n"
    "and thickness so GTAO matches 3-D ray-traced AO references (Ceres, over the\n"
    "training scenes, each scene's residuals weighted equally; derivatives by finite\n"
    "differences of 0.01 in each parameter), and reports RMSE and DSSIM before and\n"
    "after on the training and the held-out scenes.",
    fit_options, NULL, NULL};

static int fit_gtao_params(int argc, char **argv)
{
    gtao_fit_request rq = {NULL, GTAO_FIT_DEFAULT_TRAIN, GTAO_FIT_DEFAULT_TEST, GTAO_FIT_DEFAULT_PRESET, GTAO_FIT_DSSIM};
    const char *output = NULL;
    int status;
    if (cli_options_parse(&fit_command, (void *[]){&rq.refs_dir, &rq.train, &rq.test, &rq.preset, &rq.objective, &output},
                          argc, argv, &status) != 0)
        return status;
    gt_error e;
    run_inputs_note_folder(rq.refs_dir, "--refs"); /* the references are read from it */
    if (run_inputs_check_output(output, &e) != 0)
        return cli_fail(&e);
    static gtao_fit_result r;
    if (gtao_params_study(&rq, &r, &e) != 0)
        return cli_fail(&e);
    gtao_params_print(stdout, &rq, &r);
    cJSON *root = gtao_fit_json(&rq, &r);
    char *text = cJSON_Print(root);
    status = text && atomic_write_text(output, text, &e) == 0 ? EXIT_OK : cli_fail(&e);
    free(text);
    cJSON_Delete(root);
    return status;
}

static const cli_option bench_options[] = {
    CLI_STRING("scene", "S", "builtin:NAME or a glTF file"), CLI_THREADS,
    CLI_INT("repeats", "R", 1, 100, "passes per figure"), CLI_END};
static const cli_command bench_command = {
    "bench gtao",
    "Measures, on one scene and camera:\n"
    "  talk's configuration  GTAO for a 1920x1080 frame at half resolution (960x540):\n"
    "                        1 direction per pixel, 8 samples per direction (4 per side),\n"
    "                        the 4x4 spatio-temporal pattern, fast acos/sqrt, the 4x4\n"
    "                        bilateral denoiser and the temporal accumulation, per frame\n"
    "                        (averaged over the 24-frame cycle), on 1 and T threads;\n"
    "                        and VBAO the same way (32 sectors, thickness 0.05 camera distances)\n"
    "  presets               ns per pixel of one frame of each preset (low .. ultra and the\n"
    "                        brute-force reference) and of the height-field Monte Carlo\n"
    "                        reference at 64 spp, on a 240x136 image of the same view\n"
    "Each figure is the best of R passes.",
    bench_options, NULL, NULL};

static int bench_gtao(int argc, char **argv)
{
    const char *spec = "builtin:menger";
    long threads = threads_default(), repeats = 3;
    int status;
    if (cli_options_parse(&bench_command, (void *[]){&spec, &threads, &repeats}, argc, argv, &status) != 0)
        return status;
    gt_error e;
    gtao_bench_result r;
    if (gtao_bench_run(spec, (int)threads, (int)repeats, &r, &e) != 0)
        return cli_fail(&e);
    gtao_bench_print(stdout, spec, (int)threads, &r);
    return EXIT_OK;
}

/* GTAO is scored against the AO stage's references (its `needs`). */
static int all_stage_gtao(report_context *ctx, gt_error *e)
{
    char refs[4096];
    snprintf(refs, sizeof refs, "%s/%s", ctx->study.output_dir, AO_REFERENCES_DIR);
    gtao_validation_request rq = {refs};
    static gtao_validation_result r;
    return gtao_validation_study(&ctx->study, &rq, &r, e) != 0 ? -1 : gtao_section(ctx, &r, e);
}

/* The talk's shortcuts read the AO references and the `gtao` stage's height-field references. */
static int all_stage_gtao_shortcuts(report_context *ctx, gt_error *e)
{
    char refs[4096], gtao[4096];
    snprintf(refs, sizeof refs, "%s/%s", ctx->study.output_dir, AO_REFERENCES_DIR);
    snprintf(gtao, sizeof gtao, "%s/%s", ctx->study.output_dir, GTAO_VALIDATION_DIR);
    gtao_shortcuts_request rq = {refs, gtao};
    static gtao_checks_result r;
    return gtao_checks_study(&ctx->study, &rq, &r, e) != 0 ? -1 : (gtao_checks_section(ctx, &r), 0);
}

const technique technique_gtao = {
    .name = "gtao",
    .subcommands = {
        [VERB_APPROX] = CLI_SUBCOMMANDS(
            {"gtao", approx_gtao, "ground-truth AO (Jimenez et al. 2016): cosine-weighted horizons, bent normals"},
            {"hbao", approx_hbao, "horizon-based AO (Bavoil et al. 2008): uniform weighting"},
            {"vo", approx_vo, "volumetric obscurance with 4 samples (Loos and Sloan 2010; CryENGINE 3)"},
            {"alchemy", approx_alchemy, "Alchemy ambient obscurance (McGuire et al. 2011), a baseline the GTAO talk cites"},
            {"crytek", approx_crytek, "CryENGINE 2's SSAO (Mittring 2007), a baseline the GTAO talk cites"}),
        [VERB_FIT] = CLI_SUBCOMMANDS(
            {"gtao-params", fit_gtao_params, "GTAO radius, falloff and thickness against 3-D AO references"}),
        [VERB_BENCH] = CLI_SUBCOMMANDS(
            {"gtao", bench_gtao, "GTAO at 1920x1080 in the talk's configuration, every preset's cost per pixel"}),
    },
    .stages = ALL_STAGES(
        {"gtao", "GTAO validation", all_stage_gtao, GTAO_VALIDATION_DIR, "ao"},
        {"gtao-shortcuts", "GTAO's shortcuts", all_stage_gtao_shortcuts, NULL, "gtao"}),
};
