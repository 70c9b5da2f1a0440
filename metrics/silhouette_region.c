#include "metrics/silhouette_region.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int surface(const float *mask, size_t i) { return mask[i] >= 0.5f; }

/* Whether the 4-neighbours i and j are separated by a discontinuity. */
static int discontinuous(const float *depth, const float *mask, size_t i, size_t j, double relative_jump)
{
    if (surface(mask, i) != surface(mask, j))
        return 1;
    if (!surface(mask, i))
        return 0;
    double a = depth[i], b = depth[j];
    return fabs(a - b) > relative_jump * fmin(a, b);
}

/* edge[i] = 1 where a discontinuity separates pixel i from its right or lower
 * neighbour (both pixels are marked). */
static void mark_edges(const float *depth, const float *mask, int width, int height, double relative_jump,
                       unsigned char *edge)
{
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            size_t i = (size_t)y * width + x;
            if (x + 1 < width && discontinuous(depth, mask, i, i + 1, relative_jump))
                edge[i] = edge[i + 1] = 1;
            if (y + 1 < height && discontinuous(depth, mask, i, i + width, relative_jump))
                edge[i] = edge[i + width] = 1;
        }
}

/* Whether an edge pixel lies within the (2 radius + 1)^2 square about (x, y). */
static int near_edge(const unsigned char *edge, int width, int height, int x, int y, int radius)
{
    for (int v = y - radius; v <= y + radius; ++v)
        for (int u = x - radius; u <= x + radius; ++u)
            if (u >= 0 && v >= 0 && u < width && v < height && edge[(size_t)v * width + u])
                return 1;
    return 0;
}

int silhouette_region(const float *depth, const float *mask, int width, int height, int radius,
                      double relative_jump, float *region, float *interior)
{
    size_t n = (size_t)width * height;
    unsigned char *edge = calloc(n, 1);
    if (!edge)
        return -1;
    mark_edges(depth, mask, width, height, relative_jump, edge);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            size_t i = (size_t)y * width + x;
            int in = surface(mask, i) && near_edge(edge, width, height, x, y, radius);
            region[i] = in ? 1.0f : 0.0f;
            if (interior)
                interior[i] = surface(mask, i) && !in ? 1.0f : 0.0f;
        }
    free(edge);
    return 0;
}
