/* The split-sum DFG (environment BRDF) LUT of Karis 2013: `gtlab lut dfg`
 * and its section of `gtlab all` (studies/dfg.h), beside Filament's 128^2. */
#define _GNU_SOURCE
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "cli/gnuplot_plot.h"
#include "cli/report_table.h"
#include "cli/technique.h"
#include "studies/dfg.h"
#include "core/threads.h"

static void print_help(void)
{
    printf("usage: gtlab lut dfg [--size N] [--threads T] -o DIR\n"
           "\n"
           "Tabulates the split-sum environment BRDF of Karis 2013 for GGX with height-correlated\n"
           "Smith masking: scale A and bias B (directional albedo = F0 A + B under Schlick's\n"
           "Fresnel) and E = A + B, the single-scattering albedo that multiple-scattering energy\n"
           "compensation (Kulla-Conty 2017, Fdez-Aguera 2019) divides by. x = n.v, y = perceptual\n"
           "roughness, sampled at texel centres as a GPU reads them (luts/dfg_lut.h).\n"
           "Writes DIR/dfg_N.exr (float A, B, E), .png (16-bit, R = A, G = B), .h (C array)\n"
           "and .hlsl (the array and DFG(nv, roughness), the same bilinear lookup).\n"
           "\n"
           "  --size N        %d..%d (default %d, Filament's choice)\n"
           "  --threads T     worker threads (default: all cores); the table does not depend on it\n"
           "  -o, --output DIR  output folder (created if absent)\n"
           "  -h, --help\n",
           DFG_MIN_SIZE, DFG_MAX_SIZE, DFG_FILAMENT_SIZE);
}

static int lut_dfg(int argc, char **argv)
{
    static const struct option longs[] = {{"size", required_argument, 0, 'n'}, {"threads", required_argument, 0, 't'},
                                          {"output", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'},
                                          {0, 0, 0, 0}};
    long size = DFG_FILAMENT_SIZE, threads = threads_default();
    const char *dir = NULL;
    for (int c; (c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1;) {
        switch (c) {
        case 'n': if (cli_parse_int("--size", optarg, DFG_MIN_SIZE, DFG_MAX_SIZE, &size)) return EXIT_USER_ERROR; break;
        case 't': if (cli_parse_int("--threads", optarg, 1, 1024, &threads)) return EXIT_USER_ERROR; break;
        case 'o': dir = optarg; break;
        case 'h': print_help(); return EXIT_OK;
        default: return cli_usage_error("lut dfg");
        }
    }
    if (optind < argc)
        return cli_failf("lut dfg", "unexpected argument '%s'", argv[optind]);
    if (!dir)
        return cli_failf("lut dfg", "-o/--output DIR is required");
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return cli_failf(dir, "cannot create the folder: %s", strerror(errno));
    dfg_result r;
    gt_error e;
    if (dfg_write_table(dir, (int)size, (int)threads, &r, &e) != 0)
        return cli_fail(&e);
    printf("%s/dfg_%ld.{exr,png,h,hlsl}: %ld^2 in %.2f s; quadrature error <= %.1e; smallest albedo E %.4f\n", dir,
           size, size, r.build_seconds, r.max_error_estimate, r.e_min);
    return EXIT_OK;
}

#define ROW dfg_interpolation_result
static const report_column columns[] = {
    REPORT_INT("size N", "size", ROW, size),
    REPORT_REAL("max E, whole square", "max_error_e", "%.2e", ROW, max_error[DFG_ALBEDO]),
    REPORT_REAL("RMS E, whole square", "rms_error_e", "%.2e", ROW, rms_error[DFG_ALBEDO]),
    REPORT_REAL("max A, between centres", "interior_max_error_a", "%.2e", ROW, interior_max_error[DFG_SCALE]),
    REPORT_REAL("max B, between centres", "interior_max_error_b", "%.2e", ROW, interior_max_error[DFG_BIAS]),
    REPORT_REAL("max E, between centres", "interior_max_error_e", "%.2e", ROW, interior_max_error[DFG_ALBEDO]),
    REPORT_REAL("RMS E, between centres", "interior_rms_error_e", "%.2e", ROW, interior_rms_error[DFG_ALBEDO]),
    REPORT_REAL(NULL, "max_error_a", NULL, ROW, max_error[DFG_SCALE]),
    REPORT_REAL(NULL, "max_error_b", NULL, ROW, max_error[DFG_BIAS]),
    REPORT_REAL(NULL, "interior_rms_error_a", NULL, ROW, interior_rms_error[DFG_SCALE]),
    REPORT_REAL(NULL, "interior_rms_error_b", NULL, ROW, interior_rms_error[DFG_BIAS]),
    REPORT_INT(NULL, "interior_points", ROW, interior_points),
    REPORT_REAL("build s", "build_seconds", "%.1f", ROW, build_seconds),
};
static const report_column table_columns[] = {
    REPORT_INT(NULL, "size", dfg_result, request.size),
    REPORT_INT(NULL, "interpolation_points", dfg_result, request.points),
    REPORT_REAL(NULL, "max_quadrature_error_estimate", NULL, dfg_result, max_error_estimate),
    REPORT_REAL(NULL, "smallest_albedo_e", NULL, dfg_result, e_min),
    REPORT_REAL(NULL, "build_seconds", NULL, dfg_result, build_seconds),
};
#undef ROW

/* Interior RMS error of A, B and E against the size, log-log. */
static int plot(const all_context *ctx, gt_error *e)
{
    char data[4096], png[4096], script[8192];
    snprintf(data, sizeof data, "%s/%s/dfg_interpolation.dat", ctx->study.output_dir, DFG_LUTS_DIR);
    snprintf(png, sizeof png, "%s/figures/dfg_interpolation.png", ctx->study.output_dir);
    snprintf(script, sizeof script,
             "set logscale xy\nset xrange [10:400]\nset xlabel 'table size N (N x N)'\nset ylabel 'RMS error between texel centres'\n"
             "set title 'DFG LUT: bilinear lookup against the quadrature'\nset key top right\n"
             "set arrow from %d, graph 0 to %d, graph 1 nohead dashtype 2\n"
             "set label 'Filament' at %d, graph 0.95 right offset -0.5,0\n"
             "plot '%s' using 1:5 with linespoints title 'A', '' using 1:9 with linespoints title 'B', "
             "'' using 1:13 with linespoints title 'E = A + B'\n",
             DFG_FILAMENT_SIZE, DFG_FILAMENT_SIZE, DFG_FILAMENT_SIZE, data);
    return gnuplot_render(script, png, 900, 520, e);
}

static void render_findings(all_context *ctx, const dfg_result *r)
{
    if (r->filament_row < 1)
        return;
    const dfg_interpolation_result *f = &r->by_size[r->filament_row], *half = &r->by_size[r->filament_row - 1];
    report_finding(ctx->doc, "DFG LUT",
                   "At Filament's %dx%d, bilinear lookup of the split-sum DFG table is within %.1e of the exact "
                   "albedo E between texel centres (RMS %.1e); %dx%d has %.1fx the RMS error. Near the borders, "
                   "where a texture clamps, the error reaches %.1e.",
                   f->size, f->size, f->interior_max_error[DFG_ALBEDO], f->interior_rms_error[DFG_ALBEDO], half->size,
                   half->size, half->interior_rms_error[DFG_ALBEDO] / f->interior_rms_error[DFG_ALBEDO],
                   f->max_error[DFG_ALBEDO]);
}

static void render_section(all_context *ctx, const dfg_result *r)
{
    const dfg_request *rq = &r->request;
    report_heading(ctx->doc, 2, "Split-sum DFG LUT (environment BRDF)");
    report_paragraph(ctx->doc,
                     "Karis 2013's split sum tabulates the GGX directional albedo as F0 A(n.v, r) + B(n.v, r) "
                     "(height-correlated Smith masking, Schlick Fresnel), and E = A + B, the single-scattering "
                     "albedo that multiple-scattering energy compensation divides by (Kulla-Conty 2017). The %dx%d "
                     "table is computed by adaptive Gauss-Kronrod quadrature with an error bound of %.1e per texel "
                     "(tested against Monte Carlo and the mirror limit), and written as luts/dfg_%d.exr, .png, .h "
                     "and .hlsl. Its smallest E is %.3f: single scattering loses up to %.0f%% of the energy. The "
                     "table below scores the bilinear lookup a GPU performs against the quadrature at %d random "
                     "(n.v, r), for each size; Filament ships %dx%d. 'Between centres' excludes the half-texel "
                     "borders, where clamp-to-edge makes the error first order in 1/N.",
                     rq->size, rq->size, r->max_error_estimate, rq->size, r->e_min, 100.0 * (1.0 - r->e_min),
                     rq->points, DFG_FILAMENT_SIZE, DFG_FILAMENT_SIZE);
    cJSON *json = cJSON_AddObjectToObject(ctx->summary, "dfg");
    report_object(json, "table", table_columns, (int)(sizeof table_columns / sizeof table_columns[0]), r);
    report_rows(ctx->doc, cJSON_AddArrayToObject(json, "interpolation"), columns,
                (int)(sizeof columns / sizeof columns[0]), r->by_size, sizeof r->by_size[0], rq->size_count);
    const char *p[1] = {"figures/dfg_interpolation.png"}, *c[1] = {"DFG LUT: RMS interpolation error against size"};
    report_figures(ctx->doc, 1, p, c);
    render_findings(ctx, r);
}

static int all_stage_dfg(all_context *ctx, gt_error *e)
{
    static dfg_result r;
    dfg_request rq = dfg_default_request(ctx->study.quality);
    char figures[2048];
    if (dfg_study(&ctx->study, &rq, &r, e) != 0 || study_make_dir(&ctx->study, "figures", figures, sizeof figures, e) != 0 ||
        plot(ctx, e) != 0)
        return -1;
    render_section(ctx, &r);
    return 0;
}

static const cli_subcommand luts[] = {
    {"dfg", lut_dfg, "split-sum DFG (Karis 2013): scale, bias, albedo vs n.v and roughness: EXR, PNG, C, HLSL"},
    {NULL, NULL, NULL},
};
static const all_stage stages[] = {
    {"dfg", "split-sum DFG LUT", all_stage_dfg, DFG_LUTS_DIR, NULL},
    {NULL, NULL, NULL, NULL, NULL},
};

const technique technique_dfg = {.name = "dfg", .subcommands = {[VERB_LUT] = luts}, .stages = stages};
