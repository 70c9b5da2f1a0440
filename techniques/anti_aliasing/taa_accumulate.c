/* Conventional accumulating TAA (taa_accumulate.h). */
#include "anti_aliasing/taa_accumulate.h"

#include <math.h>
#include <stddef.h>

#include "anti_aliasing/taa_sampling.h"

taa_accumulate_settings taa_accumulate_default_settings(void)
{
    taa_accumulate_settings s = {0.1};
    return s;
}

static void accumulate_pixel(const taa_accumulate_settings *s, const float *current, const float *motion,
                             const float *history, int width, int height, int i, int j, float *out)
{
    size_t k = (size_t)j * width + i;
    double x = i + 0.5 + motion[2 * k], y = j + 0.5 + motion[2 * k + 1];
    if (!history || !taa_inside(width, height, x, y)) {
        for (int c = 0; c < 3; ++c)
            out[3 * k + c] = current[3 * k + c];
        return;
    }
    float h[3], lo[3], hi[3];
    taa_bilinear(history, width, height, x, y, h);
    taa_neighbourhood_box(current, width, height, i, j, lo, hi);
    for (int c = 0; c < 3; ++c)
        out[3 * k + c] = (float)((1.0 - s->alpha) * fminf(fmaxf(h[c], lo[c]), hi[c]) + s->alpha * current[3 * k + c]);
}

void taa_accumulate(const taa_accumulate_settings *s, const float *current, const float *motion, const float *history,
                    int width, int height, int threads, float *out)
{
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            accumulate_pixel(s, current, motion, history, width, height, i, j, out);
}
