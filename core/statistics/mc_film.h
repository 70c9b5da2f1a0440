/* Per-pixel Monte Carlo accumulation with exact, order-independent sums.
 *
 * Means. Every sample value v of a quantity is rounded onto a fixed grid of
 * spacing 2^(E-24) (E = the quantity's scale exponent, |v| <= 2^E expected).
 * Sums of grid values are integers in grid units, which a double holds
 * exactly below 2^53: the sums do not depend on the order of addition. So a
 * render split into blocks of samples (--sample-offset) and merged gives the
 * same bits as the whole render, and a long render can be resumed. The
 * rounding moves a mean by at most 2^(E-25), far below Monte Carlo noise
 * where values are near 2^E (it is absolute, not relative to the pixel).
 *
 * Standard errors. The samples and their squares are also summed at each
 * pixel's own scale (core/statistics/moment_sums.h: exact, order-independent, every
 * sample rounded by at most 2^-48 of the pixel's largest), and the variance
 * comes from those sums, within 2^-45 of the square of the pixel's largest
 * sample: a dim pixel's standard error does not depend on how bright the
 * rest of the image is. (The grid served both until issue 23: squares below
 * the grid of squares 2^(2E-24) vanished, and dim pixels reported 0.)
 *
 * Every sum is a 64-bit integer (grid units, or the moment sums' limbs):
 * exact for up to MC_FILM_MAX_COUNT = 2^32 samples per pixel, in memory and
 * in the EXR file, where each is kept as two floats (hi + lo, 48 bits) and,
 * when some pixel needs more, a third ("lo2", 72 bits). A grid sum that a
 * sample's value could not keep exact (NaN, infinite, or beyond 2^53 grid
 * steps) is unknown, MC_GRID_SUM_UNKNOWN, and so stays through every merge.
 *
 * Samples are also summed separately over even sample indices, so the two
 * halves of a render (even and odd samples) give the reference's noise floor.
 */
#ifndef GTLAB_CORE_STATISTICS_MC_FILM_H
#define GTLAB_CORE_STATISTICS_MC_FILM_H

#include <stdint.h>

#include "core/error.h"
#include "core/image.h"
#include "core/statistics/moment_sums.h"

#define MC_FILM_MAX_QUANTITIES 64
/* The most samples a pixel may hold: 2^32. A sample adds at most 2^23 to a
 * moment limb and at most 2^25 units to a grid sum in the usual case, so
 * 2^32 samples stay within 2^63 (int64_t); counts are 64-bit integers, and
 * in a file hi + lo floats (exact to 2^48). A merge beyond is refused rather
 * than rounded. */
#define MC_FILM_MAX_COUNT 4294967296.0
/* A grid sum that is not a whole number of units below 2^63: see above. */
#define MC_GRID_SUM_UNKNOWN INT64_MIN

typedef struct {
    char name[IMAGE_NAME_MAX]; /* channel name of the mean, e.g. CH_AO (core/reference_schema.h) */
    int scale_exponent;        /* E: samples expected within [-2^E, 2^E] */
} mc_quantity;

#define MC_FILM_MAX_NORMALIZED 4

/* A quantity's rounding grid for its mean: 2^(E-24). */
typedef struct {
    double step, inverse_step;
} mc_grid;

/* v in units of the grid, rounded to the nearest (ties to even); unknown
 * when not finite or beyond 2^53 units. */
int64_t mc_grid_units(double v, const mc_grid *g);
/* a + b, unknown when either is or the sum would leave the int64 range. */
int64_t mc_grid_sum_add(int64_t a, int64_t b);
/* The value of a grid sum, NaN when unknown. */
double mc_grid_sum_value(int64_t units, const mc_grid *g);

typedef struct {
    int width, height;
    int quantity_count;
    mc_quantity *quantities;
    mc_grid grids[MC_FILM_MAX_QUANTITIES];
    int64_t *sum, *sum_even;         /* in grid units, [quantity * pixels + pixel] */
    moment_sums *moments;            /* at the pixel's scale, [quantity * pixels + pixel] */
    uint64_t *count, *count_even;    /* [pixel] */
    /* 0 for a film read from a file written before issue 23 (its squares
     * were summed on the grid): means only, no standard errors, no merge. */
    int has_moments;
    /* Layers whose .X .Y .Z means are written normalised (bent normals). */
    int normalized_count;
    char normalized[MC_FILM_MAX_NORMALIZED][IMAGE_NAME_MAX];
} mc_film;

int mc_film_init(mc_film *film, int width, int height, const mc_quantity *quantities, int quantity_count);
void mc_film_free(mc_film *film);
/* Declares that layer.X/.Y/.Z are a vector written normalised. */
int mc_film_normalize_layer(mc_film *film, const char *layer);

/* One pixel's sums while it is being sampled, kept together (and on the
 * stack) rather than scattered over the film's planes. */
typedef struct {
    int64_t sum[MC_FILM_MAX_QUANTITIES], sum_even[MC_FILM_MAX_QUANTITIES]; /* grid units */
    moment_sums moments[MC_FILM_MAX_QUANTITIES];
    uint64_t count, count_even;
} mc_pixel;

void mc_pixel_clear(mc_pixel *acc, const mc_film *film);
/* Adds one sample (values[q] for every quantity) with its sequence index. */
void mc_pixel_add_sample(mc_pixel *acc, const mc_film *film, uint32_t sample_index, const float *values);
/* Adds samples first_index .. first_index + count - 1 at once, quantity q
 * of sample k at values[q * stride + k] (quantity-major, so each
 * quantity's run is contiguous). The same sums as adding them one by one
 * (sums of grid values are exact in any order). */
void mc_pixel_add_samples(mc_pixel *acc, const mc_film *film, uint32_t first_index, int count, const float *values,
                          int stride);
/* Standard error of quantity q's mean so far (as mc_film_stderr). */
double mc_pixel_stderr(const mc_pixel *acc, int quantity);
/* Adds a pixel's sums into the film. Exact, like every sum here. */
void mc_film_add_pixel(mc_film *film, int pixel, const mc_pixel *acc);

/* Adds one sample straight into the film (mc_pixel_add_sample + mc_film_add_pixel). */
void mc_film_add_sample(mc_film *film, int pixel, uint32_t sample_index, const float *values);

/* The mean of quantity q's samples at the pixel, from its moment sums:
 * within 2^-48 P of the exact mean, P the pixel's own largest |sample|,
 * however dim it is next to the image's brightest (the grid sums, relative to the brightest,
 * for a film without moments). 0 before any sample. */
double mc_film_mean(const mc_film *film, int quantity, int pixel);
/* Standard error of the mean, sqrt(s^2 / n) with the unbiased sample
 * variance s^2 of the pixel's moment sums; +infinity with fewer than 2
 * samples, NaN when unknown (a NaN sample, or a film without moments). */
double mc_film_stderr(const mc_film *film, int quantity, int pixel);

/* Adds the channels "Q", "Q.stderr", the grid sums "Q.sum", "Q.sum_lo",
 * "Q.sumeven", "Q.sumeven_lo", and the moment sums "Q.peak" and
 * "Q.m<moment>_<limb>[lo]" (CH_SUFFIX_LIMB_FMT) of every quantity, and
 * CH_SPP, CH_SPP_EVEN with their lo parts; a sum's third part ("<lo>2",
 * CH_SUFFIX_THIRD_PART) only when some pixel needs it; and the attributes ATTR_NORMALIZED and ATTR_EXPONENTS,
 * so a film read back accumulates on the same grid. Pixels without a sample
 * (the background of a quantity that samples surfaces only) get 0 in Q and
 * Q.stderr. */
int mc_film_write_channels(const mc_film *film, image *img);
/* Means of one half of the samples only (half 0: even indices, 1: odd) into
 * channels named as the quantities. */
int mc_film_write_half_means(const mc_film *film, int half, image *img);

/* Rebuilds a film from the accumulator channels of an image written by
 * mc_film_write_channels. `what` names the file for errors. A file written
 * before issue 23 (grid sums of squares "Q.sumsq", no moment sums) is read
 * with has_moments = 0: its means and halves are right, its sums of squares
 * are not kept. */
int mc_film_read_channels(const image *img, const char *what, mc_film *film, gt_error *e);
/* 0 when the film has moment sums, else -1 with e naming `what`: a file
 * written before issue 23, whose standard errors cannot be rebuilt. */
int mc_film_check_moments(const mc_film *film, const char *what, gt_error *e);
/* dst += src (same size and quantities, matched by name: a film read from
 * a file lists them in the file's channel order, a rendered one in the
 * integrator's). Exact. Refuses films without moment sums
 * (mc_film_check_moments), naming the file. */
int mc_film_merge(mc_film *dst, const mc_film *src, const char *what, gt_error *e);
/* Empties the pixels of rows [first_row, end_row): sums, moments and
 * counts back to the state mc_film_init leaves (an interrupted block of
 * rows, taken back). */
void mc_film_clear_rows(mc_film *film, int first_row, int end_row);

#endif
