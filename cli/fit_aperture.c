/* gtlab fit aperture: the GTSO talk's gloss-to-aperture parameter u, found
 * as the talk did, by DSSIM of cone/cone specular-occlusion images against
 * Monte Carlo references (fitters/aperture_fit.h describes the search). */
#define _GNU_SOURCE
#include <cjson/cJSON.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "core/atomic_file.h"
#include "core/reference_schema.h"
#include "report/aperture_fit_figures.h"
#include "studies/specular_occlusion_inputs.h"

enum { MAX_CASES = 32 };

static void print_help(void)
{
    printf("usage: gtlab fit aperture --reference SO.exr --ao AO.exr [--reference ... --ao ...] -o fit.json\n"
           "\n"
           "Finds the GTSO talk's gloss-to-aperture parameter u (a_s = arccos(u^(1/(p+2))),\n"
           "p = 2/alpha^2 - 2) as the talk did: the u whose cone/cone specular-occlusion\n"
           "images have the lowest mean DSSIM against the Monte Carlo references. DSSIM is not\n"
           "smooth in u, so the search scans log10 u over [-12, -0.05] by 1/8 decade, then\n"
           "refines by golden section (to 1e-3 in log10 u). The talk found u = 0.01.\n"
           "\n"
           "options:\n"
           "  --reference F.exr   a 'gtlab render specular-occlusion' output (repeat for several)\n"
           "  --ao F.exr          the 'gtlab render ao' output of the same view (one per --reference)\n"
           "  --definition D      gtso (specocc.V, GGX f_r-weighted; default), d-only\n"
           "                      (specocc_d.V, the talk's older GGX D-weighted definition) or\n"
           "                      phong (specocc_phong.V, Phong-NDF-weighted, as the talk fitted)\n"
           "  --intersection I    exact (default) or oat (Oat 2007's approximation)\n"
           "  --cone C            talk (default: a_s = theta_m, the sampled half-vector's angle, as\n"
           "                      the talk) or reflected (a_s = 2 theta_m, the cone of reflected\n"
           "                      directions holding the same share of the lobe; docs/decisions.md)\n"
           "  --plot F.png        the DSSIM-vs-u curve (gnuplot)\n"
           "  -o, --output F.json u, its DSSIM, the DSSIM at the talk's u = 0.01, and the curve\n"
           "  -h, --help\n");
}

typedef struct {
    const char *references[MAX_CASES], *aos[MAX_CASES], *output, *plot;
    int reference_count, ao_count, exact;
    so_aperture_mapping mapping;
    const char *channel;
} fit_options;

static int parse_options(int argc, char **argv, fit_options *o)
{
    static const struct option longs[] = {{"reference", required_argument, 0, 'r'}, {"ao", required_argument, 0, 'a'},
                                          {"definition", required_argument, 0, 'd'}, {"intersection", required_argument, 0, 'i'},
                                          {"cone", required_argument, 0, 'c'},      {"plot", required_argument, 0, 'p'},      {"output", required_argument, 0, 'o'},
                                          {"help", no_argument, 0, 'h'},            {0, 0, 0, 0}};
    int c;
    while ((c = getopt_long(argc, argv, "o:h", longs, NULL)) != -1) {
        switch (c) {
        case 'r':
            if (o->reference_count == MAX_CASES) return cli_failf("--reference", "at most %d", MAX_CASES), -1;
            o->references[o->reference_count++] = optarg;
            break;
        case 'a':
            if (o->ao_count == MAX_CASES) return cli_failf("--ao", "at most %d", MAX_CASES), -1;
            o->aos[o->ao_count++] = optarg;
            break;
        case 'd':
            if (strcmp(optarg, "gtso") == 0) o->channel = CH_SPECOCC;
            else if (strcmp(optarg, "d-only") == 0) o->channel = CH_SPECOCC_D;
            else if (strcmp(optarg, "phong") == 0) o->channel = CH_SPECOCC_PHONG;
            else return cli_failf("--definition", "'%s' is not gtso, d-only or phong", optarg), -1;
            break;
        case 'i':
            if (strcmp(optarg, "exact") == 0) o->exact = 1;
            else if (strcmp(optarg, "oat") == 0) o->exact = 0;
            else return cli_failf("--intersection", "'%s' is neither exact nor oat", optarg), -1;
            break;
        case 'c':
            if (strcmp(optarg, "talk") == 0) o->mapping = SO_APERTURE_PHONG_U;
            else if (strcmp(optarg, "reflected") == 0) o->mapping = SO_APERTURE_PHONG_U_REFLECTED;
            else return cli_failf("--cone", "'%s' is neither talk nor reflected", optarg), -1;
            break;
        case 'p': o->plot = optarg; break;
        case 'o': o->output = optarg; break;
        case 'h': print_help(); return 1;
        default: return cli_usage_error("fit aperture"), -1;
        }
    }
    if (optind < argc)
        return cli_failf("fit aperture", "unexpected argument '%s'", argv[optind]), -1;
    if (o->reference_count == 0 || o->reference_count != o->ao_count)
        return cli_failf("fit aperture", "give one --ao per --reference (at least one pair)"), -1;
    if (!o->output)
        return cli_failf("fit aperture", "-o/--output is required"), -1;
    return 0;
}

int fit_aperture(int argc, char **argv)
{
    fit_options o = {.exact = 1, .mapping = SO_APERTURE_PHONG_U, .channel = CH_SPECOCC};
    int parsed = parse_options(argc, argv, &o);
    if (parsed != 0)
        return parsed > 0 ? EXIT_OK : EXIT_USER_ERROR;
    gt_error e;
    if (atomic_file_check_writable(o.output, &e) != 0)
        return cli_fail(&e);
    static image refs[MAX_CASES], aos[MAX_CASES];
    static aperture_case cases[MAX_CASES];
    int loaded = 0, status = EXIT_OK;
    aperture_fit fit;
    if (aperture_cases_load(o.references, o.aos, o.reference_count, o.channel, refs, aos, cases, &loaded, &e) != 0 ||
        aperture_fit_run(cases, loaded, o.mapping, o.exact, &fit, &e) != 0) {
        status = cli_fail(&e);
    } else {
        cJSON *j = aperture_fit_json(&fit, o.channel, o.exact);
        char *text = cJSON_Print(j);
        cJSON_Delete(j);
        if (!text)
            gt_error_set(&e, o.output, "out of memory");
        if (!text || atomic_write_text(o.output, text, &e) != 0 ||
            (o.plot && aperture_fit_plot(&fit, 1, o.plot, "GTSO gloss-to-aperture: DSSIM against u", &e) != 0))
            status = cli_fail(&e);
        else
            printf("u = %.4g (log10 u = %.3f): mean DSSIM %.5f; at the talk's u = 0.01: %.5f (%d evaluations)\n", fit.u,
                   fit.log10_u, fit.dssim, fit.dssim_at_published, fit.evaluations);
        free(text);
    }
    aperture_cases_free(refs, aos, cases, loaded);
    return status;
}
