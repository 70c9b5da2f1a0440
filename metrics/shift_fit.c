/* Least-squares shift with block-clustered standard errors; see shift_fit.h. */
#include "metrics/shift_fit.h"

#include <math.h>

#include "metrics/image_error.h"

static int usable(const float *mask, int width, int height, int x, int y)
{
    if (x < 1 || y < 1 || x >= width - 1 || y >= height - 1)
        return 0;
    long i = (long)y * width + x;
    return metrics_in_mask(mask, (size_t)i) && metrics_in_mask(mask, (size_t)(i - 1)) &&
           metrics_in_mask(mask, (size_t)(i + 1)) && metrics_in_mask(mask, (size_t)(i - width)) &&
           metrics_in_mask(mask, (size_t)(i + width));
}

/* One block's M_k and v_k; its pixel count (0: none usable). */
static int block_moments(const float *a, const float *b, const float *mask, int width, int height, int bx, int by,
                         int block, double m[2][2], double v[2])
{
    int count = 0;
    m[0][0] = m[0][1] = m[1][0] = m[1][1] = v[0] = v[1] = 0.0;
    for (int y = by; y < by + block && y < height; ++y)
        for (int x = bx; x < bx + block && x < width; ++x) {
            if (!usable(mask, width, height, x, y))
                continue;
            long i = (long)y * width + x;
            double g[2] = {0.5 * (b[i + 1] - b[i - 1]), 0.5 * (b[i + width] - b[i - width])}, r = a[i] - b[i];
            for (int p = 0; p < 2; ++p) {
                v[p] += g[p] * r;
                for (int q = 0; q < 2; ++q)
                    m[p][q] += g[p] * g[q];
            }
            ++count;
        }
    return count;
}

static void add_block(shift_fit *s, double m[2][2], const double v[2])
{
    ++s->blocks;
    for (int i = 0; i < 2; ++i) {
        s->v[i] += v[i];
        for (int j = 0; j < 2; ++j) {
            s->m[i][j] += m[i][j];
            s->vv[i][j] += v[i] * v[j];
            for (int k = 0; k < 2; ++k) {
                s->vm[i][j][k] += v[i] * m[j][k];
                for (int l = 0; l < 2; ++l)
                    s->mm[i][j][k][l] += m[i][j] * m[k][l];
            }
        }
    }
}

void shift_fit_add(shift_fit *s, const float *a, const float *b, const float *mask, int width, int height, int block)
{
    for (int by = 0; by < height; by += block)
        for (int bx = 0; bx < width; bx += block) {
            double m[2][2], v[2];
            int count = block_moments(a, b, mask, width, height, bx, by, block, m, v);
            if (count > 0) {
                add_block(s, m, v);
                s->pixels += count;
            }
        }
}

/* S = sum_k (v_k - M_k d)(v_k - M_k d)^T from the moments. */
static void scores(const shift_fit *s, const double d[2], double out[2][2])
{
    for (int i = 0; i < 2; ++i)
        for (int l = 0; l < 2; ++l) {
            double x = s->vv[i][l];
            for (int k = 0; k < 2; ++k)
                x -= (s->vm[i][l][k] + s->vm[l][i][k]) * d[k];
            for (int j = 0; j < 2; ++j)
                for (int k = 0; k < 2; ++k)
                    x += s->mm[i][j][l][k] * d[j] * d[k];
            out[i][l] = x;
        }
}

void shift_fit_solve(const shift_fit *s, double d[2], double se[2])
{
    double det = s->m[0][0] * s->m[1][1] - s->m[0][1] * s->m[1][0];
    d[0] = d[1] = se[0] = se[1] = 0.0;
    if (!(fabs(det) > 0.0))
        return;
    double inv[2][2] = {{s->m[1][1] / det, -s->m[0][1] / det}, {-s->m[1][0] / det, s->m[0][0] / det}};
    d[0] = inv[0][0] * s->v[0] + inv[0][1] * s->v[1];
    d[1] = inv[1][0] * s->v[0] + inv[1][1] * s->v[1];
    double sc[2][2];
    scores(s, d, sc);
    for (int p = 0; p < 2; ++p) {
        double var = 0.0;
        for (int i = 0; i < 2; ++i)
            for (int l = 0; l < 2; ++l)
                var += inv[p][i] * sc[i][l] * inv[l][p];
        se[p] = sqrt(fmax(var, 0.0));
    }
}

double shift_fit_rms_gradient(const shift_fit *s, const double u[2])
{
    if (s->pixels <= 0)
        return 0.0;
    double q = 0.0;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            q += u[i] * s->m[i][j] * u[j];
    return sqrt(fmax(q, 0.0) / (double)s->pixels);
}
