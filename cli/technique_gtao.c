/* GTAO (Jimenez et al. 2016), its screen-space baselines (HBAO, VO, Alchemy,
 * Crytek) and the talk's shortcuts measured (issue 25, items 9-13):
 * `gtlab approx gtao` (realtime/gtao.c on a G-buffer), `gtlab fit
 * gtao-params` (world radius, falloff and thickness fitted to 3-D references
 * and scored on held-out scenes: studies/gtao_params.h), `gtlab bench gtao`
 * (the talk's configuration at 1920x1080 and every preset's cost per pixel:
 * studies/gtao_bench.h) and the stages gtao and gtao-shortcuts. */
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/approx_io.h"
#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/atomic_file.h"
#include "core/reference_schema.h"
#include "core/run_inputs.h"
#include "core/threads.h"
#include "realtime/gtao.h"
#include "report/gtao_checks_section.h"
#include "report/gtao_params_json.h"
#include "report/gtao_section.h"
#include "studies/ao_references.h"
#include "studies/gtao_bench.h"

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
