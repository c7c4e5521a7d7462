#include "engine/io/image.h"

#include "engine/io/io_error.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

namespace eng::io {

namespace {

void checkPixelLimit(const char* what, uint32_t width, uint32_t height) {
    if (uint64_t(width) * height > kMaxImagePixels) {
        throw IoError(std::string(what) + ": " + std::to_string(width) + "x" + std::to_string(height) +
                      " exceeds the limit of " + std::to_string(kMaxImagePixels) + " pixels");
    }
}

size_t pixelOffset(uint32_t width, uint32_t height, uint32_t x, uint32_t y) {
    assert(x < width && y < height);
    (void)height;
    return (size_t(y) * width + x) * 4;
}

} // namespace

ImageF makeImage(uint32_t width, uint32_t height, RgbaF fill) {
    checkPixelLimit("makeImage", width, height);
    ImageF image{width, height, {}};
    image.rgba.resize(pixelCount(image) * 4);
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i + 0] = fill.r;
        image.rgba[i + 1] = fill.g;
        image.rgba[i + 2] = fill.b;
        image.rgba[i + 3] = fill.a;
    }
    return image;
}

ImageU8 makeImageU8(uint32_t width, uint32_t height, RgbaU8 fill) {
    checkPixelLimit("makeImageU8", width, height);
    ImageU8 image{width, height, {}};
    image.rgba.resize(pixelCount(image) * 4);
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i + 0] = fill.r;
        image.rgba[i + 1] = fill.g;
        image.rgba[i + 2] = fill.b;
        image.rgba[i + 3] = fill.a;
    }
    return image;
}

RgbaF pixel(const ImageF& image, uint32_t x, uint32_t y) {
    const float* p = image.rgba.data() + pixelOffset(image.width, image.height, x, y);
    return {p[0], p[1], p[2], p[3]};
}

void setPixel(ImageF& image, uint32_t x, uint32_t y, const RgbaF& value) {
    float* p = image.rgba.data() + pixelOffset(image.width, image.height, x, y);
    p[0] = value.r;
    p[1] = value.g;
    p[2] = value.b;
    p[3] = value.a;
}

RgbaU8 pixel(const ImageU8& image, uint32_t x, uint32_t y) {
    const uint8_t* p = image.rgba.data() + pixelOffset(image.width, image.height, x, y);
    return {p[0], p[1], p[2], p[3]};
}

void setPixel(ImageU8& image, uint32_t x, uint32_t y, const RgbaU8& value) {
    uint8_t* p = image.rgba.data() + pixelOffset(image.width, image.height, x, y);
    p[0] = value.r;
    p[1] = value.g;
    p[2] = value.b;
    p[3] = value.a;
}

size_t countNonFinite(const ImageF& image) {
    return size_t(
        std::count_if(image.rgba.begin(), image.rgba.end(), [](float v) { return !std::isfinite(v); }));
}

bool allFinite(const ImageF& image) {
    return std::all_of(image.rgba.begin(), image.rgba.end(), [](float v) { return std::isfinite(v); });
}

ImageU8 quantizeToU8(const ImageF& display) {
    if (!isConsistent(display)) {
        throw IoError("quantizeToU8: buffer holds " + std::to_string(display.rgba.size()) +
                      " floats, expected " + std::to_string(pixelCount(display) * 4) + " for " +
                      std::to_string(display.width) + "x" + std::to_string(display.height));
    }
    ImageU8 out{display.width, display.height, std::vector<uint8_t>(display.rgba.size())};
    for (size_t i = 0; i < display.rgba.size(); ++i) {
        const float v = display.rgba[i];
        if (std::isnan(v)) {
            throw IoError("quantizeToU8: NaN at pixel " + std::to_string(i / 4) + " channel " +
                          std::to_string(i % 4));
        }
        out.rgba[i] = uint8_t(std::lround(255.0f * std::clamp(v, 0.0f, 1.0f)));
    }
    return out;
}

ImageF dequantized(const ImageU8& display) {
    ImageF out{display.width, display.height, std::vector<float>(display.rgba.size())};
    for (size_t i = 0; i < display.rgba.size(); ++i)
        out.rgba[i] = float(display.rgba[i]) / 255.0f;
    return out;
}

} // namespace eng::io
