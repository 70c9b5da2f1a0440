/* The two orders of the 4x4 direction tile; see gtao_pattern.h. */
#include "realtime/gtao_pattern.h"

#include "realtime/gtao.h"

int gtao_morton_index(int x, int y)
{
    return (x & 1) | ((y & 1) << 1) | ((x & 2) << 1) | ((y & 2) << 2);
}

float gtao_spatial_direction_morton(int x, int y) { return (1.0f / 16.0f) * (float)gtao_morton_index(x, y); }

float gtao_pattern_direction(int x, int y, int pattern)
{
    return pattern == GTAO_PATTERN_MORTON ? gtao_spatial_direction_morton(x, y) : gtao_spatial_direction(x, y);
}
