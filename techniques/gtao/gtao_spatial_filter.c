/* The bilateral filter's variants and the neighbourhood clamp; see
 * gtao_spatial_filter.h. */
#include "gtao/gtao_spatial_filter.h"

#include <math.h>

#include "gtao/gtao_denoiser.h"

const char *const gtao_depth_test_names[GTAO_DEPTH_TESTS] = {"linear depth + 1st derivatives",
                                                             "linear depth + 1st + 2nd derivatives",
                                                             "log depth + 1st derivatives"};
const gtao_spatial_options gtao_spatial_default = {GTAO_DEPTH_LINEAR_D1, 1, 0.1f};

static float depth_of(const ss_gbuffer *g, int x, int y, int log_space)
{
    float z = g->depth[(long)y * g->width + x];
    return log_space ? logf(z) : z;
}

/* First and second differences along (ox, oy): the first on the side of
 * the smaller first difference (gtao_denoiser.c's depth_slope); side: +1
 * forward, -1 backward. The second is the central one, hi - lo, taken only
 * where the two sides continue each other (a slope, "for slopes": they
 * differ by less than the depth test's threshold, or have one sign and
 * differ by less than half the steeper), 0 at a crease or an edge, whose
 * kink is not a curvature of the surface. */
typedef struct {
    float d1, d2;
    int side;
} one_sided_differences;

static one_sided_differences one_sided(const ss_gbuffer *g, int x, int y, int ox, int oy, int log_space,
                                       float crease)
{
    float zc = depth_of(g, x, y, log_space);
    float lo = ss_covered(g, x - ox, y - oy) ? zc - depth_of(g, x - ox, y - oy, log_space) : INFINITY;
    float hi = ss_covered(g, x + ox, y + oy) ? depth_of(g, x + ox, y + oy, log_space) - zc : INFINITY;
    int side = fabsf(lo) < fabsf(hi) ? -1 : 1;
    float s = side < 0 ? lo : hi;
    one_sided_differences d = {isfinite(s) ? s : 0.0f, 0.0f, side};
    /* a slope: both sides within the test's threshold of continuing each
     * other, or bending by less than half the steeper of them */
    if (isfinite(lo) && isfinite(hi) && (fabsf(hi - lo) < crease || (lo * hi > 0.0f && fabsf(hi - lo) < 0.5f * fmaxf(fabsf(lo), fabsf(hi)))))
        d.d2 = hi - lo;
    return d;
}

/* The Taylor model about the centre from one-sided differences: a forward
 * difference is z' + z''/2 (a backward one z' - z''/2), so
 *   z(o) ~= z + d1 o + d2 (o^2 - side o) / 2. */
static float model_term(one_sided_differences d, int o, int second)
{
    float t = d.d1 * (float)o;
    return second ? t + 0.5f * d.d2 * (float)(o * o - d.side * o) : t;
}

float gtao_depth_test_weight(const ss_gbuffer *g, const gtao_spatial_options *o, int x, int y, int ox, int oy)
{
    int log_space = o->depth_test == GTAO_DEPTH_LOG_D1, second = o->depth_test == GTAO_DEPTH_LINEAR_D2;
    float zc = depth_of(g, x, y, log_space);
    float scale = log_space ? o->threshold : o->threshold * zc;
    one_sided_differences dx = one_sided(g, x, y, 1, 0, log_space, scale);
    one_sided_differences dy = one_sided(g, x, y, 0, 1, log_space, scale);
    float model = zc + model_term(dx, ox, second) + model_term(dy, oy, second);
    return ss_clampf(1.0f - fabsf(depth_of(g, x + ox, y + oy, log_space) - model) / scale, 0.0f, 1.0f);
}

static float filter_pixel(const ss_gbuffer *g, const gtao_spatial_options *o, int shift, const float *in, int x,
                          int y)
{
    float sum = 0.0f, weight = 0.0f;
    for (int oy = -1 - shift; oy <= 2 - shift; ++oy)
        for (int ox = -1 - shift; ox <= 2 - shift; ++ox) {
            if (!ss_covered(g, x + ox, y + oy))
                continue;
            float w = gtao_depth_test_weight(g, o, x, y, ox, oy);
            sum += w * in[(long)(y + oy) * g->width + x + ox];
            weight += w;
        }
    return weight > 0.0f ? sum / weight : in[(long)y * g->width + x];
}

void gtao_spatial_filter(const ss_gbuffer *g, int frame, const gtao_spatial_options *o, const float *in, float *out)
{
    int shift = o->alternate ? frame & 1 : 0;
#pragma omp parallel for schedule(static)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            out[i] = g->mask[i] != 0.0f ? filter_pixel(g, o, shift, in, x, y) : 0.0f;
        }
}

static void neighbourhood(const ss_gbuffer *g, const float *in, int x, int y, float *lo, float *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int oy = -1; oy <= 1; ++oy)
        for (int ox = -1; ox <= 1; ++ox)
            if (ss_covered(g, x + ox, y + oy)) {
                float v = in[(long)(y + oy) * g->width + x + ox];
                *lo = ss_minf(*lo, v);
                *hi = ss_maxf(*hi, v);
            }
}

void gtao_temporal_clamped(const ss_gbuffer *g, const float *in, int frame, float clamp_window, float *history)
{
    size_t n = (size_t)g->width * g->height;
    if (frame > 0 && clamp_window >= 0.0f)
        for (int y = 0; y < g->height; ++y)
            for (int x = 0; x < g->width; ++x) {
                long i = (long)y * g->width + x;
                float lo, hi;
                if (g->mask[i] == 0.0f)
                    continue;
                neighbourhood(g, in, x, y, &lo, &hi);
                float window = hi - lo;
                history[i] = ss_clampf(history[i], lo - clamp_window * window, hi + clamp_window * window);
            }
    gtao_temporal_accumulate(in, frame, n, history);
}
