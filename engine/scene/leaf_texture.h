#pragma once
// The procedural leaf texture for foliage cards: RGBA8 with the leaf shape in
// alpha (alpha-tested at 0.5), green veined colour, encoded as PNG so the scene
// can embed it in a glTF buffer like any authored asset.

#include <cstdint>
#include <vector>

namespace eng::scene {

struct LeafImage {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba8;
};

// size x size texels; u across the leaf, v from stalk (v = 0) to tip (v = 1).
LeafImage makeLeafImage(uint32_t size = 128);

// PNG bytes of an RGBA8 image (stb_image_write into memory).
std::vector<uint8_t> encodePng(const LeafImage& image);

} // namespace eng::scene
