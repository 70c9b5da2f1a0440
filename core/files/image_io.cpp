// 8-bit previews and error heatmaps through OpenImageIO, and the float RGB
// reader of HDR environments: the thin C++ adapter behind core/files/image_io.h. OIIO does the colour work (the sRGB encoding, the
// named colour maps, the 8-bit quantisation) and picks the file format from
// the destination's extension; the file is encoded in memory and written to
// a temporary name, every write checked, and renamed into place
// (core/files/atomic_file.h).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

extern "C" {
#include "core/files/atomic_file.h"
#include "core/files/input_file.h"
#include "core/files/image_io.h"
}

namespace {

using OIIO::ImageBuf;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

// OIIO's messages may span lines; ours are one line.
std::string one_line(std::string s)
{
    for (char &c : s)
        if (c == '\n' || c == '\r')
            c = ' ';
    while (!s.empty() && s.back() == ' ')
        s.pop_back();
    return s;
}

// The extension of path without its dot ("png"), which tells OIIO the format:
// the temporary file's own name ends in ".tmp-<pid>" and cannot.
std::string format_of(const char *path)
{
    std::string p(path);
    size_t slash = p.rfind('/');
    size_t dot = p.rfind('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return std::string();
    return p.substr(dot + 1);
}

// OIIO's error after a failed call on `out` (or its global one).
std::string error_of(const OIIO::ImageOutput *out, const ImageBuf &buf)
{
    std::string why = one_line(out ? out->geterror() : std::string());
    if (why.empty())
        why = one_line(buf.geterror());
    if (why.empty())
        why = one_line(OIIO::geterror());
    return why.empty() ? std::string("no reason given") : why;
}

// The file's bytes: buf encoded in `format` with `type` per channel, into
// memory (an IOVecOutput). Every step's result is checked, close() too (a
// PNG's last chunks are written there). A format whose writer takes no
// IOProxy is refused: its file writes could not be checked.
int encode(const char *path, const ImageBuf &buf, TypeDesc type, const std::string &format,
           std::vector<unsigned char> &bytes, gt_error *e)
{
    OIIO::Filesystem::IOVecOutput memory(bytes);
    auto out = OIIO::ImageOutput::create(format);
    if (!out)
        return gt_error_set(e, path, "cannot write image: %s", error_of(nullptr, buf).c_str());
    if (!out->supports("ioproxy"))
        return gt_error_set(e, path, "cannot write .%s images: OpenImageIO's %s writer cannot write to memory, so "
                                     "gtlab could not check the file (use .png, .tif, .exr, .jpg, ...)",
                            format.c_str(), out->format_name());
    ImageSpec spec = buf.spec();
    spec.set_format(type);
    bool ok = out->set_ioproxy(&memory) && out->open(path, spec) && buf.write(out.get());
    std::string why = ok ? std::string() : error_of(out.get(), buf);
    if (!out->close() && ok)
        ok = false, why = error_of(out.get(), buf);
    return ok ? 0 : gt_error_set(e, path, "cannot write image: %s", why.c_str());
}

// Writes buf with `type` per channel to path, atomically: encoded in
// memory, then written through core/files/atomic_file.h, whose every write and
// close is checked (a full disk or EFBIG leaves nothing under path).
int write_as(const char *path, const ImageBuf &buf, TypeDesc type, gt_error *e)
{
    std::string format = format_of(path);
    if (format.empty())
        return gt_error_set(e, path, "cannot tell the image format: the file name has no extension");
    if (atomic_file_check_writable(path, e) != 0)
        return -1;
    std::vector<unsigned char> bytes;
    if (encode(path, buf, type, format, bytes, e) != 0)
        return -1;
    return atomic_write_bytes(path, bytes.data(), bytes.size(), e);
}

// Writes buf as 8 bits per channel to path, atomically.
int write_8bit(const char *path, const ImageBuf &buf, gt_error *e) { return write_as(path, buf, TypeDesc::UINT8, e); }

// OIIO's linear -> sRGB transfer function (IEC 61966-2-1).
bool encode_srgb(ImageBuf &dst, const ImageBuf &linear, const char *path, gt_error *e)
{
    if (OIIO::ImageBufAlgo::colorconvert(dst, linear, "linear", "sRGB", false))
        return true;
    gt_error_set(e, path, "sRGB encoding failed: %s", one_line(dst.geterror()).c_str());
    return false;
}

bool valid_size(int width, int height) { return width > 0 && height > 0; }

// v clamped to [0, 1]; NaN, which fails every comparison, becomes 0.
float clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

} // namespace

extern "C" int image_write_preview(const char *path, const float *const *planes, int channel_count, int width,
                                   int height, float exposure, gt_error *e)
{
    if (channel_count != 1 && channel_count != 3)
        return gt_error_set(e, path, "a preview needs 1 or 3 channels, not %d", channel_count);
    if (!valid_size(width, height))
        return gt_error_set(e, path, "cannot write a %d x %d preview", width, height);
    size_t n = (size_t)width * (size_t)height;
    std::vector<float> pixels(n * (size_t)channel_count);
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < channel_count; ++c)
            pixels[i * (size_t)channel_count + (size_t)c] = clamp01(planes[c][i] * exposure);
    ImageBuf linear(ImageSpec(width, height, channel_count, TypeDesc::FLOAT), pixels.data());
    ImageBuf encoded;
    if (!encode_srgb(encoded, linear, path, e))
        return -1;
    return write_8bit(path, encoded, e);
}

namespace {

// `scaled` (values in [0, 1]) through the colour map, black where mask is
// non-NULL and 0, sRGB-encoded, with `description` (may be NULL) in the
// file's metadata. OIIO stores its maps linear (the perceptual ones are
// matplotlib's, linearised), so the result is encoded like a preview.
int write_colour_mapped(const char *path, const float *scaled, const float *mask, int width, int height,
                        const char *map_name, const char *description, gt_error *e)
{
    ImageBuf map_input(ImageSpec(width, height, 1, TypeDesc::FLOAT), const_cast<float *>(scaled));
    ImageBuf colours;
    if (!OIIO::ImageBufAlgo::color_map(colours, map_input, 0, map_name))
        return gt_error_set(e, path, "colour map \"%s\": %s", map_name, one_line(colours.geterror()).c_str());
    if (mask) {
        const float black[3] = {0.0f, 0.0f, 0.0f};
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                if (mask[(size_t)y * (size_t)width + (size_t)x] == 0.0f)
                    colours.setpixel(x, y, black, 3);
    }
    ImageBuf encoded;
    if (!encode_srgb(encoded, colours, path, e))
        return -1;
    if (description)
        encoded.specmod().attribute("ImageDescription", description);
    return write_8bit(path, encoded, e);
}

// values / vmax clamped to [0, 1] into scaled[0 .. width height).
int scale_heatmap(const char *path, const float *values, int width, int height, float vmax, float *scaled,
                  gt_error *e)
{
    if (!valid_size(width, height))
        return gt_error_set(e, path, "cannot write a %d x %d heatmap", width, height);
    if (!(vmax > 0.0f) || !std::isfinite(vmax))
        return gt_error_set(e, path, "heatmap range must be a positive finite number, not %g", (double)vmax);
    for (size_t i = 0; i < (size_t)width * (size_t)height; ++i)
        scaled[i] = clamp01(values[i] / vmax);
    return 0;
}

} // namespace

extern "C" int image_write_heatmap(const char *path, const float *values, const float *mask, int width, int height,
                                   float vmax, const char *map_name, gt_error *e)
{
    std::vector<float> scaled(valid_size(width, height) ? (size_t)width * (size_t)height : 0);
    if (scale_heatmap(path, values, width, height, vmax, scaled.data(), e) != 0)
        return -1;
    char scale[96]; // what report/heatmap_colour_bar.c reads back to draw the bar beside it
    snprintf(scale, sizeof scale, "gtlab heatmap: %s, 0 to %g", map_name, (double)vmax);
    return write_colour_mapped(path, scaled.data(), mask, width, height, map_name, scale, e);
}

extern "C" int image_heatmap_bar_rows(int height) { return height / 16 > 4 ? height / 16 : 4; }

extern "C" int image_write_heatmap_with_bar(const char *path, const float *values, const float *mask, int width,
                                            int height, float vmax, const char *map_name, gt_error *e)
{
    int bar = image_heatmap_bar_rows(height), total = height + 2 * bar;
    size_t n = valid_size(width, height) ? (size_t)width * (size_t)height : 0;
    std::vector<float> scaled((size_t)width * (size_t)total * (n > 0)), full_mask(scaled.size(), 1.0f);
    if (scale_heatmap(path, values, width, height, vmax, scaled.data(), e) != 0)
        return -1;
    for (size_t i = 0; mask && i < n; ++i)
        full_mask[i] = mask[i];
    for (int y = height; y < total; ++y)
        for (int x = 0; x < width; ++x) {
            size_t i = (size_t)y * (size_t)width + (size_t)x;
            full_mask[i] = y >= height + bar ? 1.0f : 0.0f; // a black gap, then the bar
            scaled[i] = width > 1 ? (float)x / (float)(width - 1) : 0.0f;
        }
    char description[128];
    snprintf(description, sizeof description, "%s heatmap; colour bar below: 0 (left) to %g (right)", map_name,
             (double)vmax);
    return write_colour_mapped(path, scaled.data(), full_mask.data(), width, total, map_name, description, e);
}

extern "C" int image_colour_map_srgb(const char *map_name, int count, unsigned char *rgb)
{
    if (count < 2)
        return -1;
    std::vector<float> ramp((size_t)count);
    for (int k = 0; k < count; ++k)
        ramp[(size_t)k] = (float)k / (float)(count - 1);
    ImageBuf values(ImageSpec(count, 1, 1, TypeDesc::FLOAT), ramp.data()), colours, encoded;
    gt_error e;
    if (!OIIO::ImageBufAlgo::color_map(colours, values, 0, map_name) || !encode_srgb(encoded, colours, map_name, &e))
        return -1;
    std::vector<float> pixels((size_t)count * 3);
    if (!encoded.get_pixels(OIIO::ROI(0, count, 0, 1, 0, 1, 0, 3), TypeDesc::FLOAT, pixels.data()))
        return -1;
    for (size_t i = 0; i < pixels.size(); ++i)
        rgb[i] = (unsigned char)std::lround(clamp01(pixels[i]) * 255.0f);
    return 0;
}

extern "C" int image_read_description(const char *path, char *text, size_t size)
{
    if (input_file_check(path, nullptr, nullptr) != 0)
        return -1;
    auto in = OIIO::ImageInput::open(path);
    if (!in)
        return -1;
    std::string description = in->spec().get_string_attribute("ImageDescription");
    in->close();
    if (description.empty() || size == 0)
        return -1;
    snprintf(text, size, "%s", description.c_str());
    return 0;
}

extern "C" int image_write_data8(const char *path, const float *values, int width, int height,
                                 const char *description, gt_error *e)
{
    if (!valid_size(width, height))
        return gt_error_set(e, path, "cannot write a %d x %d image", width, height);
    size_t n = (size_t)width * (size_t)height;
    std::vector<float> pixels(n);
    for (size_t i = 0; i < n; ++i)
        pixels[i] = clamp01(values[i]);
    ImageSpec spec(width, height, 1, TypeDesc::FLOAT);
    spec.attribute("oiio:ColorSpace", "Linear"); // data: no sRGB chunk, gamma 1
    if (description)
        spec.attribute("ImageDescription", description);
    ImageBuf linear(spec, pixels.data());
    return write_8bit(path, linear, e);
}

extern "C" int image_write_data16(const char *path, const float *const *planes, int channel_count, int width,
                                  int height, const char *description, gt_error *e)
{
    if (channel_count < 1 || channel_count > 4 || !valid_size(width, height))
        return gt_error_set(e, path, "cannot write a %d x %d image of %d channels", width, height, channel_count);
    size_t n = (size_t)width * (size_t)height;
    std::vector<float> pixels(n * (size_t)channel_count);
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < channel_count; ++c)
            pixels[i * (size_t)channel_count + (size_t)c] = planes[c] ? clamp01(planes[c][i]) : 0.0f;
    ImageSpec spec(width, height, channel_count, TypeDesc::FLOAT);
    spec.attribute("oiio:ColorSpace", "Linear"); // data: no sRGB chunk, gamma 1
    if (description)
        spec.attribute("ImageDescription", description);
    ImageBuf linear(spec, pixels.data());
    return write_as(path, linear, TypeDesc::UINT16, e);
}

namespace {

// The indices of the channels read as R, G, B: the channels named exactly
// "R", "G", "B" if all three exist, else the first three; a single channel
// serves all three.
void rgb_channels(const ImageSpec &spec, int index[3])
{
    static const char *const names[3] = {"R", "G", "B"};
    int found = 0;
    for (int c = 0; c < 3; ++c) {
        index[c] = spec.channelindex(names[c]);
        found += index[c] >= 0;
    }
    if (found == 3)
        return;
    for (int c = 0; c < 3; ++c)
        index[c] = spec.nchannels >= 3 ? c : 0;
}

} // namespace

extern "C" int image_read_rgb_float(const char *path, int *width, int *height, float **rgb, int *floating_point,
                                    gt_error *e)
{
    *rgb = nullptr;
    int64_t file_size = 0;
    if (input_file_check(path, &file_size, e) != 0) // a device or a FIFO would hang OpenImageIO's open
        return -1;
    auto in = OIIO::ImageInput::open(path);
    if (!in)
        return gt_error_set(e, path, "cannot read image: %s", one_line(OIIO::geterror()).c_str());
    const ImageSpec spec = in->spec();
    if ((double)spec.image_bytes(true) > (double)file_size * INPUT_MAX_DECODE_RATIO)
        return gt_error_set(e, path, "the header claims %d x %d pixels of %d channels, more than a file of %lld bytes "
                            "can hold: truncated or crafted", spec.width, spec.height, spec.nchannels,
                            (long long)file_size);
    if (spec.nchannels < 1 || !valid_size(spec.width, spec.height))
        return gt_error_set(e, path, "not an image with pixels (%d x %d, %d channels)", spec.width, spec.height,
                            spec.nchannels);
    // The EXR reader's bounds (docs/design.md, "Input is hostile").
    if ((double)spec.width * spec.height > 268435456.0 || (double)spec.width * spec.height * spec.nchannels > 1073741824.0)
        return gt_error_set(e, path, "%d x %d pixels of %d channels: more than 2^28 pixels or 2^30 values", spec.width,
                            spec.height, spec.nchannels);
    size_t n = (size_t)spec.width * (size_t)spec.height;
    std::vector<float> all(n * (size_t)spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, TypeDesc::FLOAT, all.data()))
        return gt_error_set(e, path, "cannot read pixels: %s", one_line(in->geterror()).c_str());
    int index[3];
    rgb_channels(spec, index);
    float *out = static_cast<float *>(malloc(sizeof(float) * 3 * n));
    if (!out)
        return gt_error_set(e, path, "out of memory for %d x %d pixels", spec.width, spec.height);
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            out[3 * i + (size_t)c] = all[i * (size_t)spec.nchannels + (size_t)index[c]];
    *width = spec.width;
    *height = spec.height;
    *rgb = out;
    *floating_point = spec.format.is_floating_point();
    return 0;
}
