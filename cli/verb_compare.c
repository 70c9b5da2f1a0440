/* gtlab compare: SSIM/DSSIM, RMSE and absolute errors between one channel of
 * two EXR images, with the references' noise floors and an error heatmap
 * (metrics/image_comparison.h runs it and renders the table and JSON). */
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "metrics/image_comparison.h"

#define HEATMAP_PERCENTILE_TEXT IMAGE_COMPARISON_HEATMAP_PERCENTILE_TEXT
#define HEATMAP_COLOUR_MAP IMAGE_COMPARISON_COLOUR_MAP

static const char *metric_name(int i) { return i == 1 ? "dssim" : "abs"; }

static const cli_option options[] = {
    CLI_STRING("channel", "C", "channel to compare (default: the first of ao.V,\n"
               "multibounce.V, specocc.V, ao.Vuniform in both files)"),
    CLI_FLAG("noise-floor", "also report the noise floor: the DSSIM between the\n"
             "means of the even- and odd-index samples of A (A must\n"
             "be a gtlab reference render), and of B if B is one"),
    CLI_OUTPUT_FILE("heatmap", "F.png", "write an error heatmap (OIIO colour map '" HEATMAP_COLOUR_MAP "', black\n"
               "outside the mask); full scale is the " HEATMAP_PERCENTILE_TEXT " percentile of\n"
               "the error inside the mask, and is printed"),
    CLI_CHOICE("heatmap-metric", "M", metric_name, 2, "abs: |A-B| per pixel (default); dssim: (1 - SSIM) / 2\n"
               "of the window centred on each pixel"),
    CLI_DOUBLE("scale", "V", 1e-9, 1e9, "the heatmap's full scale, fixed (0.25: the report's AO error maps),\n"
               "instead of the percentile, so maps of several runs compare"),
    CLI_SWITCH("colour-bar", "the heatmap's colour bar below it, 0 (left) to the full scale\n"
               "(right) (default on)"),
    CLI_FLAG("json", "print one JSON object instead of the table"), CLI_END};
static const cli_command command = {
    "compare",
    "Compares one channel of two EXR images of the same size over the pixels where\n"
    "both images' mask.A is 1 (an image without mask.A counts as all 1):\n"
    "  SSIM      Wang, Bovik, Sheikh, Simoncelli 2004: 11x11 Gaussian window\n"
    "            (sigma 1.5), K1 = 0.01, K2 = 0.03, L = 1, population variances;\n"
    "            the mean over the window centres inside the mask whose window\n"
    "            lies inside the image (so 5-pixel borders are never centres)\n"
    "  DSSIM     (1 - SSIM) / 2\n"
    "  FLIP      NVIDIA's FLIP (Andersson et al. 2020) of B against A: LDR-FLIP\n"
    "            when A's values are at most 1, else HDR-FLIP (metrics/flip.h)\n"
    "  RMSE, mean |A-B|, max |A-B| (and where), means of A and B",
    options, "A.exr B.exr",
    "example: gtlab compare ao_ref.exr ao_gtao.exr --noise-floor --heatmap err.png\n"
    "exit status: 0 success, 1 bad input (missing file or channel, sizes differ),\n"
    "2 internal error"};

/* Returns 0 to go on, else 1 and the exit status. */
static int parse_options(int argc, char **argv, image_comparison_request *o, int *json, int *status)
{
    int metric = -1;
    cli_arguments files;
    o->colour_bar = -1;
    void *values[] = {&o->channel, &o->noise_floor, &o->heatmap, &metric, &o->scale, &o->colour_bar, json, &files};
    if (cli_options_parse(&command, values, argc, argv, status) != 0)
        return 1;
    if (!o->heatmap && (metric >= 0 || o->scale > 0 || o->colour_bar >= 0))
        return *status = cli_failf(metric >= 0 ? "--heatmap-metric" : o->scale > 0 ? "--scale" : "--colour-bar",
                                   "sets the heatmap: add --heatmap F.png"), 1;
    o->colour_bar = o->colour_bar != 0;
    o->heatmap_dssim = metric == 1;
    if (files.count != 2)
        return *status = cli_failf("compare", "give exactly two EXR files, A and B (see 'gtlab compare --help')"), 1;
    o->a = files.values[0];
    o->b = files.values[1];
    return 0;
}

int verb_compare(int argc, char **argv)
{
    image_comparison_request o = {0};
    image_comparison r;
    gt_error e;
    int json = 0, status;
    if (parse_options(argc, argv, &o, &json, &status) != 0)
        return status;
    if (image_comparison_run(&o, &r, &e) != 0)
        return cli_fail(&e);
    if (!json) {
        image_comparison_print(stdout, &o, &r);
        return EXIT_OK;
    }
    char *text = image_comparison_json(&o, &r);
    if (!text)
        return fprintf(stderr, "gtlab: compare: out of memory\n"), EXIT_INTERNAL_ERROR;
    printf("%s\n", text);
    free(text);
    return EXIT_OK;
}
