/* The colour-grading LUT study (color_grading_study.h). */
#include "color_grading/color_grading_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/files/image_io.h"
#include "core/vec3.h" /* M_PI */
#include "metrics/color_difference.h"
#include "core/sampling/pixel_filter.h"
#include "core/optics/srgb.h"
#include "raytracer/shaded_frame.h"
#include "hdr_precision/hdr_precision.h"

enum { CHART_PIXELS = GRADING_CHART_W * GRADING_CHART_H, CUBE_SAMPLES = 32768 };

typedef struct {
    color_lut_space space;
    color_lut_interpolation interpolation;
    int eight_bit;
} lut_variant;

static const lut_variant variants[GRADING_VARIANTS] = {
    {COLOR_LUT_SRGB, COLOR_LUT_TRILINEAR, 0}, {COLOR_LUT_SRGB, COLOR_LUT_TETRAHEDRAL, 0},
    {COLOR_LUT_LINEAR, COLOR_LUT_TRILINEAR, 0}, {COLOR_LUT_LINEAR, COLOR_LUT_TETRAHEDRAL, 0},
    {COLOR_LUT_SRGB, COLOR_LUT_TRILINEAR, 1}, {COLOR_LUT_LOG, COLOR_LUT_TETRAHEDRAL, 0}};
static const int sizes[GRADING_SIZES] = {16, 32, 64};

/* Fully saturated hue h (degrees) scaled to value 1, mixed with white by (1 - s). */
static void hue_colour(double h, double s, double rgb[3])
{
    for (int c = 0; c < 3; ++c) {
        double k = fmod(h / 60.0 + (c == 0 ? 5.0 : c == 1 ? 3.0 : 1.0), 6.0);
        double v = 1.0 - fmax(0.0, fmin(1.0, fmin(k, 4.0 - k)));
        rgb[c] = 1.0 - s * v;
    }
}

/* The chart's scene-linear colour at pixel (x, y): four bands (see the header). */
static void chart_scene(int x, int y, double rgb[3])
{
    static const double skin[6][3] = {{0.45, 0.29, 0.22}, {0.62, 0.43, 0.33}, {0.36, 0.21, 0.15},
                                      {0.76, 0.58, 0.47}, {0.25, 0.15, 0.11}, {0.55, 0.36, 0.26}};
    double u = (x + 0.5) / GRADING_CHART_W, exposure = 1.0;
    if (y < 48) {
        hue_colour(360.0 * u, 1.0, rgb);
        exposure = 0.18 * pow(2.0, -3.0 + 7.0 * y / 47.0);
    } else if (y < 80) {
        hue_colour(360.0 * u, (y - 48) / 31.0, rgb);
        exposure = 0.36;
    } else if (y < 104) {
        int patch = (int)(u * 6.0);
        memcpy(rgb, skin[patch], sizeof skin[patch]);
        exposure = pow(2.0, -2.0 + 4.0 * (u * 6.0 - patch));
    } else {
        rgb[0] = rgb[1] = rgb[2] = 1.0;
        exposure = pow(2.0, -8.0 + 12.0 * u);
    }
    for (int c = 0; c < 3; ++c)
        rgb[c] *= exposure;
}

/* Display values: the filmic curve's output (already display-encoded). */
static void make_chart(double *rgb)
{
    for (int y = 0; y < GRADING_CHART_H; ++y)
        for (int x = 0; x < GRADING_CHART_W; ++x) {
            double *p = rgb + 3 * (y * GRADING_CHART_W + x), scene[3];
            chart_scene(x, y, scene);
            for (int c = 0; c < 3; ++c)
                p[c] = fmin(1.0, tonemap_filmic_display(scene[c], 1.0));
        }
}

/* The render's display values from its radiance samples. */
static void render_frame(const embree_scene *es, const camera *cam, int threads, float *radiance, float *xy,
                         float *pixels, double *rgb)
{
    frame_lighting light = frame_lighting_default();
    shaded_frame_render_supersampled(es, cam, &light, 2, 5u, threads, radiance, xy);
    pixel_filter_resolve(PIXEL_FILTER_BOX, radiance, xy, GRADING_CHART_W, GRADING_CHART_H, 2, threads, pixels);
    for (size_t k = 0; k < 3 * (size_t)CHART_PIXELS; ++k)
        rgb[k] = fmin(1.0, tonemap_filmic_display(pixels[k], 1.0));
}

/* The render: builtin:cornell, 2 x 2 stratified samples per pixel, box
 * filter, the filmic curve to display values. */
static int make_render(double *rgb, int threads, gt_error *e)
{
    size_t samples = (size_t)CHART_PIXELS * 4;
    float *radiance = malloc(3 * samples * sizeof(float)), *xy = malloc(2 * samples * sizeof(float));
    float *pixels = malloc(3 * (size_t)CHART_PIXELS * sizeof(float));
    scene s;
    camera cam;
    embree_scene es;
    int rc = radiance && xy && pixels ? 0 : gt_error_set(e, "colour grading", "out of memory");
    if (rc == 0 && (rc = study_load_view("builtin:cornell", GRADING_CHART_W, GRADING_CHART_H, &s, &cam, e)) == 0) {
        if ((rc = embree_scene_build(&s, &es, e)) == 0) {
            render_frame(&es, &cam, threads, radiance, xy, pixels, rgb);
            embree_scene_release(&es);
        }
        scene_free(&s);
    }
    free(radiance), free(xy), free(pixels);
    return rc;
}

static void make_cube(double *rgb)
{
    unsigned long long s = 0x5EEDull;
    for (int i = 0; i < 3 * CUBE_SAMPLES; ++i) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        rgb[i] = (double)(s >> 11) * 0x1.0p-53;
    }
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Max and 99th percentile (nearest rank) of n values; sorts them. */
static void max_p99(double *v, int n, double *max, double *p99)
{
    qsort(v, (size_t)n, sizeof *v, compare_double);
    *max = v[n - 1];
    *p99 = v[(int)ceil(0.99 * n) - 1];
}

/* Work arrays of one image. */
typedef struct {
    const double *in;    /* display colours */
    double *exact, *got; /* the grade, the LUT */
    double *lsb, *de;
    int n;
} image_work;

static void quantise_8bit(color_lut *lut)
{
    size_t n = 3 * (size_t)lut->size * lut->size * lut->size;
    for (size_t i = 0; i < n; ++i)
        lut->rgb[i] = (float)(round(lut->rgb[i] * 255.0) / 255.0);
}

static void score_image(const color_lut *lut, color_lut_interpolation interpolation, const color_difference *cd,
                        image_work *w, grading_error *out)
{
    for (int i = 0; i < w->n; ++i) {
        double *g = w->got + 3 * i, *x = w->exact + 3 * i;
        color_lut_lookup(lut, interpolation, w->in + 3 * i, g);
        for (int c = 0; c < 3; ++c)
            g[c] = fmin(1.0, fmax(0.0, g[c]));
        w->lsb[i] = 255.0 * fmax(fabs(g[0] - x[0]), fmax(fabs(g[1] - x[1]), fabs(g[2] - x[2])));
    }
    color_difference_ciede2000(cd, w->exact, w->got, (size_t)w->n, w->de);
    max_p99(w->lsb, w->n, &out->max_lsb, &out->p99_lsb);
    max_p99(w->de, w->n, &out->max_de, &out->p99_de);
}

static void grade_image(const color_grade *g, image_work *w)
{
    for (int i = 0; i < w->n; ++i)
        color_grade_apply(g, w->in + 3 * i, w->exact + 3 * i);
}

static int score_grade(const color_grade *g, image_work w[GRADING_IMAGES], const color_difference *cd,
                       grading_result *out, gt_error *e)
{
    for (int i = 0; i < GRADING_IMAGES; ++i)
        grade_image(g, &w[i]);
    for (int s = 0; s < GRADING_SIZES; ++s)
        for (int v = 0; v < GRADING_VARIANTS; ++v) {
            color_lut lut;
            if (color_lut_bake(&lut, sizes[s], variants[v].space, g) != 0)
                return gt_error_set(e, "colour grading", "out of memory");
            if (variants[v].eight_bit)
                quantise_8bit(&lut);
            grading_row *row = &out->rows[out->row_count++];
            *row = (grading_row){.grade = g->name,
                                 .size = sizes[s],
                                 .space = color_lut_space_name(variants[v].space),
                                 .interpolation = color_lut_interpolation_name(variants[v].interpolation),
                                 .storage = variants[v].eight_bit ? "8-bit" : "float"};
            for (int i = 0; i < GRADING_IMAGES; ++i)
                score_image(&lut, variants[v].interpolation, cd, &w[i], &row->image[i]);
            row->perceptual = row->image[0].max_de < 1.0 && row->image[2].max_de < 1.0;
            row->within_1lsb = row->image[0].p99_lsb <= 1.0;
            color_lut_free(&lut);
        }
    return 0;
}

/* The chart and the chart graded exactly, as previews (display values are
 * decoded to linear: the writer encodes them back to sRGB). */
static int write_chart(const char *dir, const char *name, const double *rgb, gt_error *e)
{
    float *planes[3];
    int rc = 0;
    for (int c = 0; c < 3; ++c)
        rc |= (planes[c] = malloc(sizeof(float) * CHART_PIXELS)) == NULL;
    for (int i = 0; i < CHART_PIXELS && rc == 0; ++i)
        for (int c = 0; c < 3; ++c)
            planes[c][i] = (float)srgb_to_linear(rgb[3 * i + c]);
    char path[4096 + 64];
    snprintf(path, sizeof path, "%s/%s.png", dir, name);
    rc = rc ? gt_error_set(e, path, "out of memory")
            : image_write_preview(path, (const float *const *)planes, 3, GRADING_CHART_W, GRADING_CHART_H, 1.0f, e);
    for (int c = 0; c < 3; ++c)
        free(planes[c]);
    return rc;
}

static int alloc_work(image_work *w, const double *in, int n)
{
    w->in = in;
    w->n = n;
    w->exact = malloc(sizeof(double) * 3 * (size_t)n);
    w->got = malloc(sizeof(double) * 3 * (size_t)n);
    w->lsb = malloc(sizeof(double) * (size_t)n);
    w->de = malloc(sizeof(double) * (size_t)n);
    return w->exact && w->got && w->lsb && w->de ? 0 : -1;
}

static void free_work(image_work *w)
{
    free(w->exact), free(w->got), free(w->lsb), free(w->de);
}

/* Every grade's rows; the graded charts of the looks beside the chart. */
static int run_grades(const char *dir, image_work w[GRADING_IMAGES], const color_difference *cd, grading_result *out,
                      gt_error *e)
{
    int rc = write_chart(dir, "chart", w[0].in, e);
    if (rc == 0)
        rc = write_chart(dir, "render", w[2].in, e);
    for (int g = 0; g < COLOR_GRADE_PRESETS && rc == 0; ++g) {
        rc = score_grade(color_grade_preset(g), w, cd, out, e);
        char name[64];
        snprintf(name, sizeof name, "chart_grade%d", g);
        if (rc == 0 && g > 0)
            rc = write_chart(dir, name, w[0].exact, e);
    }
    return rc;
}

int color_grading_study(const study_context *ctx, grading_result *out, gt_error *e)
{
    char dir[4096];
    memset(out, 0, sizeof *out);
    out->cube_samples = CUBE_SAMPLES;
    if (study_make_dir(ctx, GRADING_DIR, dir, sizeof dir, e) != 0)
        return -1;
    color_difference *cd = color_difference_create(e);
    double *chart = malloc(sizeof(double) * 3 * CHART_PIXELS), *cube = malloc(sizeof(double) * 3 * CUBE_SAMPLES);
    double *render = malloc(sizeof(double) * 3 * CHART_PIXELS);
    image_work w[GRADING_IMAGES] = {{0}};
    int rc = cd && chart && cube && render ? 0 : (cd ? gt_error_set(e, dir, "out of memory") : -1);
    if (rc == 0) {
        make_chart(chart), make_cube(cube);
        rc = make_render(render, ctx->threads, e);
    }
    if (rc == 0 && (alloc_work(&w[0], chart, CHART_PIXELS) | alloc_work(&w[1], cube, CUBE_SAMPLES) |
                    alloc_work(&w[2], render, CHART_PIXELS)))
        rc = gt_error_set(e, dir, "out of memory");
    if (rc == 0)
        rc = run_grades(dir, w, cd, out, e);
    free_work(&w[0]), free_work(&w[1]), free_work(&w[2]);
    free(chart), free(cube), free(render);
    color_difference_free(cd);
    return rc;
}
