// libsquish adapter for specular_occlusion/bc4_codec.h (see there).
#include "specular_occlusion/bc4_codec.h"

#include <squish.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

static int blocks_across(int n) { return (n + 3) / 4; }

size_t bc4_storage_bytes(int width, int height)
{
    return (size_t)blocks_across(width) * (size_t)blocks_across(height) * BC4_BLOCK_BYTES;
}

// The nearest 8-bit value (255 v is exact in a double; ties to even).
static unsigned char to_unorm8(float v)
{
    return (unsigned char)std::lrint(255.0 * std::min(1.0, std::max(0.0, (double)v)));
}

void bc4_encode(const float *values, int width, int height, unsigned char *blocks)
{
    // libsquish's BC4 codes the red channel of RGBA texels.
    std::vector<squish::u8> rgba((size_t)width * height * 4, 0);
    for (size_t i = 0; i < (size_t)width * height; ++i)
        rgba[4 * i] = to_unorm8(values[i]);
    squish::CompressImage(rgba.data(), width, height, blocks, squish::kBc4);
}

void bc4_decode(const unsigned char *blocks, int width, int height, float *decoded)
{
    for (int by = 0; by < blocks_across(height); ++by)
        for (int bx = 0; bx < blocks_across(width); ++bx) {
            // A DXT5 block is the BC4 (alpha) block followed by a colour block.
            unsigned char dxt5[16] = {0};
            std::memcpy(dxt5, blocks + ((size_t)by * blocks_across(width) + bx) * BC4_BLOCK_BYTES, BC4_BLOCK_BYTES);
            squish::u8 rgba[16 * 4];
            squish::Decompress(rgba, dxt5, squish::kDxt5);
            for (int t = 0; t < 16; ++t) {
                int x = 4 * bx + t % 4, y = 4 * by + t / 4;
                if (x < width && y < height)
                    decoded[(size_t)y * width + x] = rgba[4 * t + 3] / 255.0f;
            }
        }
}
