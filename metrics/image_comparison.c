/* One comparison of two EXR files, and its table and JSON: see the header. */
#include "metrics/image_comparison.h"

#include <cjson/cJSON.h>
#include <stdlib.h>

#include "core/files/atomic_file.h"
#include "core/files/exr_io.h"
#include "core/files/image_io.h"

static const char *scale_rule(metrics_heatmap_scale scale)
{
    switch (scale) {
    case HEATMAP_SCALE_PERCENTILE: return "the " IMAGE_COMPARISON_HEATMAP_PERCENTILE_TEXT " percentile";
    case HEATMAP_SCALE_MAXIMUM:
        return "the maximum, as the " IMAGE_COMPARISON_HEATMAP_PERCENTILE_TEXT " percentile is 0";
    default: return "arbitrary: the error is 0 everywhere";
    }
}

/* The heatmap (metrics_pair_heatmap) written as a PNG. */
static int write_heatmap(const image_comparison_request *rq, const metrics_pair *pair, const float *ssim_map,
                         image_comparison *r, gt_error *e)
{
    metrics_heatmap h;
    if (metrics_pair_heatmap(pair, ssim_map, IMAGE_COMPARISON_HEATMAP_PERCENTILE, rq->heatmap, &h, e) != 0)
        return -1;
    r->heatmap_vmax = rq->scale > 0 ? (float)rq->scale : h.vmax;
    r->heatmap_vmax_rule = rq->scale > 0 ? "fixed by --scale" : scale_rule(h.scale);
    int status = (rq->colour_bar ? image_write_heatmap_with_bar : image_write_heatmap)(
        rq->heatmap, h.values, h.mask, pair->width, pair->height, r->heatmap_vmax, IMAGE_COMPARISON_COLOUR_MAP, e);
    metrics_heatmap_free(&h);
    return status;
}

/* Every figure the request asks for. */
static int measure(const image_comparison_request *rq, const image *a, const image *b, const metrics_pair *pair,
                   image_comparison *r, gt_error *e)
{
    float *ssim_map = NULL;
    if (rq->heatmap && rq->heatmap_dssim && !(ssim_map = malloc(sizeof *ssim_map * image_pixel_count(a))))
        return gt_error_set(e, rq->a, "out of memory");
    int status = metrics_pair_measure(pair, a, rq->a, b, rq->b, rq->noise_floor, ssim_map, &r->figures, e);
    if (status == 0 && rq->heatmap)
        status = write_heatmap(rq, pair, ssim_map, r, e);
    free(ssim_map);
    return status;
}

static int compare_images(const image_comparison_request *rq, const image *a, const image *b, image_comparison *out,
                          gt_error *e)
{
    metrics_pair pair;
    if (metrics_pair_init(&pair, a, rq->a, b, rq->b, rq->channel, e) != 0)
        return -1;
    snprintf(out->channel, sizeof out->channel, "%s", pair.channel);
    out->width = pair.width, out->height = pair.height;
    int status = measure(rq, a, b, &pair, out, e);
    metrics_pair_free(&pair);
    return status;
}

int image_comparison_run(const image_comparison_request *rq, image_comparison *out, gt_error *e)
{
    *out = (image_comparison){0};
    if (rq->heatmap && atomic_file_check_writable(rq->heatmap, e) != 0)
        return -1;
    image a, b;
    if (exr_read(rq->a, &a, e) != 0)
        return -1;
    if (exr_read(rq->b, &b, e) != 0) {
        image_free(&a);
        return -1;
    }
    int status = compare_images(rq, &a, &b, out, e);
    image_free(&a);
    image_free(&b);
    return status;
}

static const char *heatmap_metric_name(const image_comparison_request *rq)
{
    return rq->heatmap_dssim ? "per-window DSSIM" : "|A-B|";
}

void image_comparison_print(FILE *f, const image_comparison_request *rq, const image_comparison *r)
{
    const metrics_pair_figures *x = &r->figures;
    fprintf(f, "A  %s\nB  %s\n", rq->a, rq->b);
    fprintf(f, "channel %s, %dx%d: %zu pixels inside both masks, %zu SSIM window centres\n\n", r->channel, r->width,
            r->height, x->error.pixels, x->ssim.centres);
    fprintf(f, "  SSIM          %.6f\n", x->ssim.ssim);
    fprintf(f, "  DSSIM         %.6g\n", x->ssim.dssim);
    fprintf(f, "  FLIP          %.6g (%s of B against A)\n", x->flip.mean, x->flip.hdr ? "HDR-FLIP" : "LDR-FLIP");
    fprintf(f, "  RMSE          %.6g\n", x->error.rmse);
    fprintf(f, "  mean |A-B|    %.6g\n", x->error.mean_abs);
    fprintf(f, "  max |A-B|     %.6g at pixel (%d, %d)\n", x->error.max_abs, x->error.max_x, x->error.max_y);
    fprintf(f, "  mean A        %.6g\n", x->error.mean_a);
    fprintf(f, "  mean B        %.6g\n", x->error.mean_b);
    if (x->has_floor_a)
        fprintf(f, "  noise floor   DSSIM %.6g between the even and odd samples of A\n", x->floor_a.dssim);
    if (x->has_floor_b)
        fprintf(f, "                DSSIM %.6g between the even and odd samples of B\n", x->floor_b.dssim);
    if (rq->heatmap)
        fprintf(f, "\nheatmap %s: %s, colour map %s, full scale %.6g (%s); black outside the mask%s\n", rq->heatmap,
                heatmap_metric_name(rq), IMAGE_COMPARISON_COLOUR_MAP, r->heatmap_vmax, r->heatmap_vmax_rule,
                rq->colour_bar ? "; the colour bar below it runs from 0 (left) to the full scale (right)" : "");
}

static void add_heatmap(cJSON *root, const image_comparison_request *rq, const image_comparison *r)
{
    cJSON *h = cJSON_AddObjectToObject(root, "heatmap");
    cJSON_AddStringToObject(h, "path", rq->heatmap);
    cJSON_AddStringToObject(h, "metric", rq->heatmap_dssim ? "dssim" : "abs");
    cJSON_AddStringToObject(h, "colour_map", IMAGE_COMPARISON_COLOUR_MAP);
    cJSON_AddNumberToObject(h, "vmax", r->heatmap_vmax);
    cJSON_AddStringToObject(h, "vmax_is", r->heatmap_vmax_rule);
    cJSON_AddBoolToObject(h, "colour_bar", rq->colour_bar);
}

char *image_comparison_json(const image_comparison_request *rq, const image_comparison *r)
{
    const metrics_pair_figures *x = &r->figures;
    cJSON *root = cJSON_CreateObject();
    if (!root)
        return NULL;
    cJSON_AddStringToObject(root, "a", rq->a);
    cJSON_AddStringToObject(root, "b", rq->b);
    cJSON_AddStringToObject(root, "channel", r->channel);
    cJSON_AddNumberToObject(root, "width", r->width);
    cJSON_AddNumberToObject(root, "height", r->height);
    cJSON_AddNumberToObject(root, "pixels", (double)x->error.pixels);
    cJSON_AddNumberToObject(root, "ssim_window_centres", (double)x->ssim.centres);
    cJSON_AddNumberToObject(root, "ssim", x->ssim.ssim);
    cJSON_AddNumberToObject(root, "dssim", x->ssim.dssim);
    cJSON_AddNumberToObject(root, "flip", x->flip.mean);
    cJSON_AddBoolToObject(root, "flip_hdr", x->flip.hdr);
    cJSON_AddNumberToObject(root, "rmse", x->error.rmse);
    cJSON_AddNumberToObject(root, "mean_abs", x->error.mean_abs);
    cJSON_AddNumberToObject(root, "max_abs", x->error.max_abs);
    const int at[2] = {x->error.max_x, x->error.max_y};
    cJSON_AddItemToObject(root, "max_abs_pixel", cJSON_CreateIntArray(at, 2));
    cJSON_AddNumberToObject(root, "mean_a", x->error.mean_a);
    cJSON_AddNumberToObject(root, "mean_b", x->error.mean_b);
    if (x->has_floor_a)
        cJSON_AddNumberToObject(root, "noise_floor_dssim", x->floor_a.dssim);
    if (x->has_floor_b)
        cJSON_AddNumberToObject(root, "noise_floor_dssim_b", x->floor_b.dssim);
    if (rq->heatmap)
        add_heatmap(root, rq, r);
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    return text;
}
