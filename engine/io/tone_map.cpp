#include "engine/io/tone_map.h"

#include "engine/io/io_error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace eng::io {

namespace {

// Above this the fitted curve is >= 1 (its crossing of 1 is the root of 0.08 x^2 - 0.56 x - 0.14,
// x = 7.2417), so returning 1 changes no result and avoids overflow to Inf/Inf.
constexpr float kAcesSaturation = 8.0f;
constexpr float kSrgbLinearLimit = 0.0031308f;

} // namespace

float toneMapAces(float x) {
    if (std::isnan(x)) return x;
    if (x <= 0.0f) return 0.0f;
    if (x >= kAcesSaturation) return 1.0f;
    const float mapped = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return std::clamp(mapped, 0.0f, 1.0f);
}

float linearToSrgb(float v) {
    if (std::isnan(v)) return v;
    v = std::clamp(v, 0.0f, 1.0f);
    if (v <= kSrgbLinearLimit) return 12.92f * v;
    return 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

ImageF toneMapped(const ImageF& hdr) {
    if (!isConsistent(hdr)) {
        throw IoError("toneMapped: buffer holds " + std::to_string(hdr.rgba.size()) + " floats, expected " +
                      std::to_string(pixelCount(hdr) * 4) + " for " + std::to_string(hdr.width) + "x" +
                      std::to_string(hdr.height));
    }
    ImageF out{hdr.width, hdr.height, std::vector<float>(hdr.rgba.size())};
    for (size_t i = 0; i < hdr.rgba.size(); i += 4) {
        for (size_t c = 0; c < 3; ++c) {
            out.rgba[i + c] = linearToSrgb(toneMapAces(hdr.rgba[i + c]));
        }
        out.rgba[i + 3] = 1.0f;
    }
    return out;
}

ImageF srgbEncoded(const ImageF& display) {
    if (!isConsistent(display)) throw IoError("srgbEncoded: inconsistent image buffer");
    ImageF out = display;
    for (size_t i = 0; i < out.rgba.size(); ++i)
        if (i % 4 != 3) out.rgba[i] = linearToSrgb(out.rgba[i]);
    return out;
}

ImageU8 toneMapToSrgb8(const ImageF& hdr) {
    return quantizeToU8(toneMapped(hdr));
}

} // namespace eng::io
