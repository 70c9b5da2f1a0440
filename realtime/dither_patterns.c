/* White, blue, interleaved-gradient and Bayer dither patterns: see dither_patterns.h. */
#include "realtime/dither_patterns.h"

#include <math.h>
#include <stddef.h>

const char *dither_pattern_name(dither_pattern p)
{
    static const char *const names[DITHER_PATTERN_COUNT] = {"white", "blue", "ign", "bayer"};
    return p >= 0 && p < DITHER_PATTERN_COUNT ? names[p] : "?";
}

double dither_ign(int x, int y)
{
    double inner = 0.06711056 * x + 0.00583715 * y;
    double outer = 52.9829189 * (inner - floor(inner));
    return outer - floor(outer);
}

/* Bayer's index at (x, y) in the 2^levels square, by the recursion. */
static int bayer_index(int x, int y, int levels)
{
    static const int base[2][2] = {{0, 2}, {3, 1}};
    int m = 0;
    for (int l = 0; l < levels; ++l) /* from the finest bit: M_2n = 4 M_n + base */
        m += base[(y >> l) & 1][(x >> l) & 1] << (2 * (levels - 1 - l));
    return m;
}

double dither_bayer8(int x, int y) { return (bayer_index(x & 7, y & 7, 3) + 0.5) / 64.0; }

double dither_pattern_value(dither_pattern p, const blue_noise_texture *blue, uint64_t stream, int x, int y)
{
    int shift_x = (int)(stream % 64) * 5, shift_y = (int)(stream % 64) * 3;
    switch (p) {
    case DITHER_PATTERN_WHITE: return blue_noise_uniform(stream, ((uint64_t)(uint32_t)y << 32) | (uint32_t)x);
    case DITHER_PATTERN_BLUE: {
        int n = blue->size, c = (int)(stream % (uint64_t)blue->channel_count);
        return blue->values[(size_t)c * n * n + (size_t)(((y % n) + n) % n) * n + ((x % n) + n) % n];
    }
    case DITHER_PATTERN_IGN: return dither_ign(x + shift_x, y + shift_y);
    default: return dither_bayer8(x + shift_x, y + shift_y);
    }
}
