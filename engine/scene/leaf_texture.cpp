#include "engine/scene/leaf_texture.h"

#include <stb_image_write.h>

#include <algorithm>
#include <cmath>

namespace eng::scene {

namespace {

constexpr float kPi = 3.14159265359f;

// Half width of the leaf blade at v in [0, 1] as a fraction of the texture width.
float bladeHalfWidth(float v) {
    if (v <= 0.0f || v >= 1.0f) {
        return 0.0f;
    }
    // v^0.8 moves the widest point below the middle, like most broad leaves.
    return 0.46f * std::pow(std::sin(kPi * std::pow(v, 0.8f)), 0.9f);
}

uint8_t toByte(float v) {
    return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const auto* bytes = static_cast<const uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

} // namespace

LeafImage makeLeafImage(uint32_t size) {
    LeafImage image;
    image.width = size;
    image.height = size;
    image.rgba8.resize(static_cast<size_t>(size) * size * 4);
    const float texel = 1.0f / static_cast<float>(size);
    for (uint32_t y = 0; y < size; ++y) {
        const float v = (static_cast<float>(y) + 0.5f) * texel;
        for (uint32_t x = 0; x < size; ++x) {
            const float u = (static_cast<float>(x) + 0.5f) * texel;
            const float across = std::abs(u - 0.5f);
            const float halfWidth = std::max(bladeHalfWidth(v), v < 0.1f ? 0.02f : 0.0f); // stalk at the base
            // Signed distance to the edge in texels, for a one-texel soft edge
            // that keeps the 0.5 alpha contour smooth under filtering.
            const float inside = (halfWidth - across) / texel;
            const float alpha = std::clamp(0.5f + inside, 0.0f, 1.0f);

            // Midrib and side veins darker; blade lighter toward the edge.
            const float edge = halfWidth > 0.0f ? std::clamp(across / halfWidth, 0.0f, 1.0f) : 1.0f;
            const float midrib = across < 0.012f ? 1.0f : 0.0f;
            const float sidePhase = std::fmod((v - across * 0.9f) * 14.0f, 1.0f);
            const float sideVein = (sidePhase < 0.07f && v > 0.1f) ? 0.6f : 0.0f;
            const float vein = std::max(midrib, sideVein);
            const float r = 0.16f + 0.10f * edge + 0.05f * v - 0.06f * vein;
            const float g = 0.42f + 0.12f * edge - 0.05f * v - 0.10f * vein;
            const float b = 0.08f + 0.04f * edge - 0.03f * vein;

            uint8_t* o = image.rgba8.data() + (static_cast<size_t>(y) * size + x) * 4;
            o[0] = toByte(r);
            o[1] = toByte(g);
            o[2] = toByte(b);
            // Outside texels keep the leaf colour (only alpha drops) so bilinear
            // filtering and mips do not pull a dark fringe into the silhouette.
            o[3] = toByte(alpha);
        }
    }
    return image;
}

std::vector<uint8_t> encodePng(const LeafImage& image) {
    std::vector<uint8_t> png;
    const int stride = static_cast<int>(image.width * 4);
    stbi_write_png_to_func(&appendBytes, &png, static_cast<int>(image.width), static_cast<int>(image.height),
                           4, image.rgba8.data(), stride);
    return png;
}

} // namespace eng::scene
