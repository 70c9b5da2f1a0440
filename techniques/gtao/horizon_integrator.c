/* Horizon-based numerical integrator (seeds/001, "Methodology"); see
 * horizon_integrator.h. */
#include "gtao/horizon_integrator.h"

#include <math.h>

static double integrand(const gtao_slice *s, vec3 n, gtao_weighting w, double theta)
{
    double sin_t = sin(theta), weight = fabs(sin_t);
    if (w == GTAO_UNIFORM)
        return 0.5 * weight;
    double c = cos(theta);
    double nw = (double)n.x * (c * s->v.x + sin_t * s->side.x) + (double)n.y * (c * s->v.y + sin_t * s->side.y) +
                (double)n.z * (c * s->v.z + sin_t * s->side.z);
    return fmax(nw, 0.0) * weight;
}

static double simpson(const gtao_slice *s, vec3 n, gtao_weighting w, double a, double b, int intervals)
{
    double h = (b - a) / intervals, sum = integrand(s, n, w, a) + integrand(s, n, w, b);
    for (int k = 1; k < intervals; ++k)
        sum += (k & 1 ? 4.0 : 2.0) * integrand(s, n, w, a + k * h);
    return sum * h / 3.0;
}

double horizon_arc_numeric(const gtao_slice *s, vec3 n, gtao_weighting w, int intervals)
{
    return simpson(s, n, w, s->h1, 0.0, intervals) + simpson(s, n, w, 0.0, s->h2, intervals);
}

void horizon_integrator_render(const ss_gbuffer *g, const gtao_params *p, int intervals, float *ao)
{
    gtao_params q = *p;
    q.pattern = 0;
    q.fast_math = 0;
#pragma omp parallel for schedule(dynamic, 4)
    for (int y = 0; y < g->height; ++y)
        for (int x = 0; x < g->width; ++x) {
            long i = (long)y * g->width + x;
            double sum = 0.0;
            if (g->mask[i] != 0.0f) {
                vec3 n = ss_view_normal(g, x, y);
                for (int k = 0; k < q.slices; ++k) {
                    gtao_slice s;
                    gtao_search_slice(g, x, y, &q, gtao_slice_angle(x, y, 0, k, q.slices, 0), 0.5f, &s);
                    sum += s.weight * horizon_arc_numeric(&s, n, q.weighting, intervals);
                }
            }
            ao[i] = (float)(sum / q.slices);
        }
}
