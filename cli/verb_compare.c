/* gtlab compare: SSIM/DSSIM, RMSE and absolute errors between one channel of
 * two EXR images, with the references' noise floors and an error heatmap.
 * The metrics themselves live in metrics/ (ssim.h, image_error.h). */
#define _GNU_SOURCE
#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/cli_options.h"
#include "core/atomic_file.h"
#include "core/exr_io.h"
#include "core/image_io.h"
#include "metrics/image_pair.h"

#define HEATMAP_PERCENTILE 99.0 /* the heatmap's full scale */
#define HEATMAP_PERCENTILE_TEXT "99th"
#define HEATMAP_COLOUR_MAP "inferno"

static const char *metric_name(int i) { return i == 1 ? "dssim" : "abs"; }

static const cli_option options[] = {
    CLI_STRING("channel", "C", "channel to compare (default: the first of ao.V,\n"
               "multibounce.V, specocc.V, ao.Vuniform in both files)"),
    CLI_FLAG("noise-floor", "also report the noise floor: the DSSIM between the\n"
             "means of the even- and odd-index samples of A (A must\n"
             "be a gtlab reference render), and of B if B is one"),
    CLI_STRING("heatmap", "F.png", "write an error heatmap (OIIO colour map '" HEATMAP_COLOUR_MAP "', black\n"
               "outside the mask); full scale is the " HEATMAP_PERCENTILE_TEXT " percentile of\n"
               "the error inside the mask, and is printed"),
    CLI_CHOICE("heatmap-metric", "M", metric_name, 2, "abs: |A-B| per pixel (default); dssim: (1 - SSIM) / 2\n"
               "of the window centred on each pixel"),
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
    "  RMSE, mean |A-B|, max |A-B| (and where), means of A and B",
    options, "A.exr B.exr",
    "example: gtlab compare ao_ref.exr ao_gtao.exr --noise-floor --heatmap err.png\n"
    "exit status: 0 success, 1 bad input (missing file or channel, sizes differ),\n"
    "2 internal error"};

typedef struct {
    const char *a, *b, *channel, *heatmap;
    int heatmap_dssim; /* else |A-B| */
    int json, noise_floor;
} compare_options;

/* Returns 0 to go on, else 1 and the exit status. */
static int parse_options(int argc, char **argv, compare_options *o, int *status)
{
    int metric = -1;
    cli_arguments files;
    if (cli_options_parse(&command, (void *[]){&o->channel, &o->noise_floor, &o->heatmap, &metric, &o->json, &files},
                          argc, argv, status) != 0)
        return 1;
    if (metric >= 0 && !o->heatmap)
        gt_warn("--heatmap-metric", "ignored without --heatmap");
    o->heatmap_dssim = metric == 1;
    if (files.count != 2)
        return *status = cli_failf("compare", "give exactly two EXR files, A and B (see 'gtlab compare --help')"), 1;
    o->a = files.values[0];
    o->b = files.values[1];
    return 0;
}

typedef struct {
    metrics_pair_figures figures;
    float heatmap_vmax;
    const char *heatmap_vmax_rule; /* how heatmap_vmax was chosen, for the reader */
} compare_results;

static const char *scale_rule(metrics_heatmap_scale scale)
{
    switch (scale) {
    case HEATMAP_SCALE_PERCENTILE: return "the " HEATMAP_PERCENTILE_TEXT " percentile";
    case HEATMAP_SCALE_MAXIMUM: return "the maximum, as the " HEATMAP_PERCENTILE_TEXT " percentile is 0";
    default: return "arbitrary: the error is 0 everywhere";
    }
}

/* The heatmap (metrics_pair_heatmap) written as a PNG. */
static int write_heatmap(const compare_options *o, const metrics_pair *pair, const float *ssim_map,
                         compare_results *r, gt_error *e)
{
    metrics_heatmap h;
    if (metrics_pair_heatmap(pair, ssim_map, HEATMAP_PERCENTILE, o->heatmap, &h, e) != 0)
        return -1;
    r->heatmap_vmax = h.vmax;
    r->heatmap_vmax_rule = scale_rule(h.scale);
    int status = image_write_heatmap(o->heatmap, h.values, h.mask, pair->width, pair->height, h.vmax,
                                     HEATMAP_COLOUR_MAP, e);
    metrics_heatmap_free(&h);
    return status;
}

/* Every figure the options ask for. */
static int measure(const compare_options *o, const image *a, const image *b, const metrics_pair *pair,
                   compare_results *r, gt_error *e)
{
    float *ssim_map = NULL;
    if (o->heatmap && o->heatmap_dssim && !(ssim_map = malloc(sizeof *ssim_map * image_pixel_count(a))))
        return gt_error_set(e, o->a, "out of memory");
    int status = metrics_pair_measure(pair, a, o->a, b, o->b, o->noise_floor, ssim_map, &r->figures, e);
    if (status == 0 && o->heatmap)
        status = write_heatmap(o, pair, ssim_map, r, e);
    free(ssim_map);
    return status;
}

static const char *heatmap_metric_name(const compare_options *o)
{
    return o->heatmap_dssim ? "per-window DSSIM" : "|A-B|";
}

static void print_table(const compare_options *o, const metrics_pair *pair, const compare_results *r)
{
    printf("A  %s\nB  %s\n", o->a, o->b);
    printf("channel %s, %dx%d: %zu pixels inside both masks, %zu SSIM window centres\n\n", pair->channel,
           pair->width, pair->height, r->figures.error.pixels, r->figures.ssim.centres);
    printf("  SSIM          %.6f\n", r->figures.ssim.ssim);
    printf("  DSSIM         %.6g\n", r->figures.ssim.dssim);
    printf("  RMSE          %.6g\n", r->figures.error.rmse);
    printf("  mean |A-B|    %.6g\n", r->figures.error.mean_abs);
    printf("  max |A-B|     %.6g at pixel (%d, %d)\n", r->figures.error.max_abs, r->figures.error.max_x, r->figures.error.max_y);
    printf("  mean A        %.6g\n", r->figures.error.mean_a);
    printf("  mean B        %.6g\n", r->figures.error.mean_b);
    if (r->figures.has_floor_a)
        printf("  noise floor   DSSIM %.6g between the even and odd samples of A\n", r->figures.floor_a.dssim);
    if (r->figures.has_floor_b)
        printf("                DSSIM %.6g between the even and odd samples of B\n", r->figures.floor_b.dssim);
    if (o->heatmap)
        printf("\nheatmap %s: %s, colour map %s, full scale %.6g (%s); black outside the mask\n", o->heatmap,
               heatmap_metric_name(o), HEATMAP_COLOUR_MAP, r->heatmap_vmax, r->heatmap_vmax_rule);
}

/* The JSON object, or NULL when out of memory. */
static char *results_json(const compare_options *o, const metrics_pair *pair, const compare_results *r)
{
    cJSON *root = cJSON_CreateObject();
    if (!root)
        return NULL;
    cJSON_AddStringToObject(root, "a", o->a);
    cJSON_AddStringToObject(root, "b", o->b);
    cJSON_AddStringToObject(root, "channel", pair->channel);
    cJSON_AddNumberToObject(root, "width", pair->width);
    cJSON_AddNumberToObject(root, "height", pair->height);
    cJSON_AddNumberToObject(root, "pixels", (double)r->figures.error.pixels);
    cJSON_AddNumberToObject(root, "ssim_window_centres", (double)r->figures.ssim.centres);
    cJSON_AddNumberToObject(root, "ssim", r->figures.ssim.ssim);
    cJSON_AddNumberToObject(root, "dssim", r->figures.ssim.dssim);
    cJSON_AddNumberToObject(root, "rmse", r->figures.error.rmse);
    cJSON_AddNumberToObject(root, "mean_abs", r->figures.error.mean_abs);
    cJSON_AddNumberToObject(root, "max_abs", r->figures.error.max_abs);
    const int at[2] = {r->figures.error.max_x, r->figures.error.max_y};
    cJSON_AddItemToObject(root, "max_abs_pixel", cJSON_CreateIntArray(at, 2));
    cJSON_AddNumberToObject(root, "mean_a", r->figures.error.mean_a);
    cJSON_AddNumberToObject(root, "mean_b", r->figures.error.mean_b);
    if (r->figures.has_floor_a)
        cJSON_AddNumberToObject(root, "noise_floor_dssim", r->figures.floor_a.dssim);
    if (r->figures.has_floor_b)
        cJSON_AddNumberToObject(root, "noise_floor_dssim_b", r->figures.floor_b.dssim);
    if (o->heatmap) {
        cJSON *h = cJSON_AddObjectToObject(root, "heatmap");
        cJSON_AddStringToObject(h, "path", o->heatmap);
        cJSON_AddStringToObject(h, "metric", o->heatmap_dssim ? "dssim" : "abs");
        cJSON_AddStringToObject(h, "colour_map", HEATMAP_COLOUR_MAP);
        cJSON_AddNumberToObject(h, "vmax", r->heatmap_vmax);
        cJSON_AddStringToObject(h, "vmax_is", r->heatmap_vmax_rule);
    }
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    return text;
}

int verb_compare(int argc, char **argv)
{
    compare_options o = {0};
    int status;
    if (parse_options(argc, argv, &o, &status) != 0)
        return status;

    gt_error e;
    if (o.heatmap && atomic_file_check_writable(o.heatmap, &e) != 0)
        return cli_fail(&e);
    image a, b;
    if (exr_read(o.a, &a, &e) != 0)
        return cli_fail(&e);
    if (exr_read(o.b, &b, &e) != 0) {
        image_free(&a);
        return cli_fail(&e);
    }
    metrics_pair pair;
    compare_results r = {0};
    if (metrics_pair_init(&pair, &a, o.a, &b, o.b, o.channel, &e) != 0) {
        status = cli_fail(&e);
    } else {
        if (measure(&o, &a, &b, &pair, &r, &e) != 0) {
            status = cli_fail(&e);
        } else if (!o.json) {
            print_table(&o, &pair, &r);
        } else {
            char *text = results_json(&o, &pair, &r);
            if (text)
                printf("%s\n", text);
            else
                status = (fprintf(stderr, "gtlab: compare: out of memory\n"), EXIT_INTERNAL_ERROR);
            cJSON_free(text);
        }
        metrics_pair_free(&pair);
    }
    image_free(&a);
    image_free(&b);
    return status;
}
