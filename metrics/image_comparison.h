/* `gtlab compare` as data: one channel of two EXR files compared over the
 * pixels inside both masks (metrics/image_pair.h: SSIM, DSSIM, RMSE, mean
 * and max |A-B|, the references' noise floors), an optional error heatmap
 * written as a PNG (OIIO colour map "inferno", full scale the 99th
 * percentile of the error inside the mask or a fixed one, with its colour
 * bar below it when asked), and the result rendered as a
 * table or a JSON object. Whatever runs a comparison (the command, a
 * shader run scored against a reference) goes through here. */
#ifndef GTLAB_METRICS_IMAGE_COMPARISON_H
#define GTLAB_METRICS_IMAGE_COMPARISON_H

#include <stdio.h>

#include "metrics/image_pair.h"

#define IMAGE_COMPARISON_HEATMAP_PERCENTILE 99.0 /* the heatmap's full scale */
#define IMAGE_COMPARISON_HEATMAP_PERCENTILE_TEXT "99th"
#define IMAGE_COMPARISON_COLOUR_MAP "inferno"

typedef struct {
    const char *a, *b;    /* the files */
    const char *channel;  /* NULL: the first of metrics_default_channels in both */
    const char *heatmap;  /* a PNG path, or NULL */
    int heatmap_dssim;    /* the heatmap shows per-window DSSIM, else |A-B| */
    int noise_floor;      /* also the DSSIM between each reference's even- and odd-sample means */
    double scale;         /* the heatmap's full scale, fixed (the report's error maps: 0.25); 0: the percentile */
    int colour_bar;       /* the heatmap has its colour bar below it (image_write_heatmap_with_bar) */
} image_comparison_request;

typedef struct {
    char channel[IMAGE_NAME_MAX];
    int width, height;
    metrics_pair_figures figures;
    float heatmap_vmax;
    const char *heatmap_vmax_rule; /* how heatmap_vmax was chosen, for the reader */
} image_comparison;

/* Reads both files, compares them and writes the heatmap if asked (checked
 * writable before anything is read). Returns 0, or -1 with e naming the
 * file and the problem. */
int image_comparison_run(const image_comparison_request *rq, image_comparison *out, gt_error *e);

/* The figures as the aligned table `gtlab compare` prints. */
void image_comparison_print(FILE *f, const image_comparison_request *rq, const image_comparison *r);

/* The figures as one JSON object (the caller frees it with free()), or
 * NULL when out of memory. */
char *image_comparison_json(const image_comparison_request *rq, const image_comparison *r);

#endif
