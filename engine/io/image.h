#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace eng::io {

// Refused by makeImage and by the readers: 2^28 pixels (16384 x 16384) is 4 GiB of RGBA floats,
// and a corrupt header asking for more must not turn into a huge allocation.
inline constexpr uint64_t kMaxImagePixels = uint64_t(1) << 28;

// Linear (or display-encoded, depending on who produced it) RGBA, 4 floats per pixel,
// row-major, top row first.
struct ImageF {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
};

// 8-bit RGBA, 4 bytes per pixel, row-major, top row first.
struct ImageU8 {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

struct RgbaF {
    float r = 0.0f, g = 0.0f, b = 0.0f, a = 0.0f;
};

struct RgbaU8 {
    uint8_t r = 0, g = 0, b = 0, a = 0;
};

// Every pixel set to `fill` (opaque black by default). Throws IoError above kMaxImagePixels.
ImageF makeImage(uint32_t width, uint32_t height, RgbaF fill = {0.0f, 0.0f, 0.0f, 1.0f});
ImageU8 makeImageU8(uint32_t width, uint32_t height, RgbaU8 fill = {0, 0, 0, 255});

inline size_t pixelCount(const ImageF& image) {
    return size_t(image.width) * image.height;
}
inline size_t pixelCount(const ImageU8& image) {
    return size_t(image.width) * image.height;
}

// True when the buffer holds exactly width*height RGBA pixels; writers and metrics refuse others.
inline bool isConsistent(const ImageF& image) {
    return image.rgba.size() == pixelCount(image) * 4;
}
inline bool isConsistent(const ImageU8& image) {
    return image.rgba.size() == pixelCount(image) * 4;
}

// Pixel access. (x, y) must lie inside the image: checked by assert in debug builds only,
// because these sit in per-pixel loops.
RgbaF pixel(const ImageF& image, uint32_t x, uint32_t y);
void setPixel(ImageF& image, uint32_t x, uint32_t y, const RgbaF& value);
RgbaU8 pixel(const ImageU8& image, uint32_t x, uint32_t y);
void setPixel(ImageU8& image, uint32_t x, uint32_t y, const RgbaU8& value);

// Counts every NaN or +-Inf float in the buffer (all four channels).
size_t countNonFinite(const ImageF& image);
bool allFinite(const ImageF& image);

// Display-encoded floats (already in [0,1], e.g. toneMapped() or errorHeatmap() output) to 8 bits:
// round(255 * clamp(v, 0, 1)), halves away from zero, all four channels.
// Throws IoError on NaN, which has no 8-bit value and must not silently become black.
ImageU8 quantizeToU8(const ImageF& display);

// The other way: v / 255, all four channels (an 8-bit display image, e.g. a PNG, for the metrics).
ImageF dequantized(const ImageU8& display);

} // namespace eng::io
