/* The GTAO talk's spatial and temporal denoisers (seeds/001, "Spatial
 * Denoiser Details", "Temporal Denoiser Details") and the frame loop that
 * applies them; see gtao_denoiser.h. */
#include "gtao/gtao_denoiser.h"

#include <math.h>
#include <stdlib.h>

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

int gtao_denoised_frames(const ss_gbuffer *g, gtao_frame_fn frame_fn, const void *params, int frames, int denoise,
                         int planes, float *const *out)
{
    size_t n = (size_t)g->width * (size_t)g->height;
    float *raw = malloc(sizeof *raw * n * (size_t)planes), *filtered = malloc(sizeof *filtered * n);
    float *raw_planes[4];
    if (!raw || !filtered || planes > 4) {
        free(raw);
        free(filtered);
        return -1;
    }
    for (int c = 0; c < planes; ++c)
        raw_planes[c] = raw + (size_t)c * n;
    for (int f = 0; f < (frames > 0 ? frames : 1); ++f) {
        frame_fn(g, params, f, raw_planes);
        for (int c = 0; c < planes; ++c) {
            const float *plane = raw_planes[c];
            if (denoise) {
                gtao_spatial_denoise(g, f, plane, filtered);
                plane = filtered;
            }
            gtao_temporal_accumulate(plane, f, n, out[c]);
        }
    }
    free(raw);
    free(filtered);
    return 0;
}
