/* Specular occlusion (GTSO, Jimenez et al. 2016) and its baselines:
 * `gtlab approx specular-occlusion` (specular_occlusion/specular_occlusion_approx.h),
 * `gtlab lut specular-occlusion` (the cone/lobe table in every format, with
 * its accuracy: specular_occlusion/specular_occlusion_lut.h), `gtlab fit aperture` (the
 * cone aperture fitted to references: specular_occlusion/aperture_fit_figures.h),
 * `gtlab bench specular-occlusion` (the reference's throughput:
 * specular_occlusion/specular_occlusion_bench.h) and the stage specular-occlusion. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "cli/technique.h"
#include "core/files/atomic_file.h"
#include "core/reference_schema.h"
#include "core/threads.h"
#include "specular_occlusion/aperture_fit_figures.h"
#include "specular_occlusion/specular_occlusion_approx.h"
#include "specular_occlusion/specular_occlusion_bench.h"
#include "specular_occlusion/specular_occlusion_inputs.h"
#include "specular_occlusion/specular_occlusion_lut.h"
#include "specular_occlusion/specular_occlusion_lut_writers.h"
#include "specular_occlusion/specular_occlusion_section.h"

static const char *weighting_name(int i) { return i == SO_AO_UNIFORM ? "uniform" : "cosine"; }
static const char *lobe_name(int i) { return so_lobe_name((so_lobe)i); }

static const cli_option approx_options[] = {
    CLI_REQUIRED_STRING("gbuffer", "F.exr", "G-buffer channels and camera"),
    CLI_REQUIRED_STRING("ao", "F.exr", "ao.V, bent.X/Y/Z and ao.Vuniform (may be the same file; a\n"
                        "'gtlab approx gtao' output serves the cosine weighting)"),
    CLI_STRING("variant", "V", "lut (GTSO cone/lobe), ao (AO as specular occlusion),\n"
               "lagarde (Lagarde 2014), sg (Unity HDRP's spherical Gaussians),\n"
               "cone-exact:M or cone-oat:M (cone/cone\n"
               "with the exact cap intersection or Oat 2007's), M the\n"
               "reflection-cone mapping: drobot, uludag, phong-u (with --u),\n"
               "exp2-alpha (2^(-3.32193 alpha^2)), exp2-perceptual\n(2^(-3.32193 r^2), r perceptual)"),
    CLI_DOUBLE("u", "U", 1e-12, 1.0 - 1e-12, "phong-u's parameter in (0, 1); the talk's 0.01"),
    CLI_CHOICE("ao-weighting", "W", weighting_name, 2, "cosine (ao.V, cos a_v = sqrt(1 - V)) or uniform\n"
               "(ao.Vuniform, cos a_v = 1 - V)"),
    CLI_DOUBLE("roughness", "R", 0.0, 1.0, "perceptual roughness for every pixel (default: the --gbuffer\n"
               "reference's --roughness if it had one, else roughness.Y)"),
    CLI_INT("lut-size", "N", 2, 256, "lut: table size, built on the fly"),
    CLI_CHOICE("lobe", "L", lobe_name, SO_LOBE_COUNT, "lut: ggx, ggx-d or phong"),
    CLI_OUTPUT("F.exr", 1, "output"), CLI_END};
static const cli_command approx_command = {
    "approx specular-occlusion",
    "Specular occlusion V_s from what a real-time renderer has: the G-buffer (N.*, P.*,\n"
    "roughness.Y, mask.A and the camera in the header: any gtlab reference file) and the\n"
    "AO and bent normal (ao.V, ao.Vuniform, bent.*: 'gtlab render ao'). Writes specocc.V\n"
    "and mask.A, so 'gtlab compare ref.exr out.exr --channel specocc.V' scores it.",
    approx_options, NULL, NULL};

static int approx_specular_occlusion(int argc, char **argv)
{
    const char *gbuffer = NULL, *ao = NULL, *output = NULL, *variant = "lut";
    double u = 0.01, roughness = -1.0;
    int weighting = SO_AO_COSINE, lobe = SO_LOBE_GGX, status;
    long lut_size = 32;
    if (cli_options_parse(&approx_command, (void *[]){&gbuffer, &ao, &variant, &u, &weighting, &roughness, &lut_size, &lobe,
                          &output}, argc, argv, &status) != 0)
        return status;
    so_variant v;
    if (so_variant_parse(variant, &v) != 0)
        return cli_failf("--variant", "unknown variant '%s' (see --help)", variant);
    v.u = u, v.weighting = (so_ao_weighting)weighting;
    so_approx_files files = {gbuffer, ao, output, roughness, (int)lut_size, (so_lobe)lobe, threads_default()};
    gt_error e;
    return so_approx_from_files(&files, &v, &e) != 0 ? cli_fail(&e) : EXIT_OK;
}

enum { INTERPOLATION_POINTS = 4096 }; /* stated in the help text */

static const char *axes_name(int i) { return so_lut_axes_name((so_lut_axes)i); }

static const cli_option lut_options[] = {
    CLI_INT("size", "N", 2, 256, "entries per axis; the talk: 32, or 16"),
    CLI_CHOICE("lobe", "L", lobe_name, SO_LOBE_COUNT, "ggx (f_r cos, GTSO's definition), ggx-d (D cos, the\n"
               "talk's older definition) or phong (Phong NDF, p = 2/alpha^2 - 2)"),
    CLI_CHOICE("axes", "A", axes_name, SO_AXES_COUNT, "angles (a_v/(pi/2), beta/pi, r: lower interpolation\n"
               "error, see techniques/specular_occlusion/README.md)\n"
               "or cosines (cos a_v, 0.5 cos beta + 0.5, r: the talk's\narguments)"),
    CLI_THREADS, CLI_OUTPUT_DIR, CLI_END};
static const cli_command lut_command = {
    "lut specular-occlusion",
    "Tabulates GTSO's cone/lobe specular occlusion V_s(a_v, beta, r): the fraction of\n"
    "the reflection lobe (at normal incidence, n = v = R) inside a visibility cone of\n"
    "half-angle a_v whose axis is beta from the reflection vector, for perceptual\n"
    "roughness r (GGX alpha = r^2), by adaptive Gauss-Kronrod quadrature.\n"
    "Writes DIR/specular_occlusion_<lobe>_<N>.exr (float), .png (8-bit, linear),\n"
    ".h (C array) and .json (axes, quadrature error estimate, interpolation error of\n"
    "trilinear lookup against direct integration at 4096 random points).",
    lut_options, NULL, NULL};

typedef struct {
    long size;
    int lobe, axes;
    long threads;
    const char *dir;
} lut_settings;

static int lut_specular_occlusion(int argc, char **argv)
{
    lut_settings o = {32, SO_LOBE_GGX, SO_AXES_ANGLES, threads_default(), NULL};
    int status;
    if (cli_options_parse(&lut_command, (void *[]){&o.size, &o.lobe, &o.axes, &o.threads, &o.dir}, argc, argv, &status) != 0 ||
        (status = cli_make_output_dir(o.dir)) != 0)
        return status;
    so_lut_made made;
    gt_error e;
    if (so_lut_make(o.dir, (int)o.size, (so_lobe)o.lobe, (so_lut_axes)o.axes, (int)o.threads, INTERPOLATION_POINTS,
                    &made, &e) != 0)
        return cli_fail(&e);
    printf("%s/%s.{exr,png,h,json}: %ld^3 in %.2f s; quadrature error <= %.1e; trilinear error max %.2e, rms %.2e\n",
           o.dir, made.base, o.size, made.seconds, made.max_error_estimate, made.max_interp, made.rms_interp);
    return EXIT_OK;
}

enum { MAX_CASES = 32 };

static const char *definition_name(int i) { return (const char *[]){"gtso", "d-only", "phong"}[i]; }
static const char *intersection_name(int i) { return i ? "oat" : "exact"; }
static const char *cone_name(int i) { return i ? "reflected" : "talk"; }

static const cli_option fit_options[] = {
    CLI_CUSTOM("reference", "F.exr", cli_list_add, "a 'gtlab render specular-occlusion' output (repeat for several)"),
    CLI_CUSTOM("ao", "F.exr", cli_list_add, "the 'gtlab render ao' output of the same view (one per --reference)"),
    CLI_CHOICE("definition", "D", definition_name, 3, "gtso (specocc.V, GGX f_r-weighted), d-only\n"
               "(specocc_d.V, the talk's older GGX D-weighted definition) or\n"
               "phong (specocc_phong.V, Phong-NDF-weighted, as the talk fitted)"),
    CLI_CHOICE("intersection", "I", intersection_name, 2, "exact or oat (Oat 2007's approximation)"),
    CLI_CHOICE("cone", "C", cone_name, 2, "talk (a_s = theta_m, the sampled half-vector's angle, as\n"
               "the talk) or reflected (a_s = 2 theta_m, the cone of reflected\n"
               "directions holding the same share of the lobe;\n"
               "techniques/specular_occlusion/README.md)"),
    CLI_OUTPUT_FILE("plot", "F.png", "the DSSIM-vs-u curve (gnuplot)"),
    CLI_OUTPUT("F.json", 1, "u, its DSSIM, the DSSIM at the talk's u = 0.01, and the curve"), CLI_END};
static const cli_command fit_command = {
    "fit aperture",
    "Finds the GTSO talk's gloss-to-aperture parameter u (a_s = arccos(u^(1/(p+2))),\n"
    "p = 2/alpha^2 - 2) as the talk did: the u whose cone/cone specular-occlusion\n"
    "images have the lowest mean DSSIM against the Monte Carlo references. DSSIM is not\n"
    "smooth in u, so the search scans log10 u over [-12, -0.05] by 1/8 decade, then\n"
    "refines by golden section (to 1e-3 in log10 u). The talk found u = 0.01.",
    fit_options, NULL, NULL};

typedef struct {
    const char *references[MAX_CASES], *aos[MAX_CASES], *output, *plot;
    cli_list reference_list, ao_list;
    int definition, intersection, cone;
} fit_settings;

/* 0 to go on, else 1 and the exit status. */
static int parse_options(int argc, char **argv, fit_settings *o, int *status)
{
    o->reference_list = (cli_list){o->references, 0, MAX_CASES, "--reference"};
    o->ao_list = (cli_list){o->aos, 0, MAX_CASES, "--ao"};
    if (cli_options_parse(&fit_command, (void *[]){&o->reference_list, &o->ao_list, &o->definition, &o->intersection,
                          &o->cone, &o->plot, &o->output}, argc, argv, status) != 0)
        return 1;
    if (o->reference_list.count == 0 || o->reference_list.count != o->ao_list.count)
        return *status = cli_failf("fit aperture", "give one --ao per --reference (at least one pair)"), 1;
    return 0;
}

static int fit_aperture(int argc, char **argv)
{
    fit_settings o = {0};
    int status;
    if (parse_options(argc, argv, &o, &status) != 0)
        return status;
    const char *channel = (const char *[]){CH_SPECOCC, CH_SPECOCC_D, CH_SPECOCC_PHONG}[o.definition];
    int exact = o.intersection == 0;
    so_aperture_mapping mapping = o.cone ? SO_APERTURE_PHONG_U_REFLECTED : SO_APERTURE_PHONG_U;
    gt_error e;
    if (atomic_file_check_writable(o.output, &e) != 0)
        return cli_fail(&e);
    static image refs[MAX_CASES], aos[MAX_CASES];
    static aperture_case cases[MAX_CASES];
    int loaded = 0;
    aperture_fit fit;
    if (aperture_cases_load(o.references, o.aos, o.reference_list.count, channel, refs, aos, cases, &loaded, &e) != 0 ||
        aperture_fit_run(cases, loaded, mapping, exact, &fit, &e) != 0 ||
        aperture_fit_write_json(&fit, channel, exact, o.output, &e) != 0 ||
        (o.plot && aperture_fit_plot(&fit, 1, o.plot, "GTSO gloss-to-aperture: DSSIM against u", &e) != 0))
        status = cli_fail(&e);
    else
        printf("u = %.4g (log10 u = %.3f): mean DSSIM %.5f; at the talk's u = 0.01: %.5f (%d evaluations)\n", fit.u,
               fit.log10_u, fit.dssim, fit.dssim_at_published, fit.evaluations);
    aperture_cases_free(refs, aos, cases, loaded);
    return status;
}

static const cli_option bench_options[] = {CLI_BENCH_VIEW, CLI_END};
static const cli_command bench_command = {
    "bench specular-occlusion",
    "Samples/s of the specular-occlusion reference (64 spp, roughness 0.5), 1 thread\n"
    "and T threads, with its rays/s (one ray per sample) and the speed-up of T threads\n"
    "over 1. Each figure is the best of R passes.",
    bench_options, NULL, NULL};

static void print_bench(const char *spec, int repeats, const specular_occlusion_bench_result *r)
{
    printf("specular-occlusion reference on %s, %dx%d, %d spp, roughness %.1f (best of %d)\n", spec, r->width,
           r->height, SPECOCC_BENCH_SPP, SPECOCC_BENCH_ROUGHNESS, repeats);
    printf("%-34s %14s %14s\n", "", "1 thread", "threads");
    printf("%-34s %14.3e %14.3e\n", "samples/s", r->samples_per_s[0], r->samples_per_s[1]);
    printf("%-34s %14.3e %14.3e\n", "rays/s (one ray per sample above)", r->rays_per_s[0], r->rays_per_s[1]);
    printf("%-34s %14s %14.3f\n", "speed-up threads / 1 thread", "", r->samples_per_s[1] / r->samples_per_s[0]);
}

static int bench_specular_occlusion(int argc, char **argv)
{
    const char *spec = "builtin:menger";
    long width = 256, height = 256, threads = threads_default(), repeats = 3;
    int status;
    if (cli_options_parse(&bench_command, (void *[]){&spec, &width, &height, &threads, &repeats}, argc, argv,
                          &status) != 0)
        return status;
    specular_occlusion_bench_result r;
    gt_error e;
    if (specular_occlusion_bench_run(spec, (int)width, (int)height, (int)threads, (int)repeats, &r, &e) != 0)
        return cli_fail(&e);
    print_bench(spec, (int)repeats, &r);
    return EXIT_OK;
}

GTLAB_STUDY_STAGE_NO_REQUEST(all_stage_specular_occlusion, so_study_result, specular_occlusion_study,
                             specular_occlusion_section)

const technique technique_specular_occlusion = {
    .name = "specular-occlusion",
    .subcommands = {
        [VERB_APPROX] = CLI_SUBCOMMANDS(
            {"specular-occlusion", approx_specular_occlusion, "GTSO and the other specular-occlusion variants from AO + bent normal"}),
        [VERB_FIT] = CLI_SUBCOMMANDS(
            {"aperture", fit_aperture, "GTSO gloss-to-aperture u by DSSIM against specular-occlusion references"}),
        [VERB_LUT] = CLI_SUBCOMMANDS(
            {"specular-occlusion", lut_specular_occlusion, "GTSO cone/lobe V_s(a_v, beta, r): EXR, 8-bit PNG, C header"}),
        [VERB_BENCH] = CLI_SUBCOMMANDS(
            {"specular-occlusion", bench_specular_occlusion, "samples/s of the specular-occlusion reference, 1 and T threads"}),
    },
    .stages = ALL_STAGES({"specular-occlusion", "specular occlusion", all_stage_specular_occlusion, NULL, NULL}),
};
