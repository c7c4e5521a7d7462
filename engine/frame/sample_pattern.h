#pragma once
// The one table of sample positions (DESIGN section 3). Rates 1 and 4 are native;
// n = 4m for m = 2, 4, 8 is emulated by m layered 4x rasterisations, layer l
// shifted by layerOffset(l) pixels so that its hardware sample at q lands on the
// emulated position q - layerOffset(l).
//
// The offsets form an n-rooks pattern: the 4x standard positions sit on odd
// multiples of 1/8; layer offsets are odd multiples of 1/(8m) in x and a
// permutation of them in y, so every emulated sample has its own column and row
// on a (4m)x(4m) grid inside the pixel and the offsets sum to zero (the pattern
// is centred, so a smooth signal's average over it equals the pixel centre value
// to second order).

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace eng::frame {

// The standard Vulkan 4x positions (VkPhysicalDeviceLimits::standardSampleLocations).
inline constexpr glm::vec2 kStandard4x[4] = {
    {0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};

struct SamplePattern {
    uint32_t samples = 1;                // n
    uint32_t samplesPerLayer = 1;        // hardware rate: 1 or 4
    uint32_t layers = 1;                 // m
    std::vector<glm::vec2> layerOffsets; // pixels, per layer
    std::vector<glm::vec2> positions;    // [0,1)^2, per sample s = layer * samplesPerLayer + hardware sample
};

bool isSupportedSampleCount(uint32_t n);           // 1, 4, 8, 16, 32
std::string supportedSampleCounts();               // "1, 4, 8, 16, 32" for messages
SamplePattern makeSamplePattern(uint32_t samples); // throws std::invalid_argument for other counts

} // namespace eng::frame
