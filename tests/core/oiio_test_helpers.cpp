// OpenImageIO helpers for the core tests (see oiio_test_helpers.h).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

extern "C" {
#include "tests/core/oiio_test_helpers.h"
}

using namespace OIIO;

static void copy_name(char *dst, size_t size, const std::string &src) { snprintf(dst, size, "%s", src.c_str()); }

extern "C" int oiio_test_read(const char *path, oiio_test_image *img)
{
    memset(img, 0, sizeof *img);
    auto in = ImageInput::open(path);
    if (!in) {
        fprintf(stderr, "oiio_test_read: %s\n", OIIO::geterror().c_str());
        return -1;
    }
    const ImageSpec &spec = in->spec();
    if (spec.nchannels > OIIO_TEST_MAX_CHANNELS) {
        fprintf(stderr, "oiio_test_read: %s: too many channels\n", path);
        return -1;
    }
    img->width = spec.width;
    img->height = spec.height;
    img->channels = spec.nchannels;
    img->x = spec.x;
    img->y = spec.y;
    img->full_x = spec.full_x;
    img->full_y = spec.full_y;
    img->full_width = spec.full_width;
    img->full_height = spec.full_height;
    img->tile_width = spec.tile_width;
    copy_name(img->format, sizeof img->format, spec.format.c_str());
    copy_name(img->compression, sizeof img->compression, spec.get_string_attribute("compression"));
    for (int c = 0; c < spec.nchannels; ++c)
        copy_name(img->channel_names[c], sizeof img->channel_names[c], spec.channelnames[c]);
    size_t n = (size_t)spec.width * (size_t)spec.height * (size_t)spec.nchannels;
    img->pixels = (float *)malloc(sizeof(float) * n);
    if (!img->pixels || !in->read_image(0, 0, 0, spec.nchannels, TypeDesc::FLOAT, img->pixels)) {
        fprintf(stderr, "oiio_test_read: %s: %s\n", path, in->geterror().c_str());
        oiio_test_image_free(img);
        return -1;
    }
    return 0;
}

extern "C" int oiio_test_write_exr(const char *path, const oiio_test_image *img, const char *pixel_type, int tile_size,
                                   const char *string_value)
{
    bool as_uint = strcmp(pixel_type, "uint") == 0;
    TypeDesc type = as_uint ? TypeDesc::UINT32 : strcmp(pixel_type, "half") == 0 ? TypeDesc::HALF : TypeDesc::FLOAT;
    ImageSpec spec(img->width, img->height, img->channels, type);
    spec.x = img->x;
    spec.y = img->y;
    spec.full_x = img->full_x;
    spec.full_y = img->full_y;
    spec.full_width = img->full_width;
    spec.full_height = img->full_height;
    if (tile_size > 0)
        spec.tile_width = spec.tile_height = tile_size;
    spec.channelnames.clear();
    for (int c = 0; c < img->channels; ++c)
        spec.channelnames.emplace_back(img->channel_names[c]);
    spec.attribute("compression", "zip");
    spec.attribute("test.string", string_value);
    spec.attribute("test.int", 7);
    size_t n = (size_t)img->width * (size_t)img->height * (size_t)img->channels;
    // OIIO treats integer pixel types as normalised, so UINT data is handed
    // over as uint32 values to be stored as they are.
    std::vector<uint32_t> uints(as_uint ? n : 0);
    for (size_t i = 0; i < uints.size(); ++i)
        uints[i] = (uint32_t)img->pixels[i];
    auto out = ImageOutput::create(path);
    bool ok = out && out->open(path, spec);
    ok = ok && (as_uint ? out->write_image(TypeDesc::UINT32, uints.data())
                        : out->write_image(TypeDesc::FLOAT, img->pixels));
    ok = ok && out->close();
    if (!ok)
        fprintf(stderr, "oiio_test_write_exr: %s: %s\n", path, out ? out->geterror().c_str() : OIIO::geterror().c_str());
    return ok ? 0 : -1;
}

extern "C" int oiio_test_color_map(const char *map, float x, float rgb[3])
{
    ImageBuf one(ImageSpec(1, 1, 1, TypeDesc::FLOAT));
    one.setpixel(0, 0, &x, 1);
    ImageBuf mapped = ImageBufAlgo::color_map(one, 0, map);
    if (mapped.has_error() || mapped.nchannels() != 3) {
        fprintf(stderr, "oiio_test_color_map: %s\n", mapped.geterror().c_str());
        return -1;
    }
    mapped.getpixel(0, 0, rgb, 3);
    return 0;
}

extern "C" void oiio_test_image_free(oiio_test_image *img)
{
    free(img->pixels);
    img->pixels = NULL;
}
