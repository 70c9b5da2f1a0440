/* The mean of a per-pixel quantity (a squared error, a paired difference of
 * squared errors) with a standard error that respects spatial correlation.
 * Neighbouring pixels of a rendered image are not independent (a denoiser
 * averages 4x4 windows, a pattern repeats every 4 pixels), so the pixels'
 * own spread would understate the uncertainty: the image is cut into b x b
 * blocks, each block's mean over its pixels inside the mask is one
 * observation, and
 *     mean = (1/B) sum_k m_k,   s.e. = sqrt( sum_k (m_k - mean)^2 / (B (B - 1)) )
 * over the B blocks with at least one pixel inside the mask (blocks weigh
 * equally). Blocks of several images (scenes) pool into one accumulator. */
#ifndef GTLAB_METRICS_BLOCK_MEAN_H
#define GTLAB_METRICS_BLOCK_MEAN_H

enum { BLOCK_MEAN_SIZE = 8 }; /* 8 x 8 pixels: twice the 4x4 pattern and denoiser */

typedef struct {
    long blocks;
    double sum, sum_squares; /* of the block means */
} block_mean;

/* Adds the blocks of values (width*height, row-major) inside mask (NULL:
 * every pixel; metrics_in_mask) to m. */
void block_mean_add(block_mean *m, const float *values, const float *mask, int width, int height, int block);
double block_mean_value(const block_mean *m);
/* The standard error of block_mean_value; 0 with fewer than 2 blocks. */
double block_mean_se(const block_mean *m);
/* sqrt of a mean squared error and its standard error by the delta method,
 * se / (2 sqrt(mse)). */
void block_mean_rmse(const block_mean *squared_error, double *rmse, double *se);

#endif
