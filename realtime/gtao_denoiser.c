/* The GTAO talk's spatial and temporal denoisers (seeds/001, "Spatial
 * Denoiser Details", "Temporal Denoiser Details"); see gtao_denoiser.h. */
#include "realtime/gtao_denoiser.h"

#include <math.h>

/* The one-sided depth difference of smaller magnitude: at a silhouette it
 * takes the side on the same surface. */
static float depth_slope(const ss_gbuffer *g, int x, int y, int ox, int oy)
{
    float zc = g->depth[(long)y * g->width + x];
    float lo = ss_covered(g, x - ox, y - oy) ? zc - g->depth[(long)(y - oy) * g->width + x - ox] : INFINITY;
    float hi = ss_covered(g, x + ox, y + oy) ? g->depth[(long)(y + oy) * g->width + x + ox] - zc : INFINITY;
    float s = fabsf(lo) < fabsf(hi) ? lo : hi;
    return isfinite(s) ? s : 0.0f;
}

static float filter_pixel(const ss_gbuffer *g, int shift, const float *in, int x, int y)
{
    float zc = g->depth[(long)y * g->width + x];
    float sx = depth_slope(g, x, y, 1, 0), sy = depth_slope(g, x, y, 0, 1);
    float sum = 0.0f, weight = 0.0f;
    for (int oy = -1 - shift; oy <= 2 - shift; ++oy)
        for (int ox = -1 - shift; ox <= 2 - shift; ++ox) {
            if (!ss_covered(g, x + ox, y + oy))
                continue;
            long j = (long)(y + oy) * g->width + x + ox;
            float plane = zc + sx * (float)ox + sy * (float)oy;
            float w = ss_minf(ss_maxf(1.0f - fabsf(g->depth[j] - plane) / (0.1f * zc), 0.0f), 1.0f);
            sum += w * in[j];
            weight += w;
        }
    return weight > 0.0f ? sum / weight : in[(long)y * g->width + x];
}

void gtao_spatial_denoise(const ss_gbuffer *g, int frame, const float *in, float *out)
{
    int shift = frame & 1; /* odd frames: window moved top/left */
#pragma omp parallel for schedule(static)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            out[i] = g->mask[i] != 0.0f ? filter_pixel(g, shift, in, x, y) : 0.0f;
        }
}

void gtao_temporal_accumulate(const float *in, int frame, size_t count, float *out)
{
    float keep = (float)frame / (float)(frame + 1), take = 1.0f / (float)(frame + 1);
    for (size_t i = 0; i < count; ++i)
        out[i] = frame == 0 ? in[i] : keep * out[i] + take * in[i];
}

void gtao_normalize_directions(const ss_gbuffer *g, float *const *d)
{
    size_t n = (size_t)g->width * (size_t)g->height;
    for (size_t i = 0; i < n; ++i) {
        float len = sqrtf(d[0][i] * d[0][i] + d[1][i] * d[1][i] + d[2][i] * d[2][i]);
        float s = g->mask[i] != 0.0f && len > 0.0f ? 1.0f / len : 0.0f;
        for (int c = 0; c < 3; ++c)
            d[c][i] *= s;
    }
}
