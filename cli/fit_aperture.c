/* gtlab fit aperture: the GTSO talk's gloss-to-aperture parameter u, found
 * as the talk did, by DSSIM of cone/cone specular-occlusion images against
 * Monte Carlo references (fitters/aperture_fit.h describes the search). */
#define _GNU_SOURCE
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "core/atomic_file.h"
#include "core/reference_schema.h"
#include "report/aperture_fit_figures.h"
#include "studies/specular_occlusion_inputs.h"

enum { MAX_CASES = 32 };

static const char *definition_name(int i) { return (const char *[]){"gtso", "d-only", "phong"}[i]; }
static const char *intersection_name(int i) { return i ? "oat" : "exact"; }
static const char *cone_name(int i) { return i ? "reflected" : "talk"; }

static const cli_option options[] = {
    CLI_CUSTOM("reference", "F.exr", cli_list_add, "a 'gtlab render specular-occlusion' output (repeat for several)"),
    CLI_CUSTOM("ao", "F.exr", cli_list_add, "the 'gtlab render ao' output of the same view (one per --reference)"),
    CLI_CHOICE("definition", "D", definition_name, 3, "gtso (specocc.V, GGX f_r-weighted), d-only\n"
               "(specocc_d.V, the talk's older GGX D-weighted definition) or\n"
               "phong (specocc_phong.V, Phong-NDF-weighted, as the talk fitted)"),
    CLI_CHOICE("intersection", "I", intersection_name, 2, "exact or oat (Oat 2007's approximation)"),
    CLI_CHOICE("cone", "C", cone_name, 2, "talk (a_s = theta_m, the sampled half-vector's angle, as\n"
               "the talk) or reflected (a_s = 2 theta_m, the cone of reflected\n"
               "directions holding the same share of the lobe; docs/decisions.md)"),
    CLI_STRING("plot", "F.png", "the DSSIM-vs-u curve (gnuplot)"),
    CLI_OUTPUT("F.json", 1, "u, its DSSIM, the DSSIM at the talk's u = 0.01, and the curve"), CLI_END};
static const cli_command command = {
    "fit aperture",
    "Finds the GTSO talk's gloss-to-aperture parameter u (a_s = arccos(u^(1/(p+2))),\n"
    "p = 2/alpha^2 - 2) as the talk did: the u whose cone/cone specular-occlusion\n"
    "images have the lowest mean DSSIM against the Monte Carlo references. DSSIM is not\n"
    "smooth in u, so the search scans log10 u over [-12, -0.05] by 1/8 decade, then\n"
    "refines by golden section (to 1e-3 in log10 u). The talk found u = 0.01.",
    options, NULL, NULL};

typedef struct {
    const char *references[MAX_CASES], *aos[MAX_CASES], *output, *plot;
    cli_list reference_list, ao_list;
    int definition, intersection, cone;
} fit_options;

/* 0 to go on, else 1 and the exit status. */
static int parse_options(int argc, char **argv, fit_options *o, int *status)
{
    o->reference_list = (cli_list){o->references, 0, MAX_CASES, "--reference"};
    o->ao_list = (cli_list){o->aos, 0, MAX_CASES, "--ao"};
    if (cli_options_parse(&command, (void *[]){&o->reference_list, &o->ao_list, &o->definition, &o->intersection,
                          &o->cone, &o->plot, &o->output}, argc, argv, status) != 0)
        return 1;
    if (o->reference_list.count == 0 || o->reference_list.count != o->ao_list.count)
        return *status = cli_failf("fit aperture", "give one --ao per --reference (at least one pair)"), 1;
    return 0;
}

int fit_aperture(int argc, char **argv)
{
    fit_options o = {0};
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
        aperture_fit_run(cases, loaded, mapping, exact, &fit, &e) != 0) {
        status = cli_fail(&e);
    } else {
        cJSON *j = aperture_fit_json(&fit, channel, exact);
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
