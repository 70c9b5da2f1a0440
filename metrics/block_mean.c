/* Block means over 8x8 tiles; see block_mean.h. */
#include "metrics/block_mean.h"

#include <math.h>

#include "metrics/image_error.h"

/* The mean of values over the block at (bx, by) inside the mask; 0 pixels: -1. */
static int one_block(const float *values, const float *mask, int width, int height, int bx, int by, int block,
                     double *mean)
{
    double sum = 0.0;
    long count = 0;
    for (int y = by; y < by + block && y < height; ++y)
        for (int x = bx; x < bx + block && x < width; ++x) {
            long i = (long)y * width + x;
            if (metrics_in_mask(mask, (size_t)i)) {
                sum += values[i];
                ++count;
            }
        }
    if (count == 0)
        return -1;
    *mean = sum / (double)count;
    return 0;
}

void block_mean_add(block_mean *m, const float *values, const float *mask, int width, int height, int block)
{
    for (int by = 0; by < height; by += block)
        for (int bx = 0; bx < width; bx += block) {
            double mean;
            if (one_block(values, mask, width, height, bx, by, block, &mean) != 0)
                continue;
            ++m->blocks;
            m->sum += mean;
            m->sum_squares += mean * mean;
        }
}

double block_mean_value(const block_mean *m) { return m->blocks > 0 ? m->sum / (double)m->blocks : 0.0; }

double block_mean_se(const block_mean *m)
{
    if (m->blocks < 2)
        return 0.0;
    double mean = block_mean_value(m), n = (double)m->blocks;
    double variance = (m->sum_squares - n * mean * mean) / (n - 1.0);
    return sqrt(fmax(variance, 0.0) / n);
}

void block_mean_rmse(const block_mean *squared_error, double *rmse, double *se)
{
    double mse = block_mean_value(squared_error);
    *rmse = sqrt(fmax(mse, 0.0));
    *se = mse > 0.0 ? block_mean_se(squared_error) / (2.0 * *rmse) : 0.0;
}
