/* The two orders of the 4x4 direction tile; see gtao_pattern.h. */
#include "gtao/gtao_pattern.h"

int gtao_morton_index(int x, int y)
{
    return (x & 1) | ((y & 1) << 1) | ((x & 2) << 1) | ((y & 2) << 2);
}

float gtao_spatial_direction_morton(int x, int y) { return (1.0f / 16.0f) * (float)gtao_morton_index(x, y); }

float gtao_pattern_direction(int x, int y, int pattern)
{
    return pattern == GTAO_PATTERN_MORTON ? gtao_spatial_direction_morton(x, y) : gtao_spatial_direction(x, y);
}

float gtao_spatial_direction(int x, int y)
{
    return (1.0f / 16.0f) * (float)((((x + y) & 3) << 2) + (x & 3));
}

float gtao_spatial_direction_as_transcribed(int x, int y)
{
    return (1.0f / 16.0f) * (float)(((x + y) & 3) << 2) + (float)(x & 3);
}

float gtao_spatial_offset(int x, int y) { return 0.25f * (float)((y - x) & 3); }

float gtao_temporal_rotation(int frame)
{
    static const float rotations[6] = {60.0f, 300.0f, 180.0f, 240.0f, 120.0f, 0.0f};
    return rotations[frame % 6] / 360.0f;
}

float gtao_temporal_offset(int frame)
{
    static const float offsets[4] = {0.0f, 0.5f, 0.25f, 0.75f};
    return offsets[(frame / 6) % 4];
}
